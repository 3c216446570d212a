"""Sweeps on 2 workers against serial, and sweeps repeated on one dask Client.

The model is M1's RLC ladder (``families.py``) of 100 sections (200 states), a 1 V step
simulated to 6 s at rtol 1e-10 with 200 output points: some 0.3 s a run in the
compiled step loop.  A sweep is 50 runs over the first resistor (0.5 to 2 Ohm), keeping
the last capacitor's voltage and current.  Timed, interleaved ``--repeat`` times
(default 3), medians printed:

* serial (``executor=None``);
* ``executor="processes"``, ``max_workers=2`` (new worker processes each sweep, their
  start-up included: :mod:`acausal.sweepworkers`);
* a ``dask.distributed`` LocalCluster of 2 worker processes with one thread each,
  started once (its start-up not included).

The speedup is serial / parallel; on a machine with 2 free processors it should be 1.8
or more.  On a machine whose processors others share, the wall times say little, so
the processor time is measured too: the serial sweep's, and for the processes the
parent's plus its workers' (``RUSAGE_CHILDREN``: their start-up, the model's
unpickling, their first run's imports, and the runs); serial / (that / 2) is the
speedup two free processors would give, load balance aside (a run is 1/25 of a
worker's share).  Then ``--dask-repeats`` (default 20) sweeps of 6 runs one after another on the
one Client, each checked against the serial result (a failed or lost run, or an
exception, is counted), and a processes sweep after the cluster has run, with one
worker killed mid-sweep (its time, and that it returns the other runs).

    python benchmarks/sweep_speedup.py [--repeat N] [--dask-repeats N] [--t-end T]
"""
from __future__ import annotations

import argparse
import os
import signal
import statistics
import sys
import threading
import time

import numpy as np

import acausal as ac

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from families import RLCLadder  # noqa: E402

__all__ = ["main"]

KW = {"t_end": 6.0, "n_points": 200, "rtol": 1e-10, "names": ["C[99].v", "L[99].i"]}


def _timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def _cpu(fn):
    """(processor seconds of this process and of the children it waited for, out)."""
    import resource
    c0, p0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.process_time()
    out = fn()
    c1, p1 = resource.getrusage(resource.RUSAGE_CHILDREN), time.process_time()
    return (p1 - p0) + (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime), out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--dask-repeats", type=int, default=20)
    parser.add_argument("--t-end", type=float, default=KW["t_end"],
                        help="the length of each run (default 6 s of simulated time)")
    args = parser.parse_args(argv)
    KW["t_end"] = args.t_end
    import distributed
    compiled = ac.compile(RLCLadder(100))
    grid = {"R[0].R": np.linspace(0.5, 2.0, 50)}
    ac.simulate(compiled, 0.1)            # the step loop's library and analysis built
    times = {"serial": [], "processes": [], "dask": []}
    cpu = {"serial": [], "processes": []}
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        client.run(lambda: None)
        reference = None
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            c, reference = _cpu(lambda: ac.sweep(compiled, grid, **KW))
            times["serial"].append(time.perf_counter() - t0)
            cpu["serial"].append(c)
            t0 = time.perf_counter()
            c, ds = _cpu(lambda: ac.sweep(compiled, grid, executor="processes",
                                          max_workers=2, **KW))
            times["processes"].append(time.perf_counter() - t0)
            cpu["processes"].append(c)
            assert np.array_equal(ds["C[99].v"].values, reference["C[99].v"].values)
            t, ds = _timed(lambda: ac.sweep(compiled, grid, executor=client, **KW))
            times["dask"].append(t)
            assert np.array_equal(ds["C[99].v"].values, reference["C[99].v"].values)
        serial = statistics.median(times["serial"])
        print(f"50 runs of {serial / 50 * 1e3:.0f} ms (serial median {serial:.2f} s)")
        for name in ("processes", "dask"):
            med = statistics.median(times[name])
            print(f"  {name:10s} 2 workers: {med:.2f} s, speedup {serial / med:.2f}x "
                  f"(runs: {', '.join(f'{serial / t:.2f}' for t in times[name])})")
        s_cpu, p_cpu = statistics.median(cpu["serial"]), statistics.median(cpu["processes"])
        print(f"  processor time: serial {s_cpu:.2f} s, processes (parent and workers) "
              f"{p_cpu:.2f} s: on two free processors {s_cpu / (p_cpu / 2):.2f}x "
              f"(load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} processors)")
        small = {"R[0].R": [0.5, 0.8, 1.1, 1.4, 1.7, 2.0]}
        expected = ac.sweep(compiled, small, **KW)["C[99].v"].values
        failures = 0
        for k in range(args.dask_repeats):
            try:
                ds = ac.sweep(compiled, small, executor=client, **KW)
                ok = bool(ds["success"].values.all()) and np.array_equal(
                    ds["C[99].v"].values, expected)
            except Exception as exc:     # noqa: BLE001 - counted and said
                print(f"  dask sweep {k + 1}: {type(exc).__name__}: {exc}")
                ok = False
            failures += not ok
        print(f"{args.dask_repeats} repeated dask sweeps on one Client: "
              f"{args.dask_repeats - failures} whole, {failures} failed")
    # a processes sweep after dask has run in this process, one worker killed mid-sweep
    killer = threading.Timer(1.0, _kill_a_worker)
    killer.start()
    t, ds = _timed(lambda: ac.sweep(compiled, grid, executor="processes", max_workers=2,
                                    **KW))
    killer.join()
    lost = [str(m) for m, ok in zip(ds["message"].values, ds["success"].values) if not ok]
    print(f"processes after dask, one worker killed at 1 s: returned in {t:.2f} s, "
          f"{int(ds['success'].values.sum())} of 50 runs with their data, lost: {lost}")
    return 0


def _kill_a_worker() -> None:
    """SIGKILL one worker process of this process's sweep (a child running
    ``acausal.sweepworkers``)."""
    me = os.getpid()
    for pid in sorted(int(p) for p in os.listdir("/proc") if p.isdigit()):
        try:
            with open(f"/proc/{pid}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                cmd = f.read()
        except OSError:
            continue
        if ppid == me and b"sweepworkers" in cmd:
            os.kill(pid, signal.SIGKILL)
            return


if __name__ == "__main__":
    sys.exit(main())
