"""Benchmark: the build of M1 (the RLC ladder of ``families.py``) against a Modelica
compiler, rumoca, on the same machine.

Run:  python benchmarks/peer_build.py [--n 1000] [--repeat 3] [--quick]

The same ladder is written in Modelica -- its own Pin, OnePort, Resistor, Inductor,
Capacitor, Ground and step source, with the values of ``RLCLadder`` (R = 1 Ohm,
L = 1 mH, C = 1 mF, a 1 V step at t = 0, every capacitor on the one ground) -- and
compiled by ``rumoca.Session().loads`` (``pip install rumoca``; skipped with a message
when it is not installed).  Each build runs in a fresh process, the two tools
interleaved, ``--repeat`` times: acausal's in a process that has imported sympy and
built the step loop's library, with an empty compile cache (the conditions of the
README's build figures), rumoca's from its import on.  Printed: the medians, the
range, the peak memory of each process, the number of states each found (2N, a check
that the models agree), and the ratio acausal / rumoca of the medians, which holds
when the machine's speed drifts between runs.  ``--quick``: 300 sections, one run each.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

_HERE = os.path.dirname(os.path.abspath(__file__))

_LIBRARY = """
connector Pin
  Real v;
  flow Real i;
end Pin;
partial model OnePort
  Pin p;
  Pin n;
  Real v;
  Real i;
equation
  v = p.v - n.v;
  0 = p.i + n.i;
  i = p.i;
end OnePort;
model Resistor
  extends OnePort;
  parameter Real R = 1.0;
equation
  v = R*i;
end Resistor;
model Inductor
  extends OnePort;
  parameter Real L = 1e-3;
equation
  L*der(i) = v;
end Inductor;
model Capacitor
  extends OnePort;
  parameter Real C = 1e-3;
equation
  i = C*der(v);
end Capacitor;
model Ground
  Pin p;
equation
  p.v = 0;
end Ground;
model StepVoltage
  extends OnePort;
  parameter Real V = 1.0;
  parameter Real startTime = 0.0;
equation
  v = if time < startTime then 0 else V;
end StepVoltage;
"""


def modelica_ladder(n: int) -> str:
    """The Modelica source of ``RLCLadder(n)``, model ``Ladder``."""
    lines = ["model Ladder", "  StepVoltage src;", "  Ground gnd;"]
    lines += [f"  Resistor R{k}; Inductor L{k}; Capacitor C{k};" for k in range(n)]
    lines += ["equation", "  connect(src.n, gnd.p);"]
    node = "src.p"
    for k in range(n):
        lines += [f"  connect({node}, R{k}.p);", f"  connect(R{k}.n, L{k}.p);",
                  f"  connect(L{k}.n, C{k}.p);", f"  connect(C{k}.n, gnd.p);"]
        node = f"C{k}.p"
    return _LIBRARY + "\n".join(lines + ["end Ladder;"]) + "\n"


def _peak_gb() -> float:
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6


def _child_acausal(n: int) -> dict:
    import time
    os.environ["ACAUSAL_CACHE"] = tempfile.mkdtemp(prefix="acausal-peer-build-")
    sys.path.insert(0, _HERE)
    import sympy  # noqa: F401 - imported before the clock starts, as in the README

    import acausal as ac
    from families import RLCLadder
    try:
        from acausal.solvers import cbdf
        cbdf.library()
    except Exception:  # noqa: BLE001 - no compiler: the numpy loop, built at once
        pass
    model = RLCLadder(n)
    t0 = time.perf_counter()
    compiled = ac.compile(model)
    seconds = time.perf_counter() - t0
    return {"seconds": seconds, "states": len(compiled.states), "gb": _peak_gb(),
            "backend": compiled.backend}


def _child_rumoca(n: int) -> dict:
    import time
    source = modelica_ladder(n)
    t0 = time.perf_counter()
    import rumoca
    model = rumoca.Session().loads(source, model="Ladder")
    seconds = time.perf_counter() - t0
    return {"seconds": seconds, "states": len(model.states), "gb": _peak_gb(),
            "version": rumoca.version() if callable(rumoca.version) else rumoca.version}


def _run(tool: str, n: int) -> dict:
    out = subprocess.run([sys.executable, os.path.abspath(__file__), "--child", tool,
                          "--n", str(n)], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"the {tool} build failed:\n{out.stderr[-2000:]}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--quick", action="store_true", help="300 sections, one run each")
    parser.add_argument("--child", choices=("acausal", "rumoca"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.quick:
        args.n, args.repeat = 300, 1
    if args.child:
        run = _child_acausal if args.child == "acausal" else _child_rumoca
        print(json.dumps(run(args.n)))
        return
    tools = ["acausal"]
    try:
        import rumoca  # noqa: F401
        tools.append("rumoca")
    except ImportError:
        print("rumoca is not installed (pip install rumoca): acausal's build alone")
    runs = {tool: [] for tool in tools}
    for k in range(args.repeat):
        for tool in (tools if k % 2 == 0 else tools[::-1]):
            runs[tool].append(_run(tool, args.n))
            print(f"  {tool:8s} run {k + 1}: {runs[tool][-1]['seconds']:.2f} s", flush=True)
    print(f"\nM1, RLC ladder of {args.n} sections: build in a fresh process, "
          f"{args.repeat} run(s) each, interleaved")
    medians = {}
    for tool, rs in runs.items():
        secs = [r["seconds"] for r in rs]
        medians[tool] = statistics.median(secs)
        extra = rs[0].get("backend") or f"rumoca {rs[0].get('version')}"
        print(f"  {tool:8s} median {medians[tool]:8.2f} s  ({min(secs):.2f}-{max(secs):.2f})"
              f"  peak {max(r['gb'] for r in rs):.2f} GB  states {rs[0]['states']}  ({extra})")
    if "rumoca" in medians:
        print(f"  acausal / rumoca: {medians['acausal'] / medians['rumoca']:.3f}")


if __name__ == "__main__":
    main()
