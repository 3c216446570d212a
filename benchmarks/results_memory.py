"""Results that scale: the peak memory of a long run and the time to read one variable.

Each case runs in a fresh process (its peak resident memory is the process's
``ru_maxrss``), with wall times of each phase:

* **stored**: M1's RLC ladder of 50 sections (``families.py``: 1008 outputs, 401
  distinct series, 100 states), a 1 V step simulated to 1 s with ``--points`` output
  points (default 1e6) and ``store=`` an HDF5 file, written as the run goes; then, in
  another fresh process, the file loaded and one variable (the last capacitor's
  voltage) read.  The target: the run within 4 GB, the variable read in under 0.5 s.
* **in memory**: the same run held in memory, one variable read (computed for itself
  only), then ``Result.save`` (written a block of points at a time).
* **motor drive**: the motor drive of ``library/examples/motor_drive.py`` over 2 s
  with 1e6 points, one variable read.

    python benchmarks/results_memory.py [--points N] [--cases stored,memory,motor]
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import textwrap

__all__ = ["main"]

HERE = os.path.dirname(os.path.abspath(__file__))

PRELUDE = textwrap.dedent("""
    import json, resource, sys, time
    sys.path.insert(0, {here!r})
    import acausal as ac
    def peak():
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    out = {{}}
    clock = time.perf_counter
""")

STORED = textwrap.dedent("""
    from families import RLCLadder
    t0 = clock()
    compiled = ac.compile(RLCLadder(50))
    out["outputs"] = len(compiled.outputs)
    t1 = clock()
    res = ac.simulate(compiled, 1.0, n_points={points}, store={path!r})
    out.update(compile_s=t1 - t0, run_s=clock() - t1, success=res.success,
               points=len(res.t), peak_mb=peak())
    print(json.dumps(out))
""")

READ = textwrap.dedent("""
    t0 = clock()
    res = ac.load_result({path!r})
    t1 = clock()
    v = res["C[49].v"]
    out.update(load_s=t1 - t0, read_s=clock() - t1, points=len(v), peak_mb=peak(),
               last=float(v[-1]))
    print(json.dumps(out))
""")

MEMORY = textwrap.dedent("""
    from families import RLCLadder
    compiled = ac.compile(RLCLadder(50))
    t1 = clock()
    res = ac.simulate(compiled, 1.0, n_points={points})
    t2 = clock()
    out.update(run_s=t2 - t1, peak_after_run_mb=peak())
    v = res["C[49].v"]
    t3 = clock()
    out.update(read_s=t3 - t2, peak_after_read_mb=peak())
    res.save({path!r})
    out.update(save_s=clock() - t3, peak_mb=peak())
    print(json.dumps(out))
""")

MOTOR = textwrap.dedent("""
    from acausal.library.examples.motor_drive import MotorDrive
    compiled = ac.compile(MotorDrive())
    t1 = clock()
    res = ac.simulate(compiled, 2.0, n_points={points})
    t2 = clock()
    out.update(outputs=len(compiled.outputs), run_s=t2 - t1, peak_after_run_mb=peak())
    v = res["load.w"]
    out.update(read_s=clock() - t2, peak_mb=peak())
    print(json.dumps(out))
""")


def _child(code: str) -> dict:
    proc = subprocess.run([sys.executable, "-c", PRELUDE.format(here=HERE) + code],
                          capture_output=True, text=True, timeout=7200)
    if proc.returncode != 0:
        raise RuntimeError(proc.stderr[-3000:])
    return json.loads(proc.stdout.strip().splitlines()[-1])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--cases", default="stored,memory,motor")
    args = parser.parse_args(argv)
    cases = args.cases.split(",")
    with tempfile.TemporaryDirectory(prefix="acausal-results-") as work:
        path = os.path.join(work, "run.h5")
        if "stored" in cases:
            run = _child(STORED.format(points=args.points, path=path))
            size = os.path.getsize(path) / 2**30
            print(f"stored: {run['outputs']} outputs x {run['points']} points, run "
                  f"{run['run_s']:.1f} s (compile {run['compile_s']:.1f} s), peak "
                  f"{run['peak_mb']:.0f} MB, file {size:.2f} GB")
            read = _child(READ.format(path=path))
            print(f"  one variable of it read in a fresh process: {read['read_s']:.3f} s "
                  f"(load {read['load_s']:.3f} s), peak {read['peak_mb']:.0f} MB")
            os.remove(path)
        if "memory" in cases:
            mem = _child(MEMORY.format(points=args.points, path=path))
            print(f"in memory: run {mem['run_s']:.1f} s, peak {mem['peak_after_run_mb']:.0f}"
                  f" MB; one variable read in {mem['read_s']:.3f} s (peak "
                  f"{mem['peak_after_read_mb']:.0f} MB); saved in {mem['save_s']:.1f} s, "
                  f"peak {mem['peak_mb']:.0f} MB")
            os.remove(path)
        if "motor" in cases:
            mot = _child(MOTOR.format(points=args.points))
            print(f"motor drive: {mot['outputs']} outputs x {args.points} points, run "
                  f"{mot['run_s']:.1f} s, peak {mot['peak_after_run_mb']:.0f} MB; one "
                  f"variable read in {mot['read_s']:.3f} s, peak {mot['peak_mb']:.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
