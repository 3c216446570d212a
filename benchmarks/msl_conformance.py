"""The MSL examples against the MSL's reference results: one row per example, totals per
package (``python benchmarks/msl_conformance.py [NAME ...]``).

Each row: the signals compared, the worst error over the reference's amplitude of its
Real signals (the bound is 1e-3, see ``tests/msl/harness.py``), the mismatching
instants of its Boolean and Integer signals, the run's wall time, and the verdict (with
the example's ``msl_known_failure``, where it names why it cannot pass).  A
NAME selects the examples whose MSL name contains it.  The examples run one after the
other in this process (``--jobs N``: in N worker processes).
"""
from __future__ import annotations

import argparse
import os
import sys
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

from acausal.tests.msl.harness import BOUND, examples, package_of, run_example  # noqa: E402


def _one(name: str):
    try:
        return run_example(examples()[name])
    except Exception as err:        # noqa: BLE001 - a row that says why
        return f"{type(err).__name__}: {str(err).splitlines()[0][:120]}"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--quick", action="store_true",
                        help="only the examples make test compares")
    args = parser.parse_args(argv)
    names = list(examples())
    if args.quick:
        from acausal.tests.msl.subset import QUICK
        names = [n for n in names if n in QUICK]
    if args.names:
        names = [n for n in names if any(s in n for s in args.names)]
    if args.jobs > 1:
        import multiprocessing
        with ProcessPoolExecutor(args.jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
            outcomes = dict(zip(names, pool.map(_one, names)))
    else:
        outcomes = {n: _one(n) for n in names}
    totals = defaultdict(lambda: [0, 0])
    print(f"{'example':58s} {'signals':>7s} {'worst/ampl':>10s} {'discrete':>8s} "
          f"{'time/s':>7s}  verdict   (bound {BOUND:g} x amplitude)")
    known = {n: getattr(c, "msl_known_failure", None) for n, c in examples().items()}
    for name, out in outcomes.items():
        package = package_of(name)
        totals[package][1] += 1
        short = name.replace("Modelica.", "")
        if isinstance(out, str):
            print(f"{short:58s} {'':>7s} {'':>10s} {'':>8s} {'':>7s}  ERROR  {out}")
            continue
        totals[package][0] += out.passed
        discrete = sum(int(c.worst) for c in out.checks if c.kind == "discrete")
        ndisc = sum(c.kind == "discrete" for c in out.checks)
        note = "" if out.success else f"  ({out.message.splitlines()[0][:80]})"
        if not out.passed and known.get(name):
            note += f"  (known: {known[name][:90]})"
        print(f"{short:58s} {len(out.checks):7d} {out.worst:10.2e} "
              f"{(str(discrete) if ndisc else '-'):>8s} {out.seconds:7.2f}  "
              f"{'pass' if out.passed else 'FAIL'}{note}")
    print()
    for package, (ok, n) in sorted(totals.items()):
        print(f"{package:58s} {ok:3d} of {n:3d} pass")
    ok = sum(v[0] for v in totals.values())
    print(f"{'all':58s} {ok:3d} of {sum(v[1] for v in totals.values()):3d} pass")
    return 0


if __name__ == "__main__":
    sys.exit(main())
