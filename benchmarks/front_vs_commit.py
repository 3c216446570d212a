"""The front passes of M1 (the RLC ladder, ``families.py``) built by this tree and by an
earlier commit, interleaved: the ratio of a change's build time to its baseline's.

The commit's tree is written to a temporary folder (``git archive``) and imported from
there (``PYTHONPATH``); each build runs in a fresh process, up to state selection
(``compile_model(..., until="state_selection")``), the two trees in turn -- this one,
the baseline, this one, ... -- so that the machine's drift falls on both alike.  Printed:
the medians of flattening's wall time, of the front passes' wall time and of their
processor time (less sensitive to other load), and the median of the ratios pair by pair.

    python benchmarks/front_vs_commit.py 7131321 [--sections 1000] [--runs 7]
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

__all__ = ["main"]

_HERE = os.path.dirname(os.path.abspath(__file__))
_ROOT = os.path.dirname(_HERE)

_CHILD = """
import json, sys, time
sys.path.insert(0, sys.argv[1])
import families
from acausal.compiler.pipeline import compile_model
import scipy.optimize, scipy.sparse.csgraph       # imports the passes make on first use
model = families.ladder(int(sys.argv[2]))
t0, c0 = time.perf_counter(), time.process_time()
out = compile_model(model, until="state_selection")
print(json.dumps({"flatten": out.report.timings["flatten"],
                  "front": time.perf_counter() - t0, "cpu": time.process_time() - c0}))
"""


def _build(pythonpath: str, benchmarks: str, sections: int) -> dict:
    env = dict(os.environ, PYTHONPATH=pythonpath)
    out = subprocess.run([sys.executable, "-c", _CHILD, benchmarks, str(sections)],
                         capture_output=True, text=True, check=True, env=env).stdout
    return json.loads(out.strip().splitlines()[-1])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("commit", help="the baseline commit")
    ap.add_argument("--sections", type=int, default=1000)
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        here = os.path.join(tmp, "this")        # this tree, imported as acausal
        os.makedirs(here)
        os.symlink(_ROOT, os.path.join(here, "acausal"))
        base = os.path.join(tmp, "base")
        package = os.path.join(base, "acausal")
        os.makedirs(package)
        archive = subprocess.run(["git", "-C", _ROOT, "archive", args.commit],
                                 capture_output=True, check=True).stdout
        subprocess.run(["tar", "-x", "-C", package], input=archive, check=True)
        base_bench = os.path.join(package, "benchmarks")
        _build(here, _HERE, args.sections)           # untimed: caches and imports warm
        _build(base, base_bench, args.sections)
        after, before = [], []
        for _ in range(args.runs):
            after.append(_build(here, _HERE, args.sections))
            before.append(_build(base, base_bench, args.sections))
    print(f"M1 ({args.sections} sections), front passes: this tree against {args.commit}, "
          f"{args.runs} interleaved pairs")
    for key, what in (("flatten", "flatten, wall s"), ("front", "front passes, wall s"),
                      ("cpu", "front passes, processor s")):
        a = [r[key] for r in after]
        b = [r[key] for r in before]
        ratio = statistics.median(x / y for x, y in zip(a, b))
        print(f"  {what:26s} {statistics.median(a):7.3f} against {statistics.median(b):7.3f}"
              f"   paired ratio {ratio:.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
