"""Random lumped networks against an independent reference: counts of what happened.

Case N (N = 0 .. cases-1) draws its network from the seed "<seed>:<N>" with the strategy
``STRATEGY_CYCLE[N % 20]``: well-posed electrical, translational and rotational
networks (solved exactly by ``tests/property/reference.py`` and compared signal by
signal), and ill-posed ones made on purpose (which must be refused with a typed error
naming a culprit).  See ``tests/property/harness.py`` for the categories and the
tolerance.

Each case runs in a worker process under a time limit (an alarm inside the worker, and
the worker is replaced if it does not answer in time).

Usage::

    python benchmarks/fuzz_networks.py                    # 1000 cases, seed 0
    python benchmarks/fuzz_networks.py --cases 200 --jobs 2
    python benchmarks/fuzz_networks.py --case 17          # one case: netlist, model, outcome
    python benchmarks/fuzz_networks.py --case 17 --shrink # ... and the smallest that fails alike
    python benchmarks/fuzz_networks.py --hybrid --n 1000 --seed 0   # hybrid models
    python benchmarks/fuzz_networks.py --hybrid --case 17           # one, verbosely

``--hybrid``: random hybrid and nonlinear models (ideal diodes and switches driven by
time and by a capacitor voltage, Coulomb and Karnopp friction, limiters and dead zones
in a loop, nonlinear conductors and springs, hydraulic orifices between volumes, inline
expressions of random depth) against hand-written mode-by-mode references, each in a
spawned worker under a wall-time cap; see ``tests/property/hybrid_harness.py``.
"""
from __future__ import annotations

import argparse
import multiprocessing as mp
import sys
import time
import traceback
from collections import Counter

import numpy as np

from acausal.tests.property.harness import CATEGORIES, make_case, run_case
from acausal.tests.property.netlists import SeededChooser, to_source

__all__ = ["STRATEGY_CYCLE", "case_of", "main"]

STRATEGY_CYCLE = (["electrical"] * 7 + ["translational"] * 3 + ["rotational"] * 4
                  + ["ill-posed electrical"] * 3 + ["ill-posed translational"]
                  + ["ill-posed rotational"] * 2)
GENERATOR_ERROR = "generator error"


def case_of(seed: int, n: int):
    strategy = STRATEGY_CYCLE[n % len(STRATEGY_CYCLE)]
    return strategy, make_case(SeededChooser(f"{seed}:{n}"), strategy)


def _one(seed: int, n: int, limit: float) -> dict:
    try:
        strategy, case = case_of(seed, n)
    except Exception:                           # noqa: BLE001  (a defect of the generator)
        return dict(n=n, strategy=STRATEGY_CYCLE[n % len(STRATEGY_CYCLE)],
                    category=GENERATOR_ERROR, detail=traceback.format_exc(limit=3)[-400:],
                    seconds=0.0, size=0)
    out = run_case(case, limit)
    return dict(n=n, strategy=strategy, category=out.category, detail=out.detail,
                reason=out.reason, error=out.error, seconds=out.seconds,
                size=len(case.net.elements), defect=case.net.defect)


def _worker(conn, seed, limit):
    try:
        while True:
            n = conn.recv()
            if n is None:
                return
            conn.send(_one(seed, n, limit))
    except (EOFError, BrokenPipeError):      # the parent has gone
        return


class _Pool:
    """Workers that take one case at a time; one that does not answer within the hard
    limit is killed (it is our own child) and replaced."""

    def __init__(self, jobs, seed, limit):
        self.seed, self.limit = seed, limit
        self.ctx = mp.get_context("fork")
        self.slots = [self._start() for _ in range(jobs)]

    def _start(self):
        parent, child = self.ctx.Pipe()
        proc = self.ctx.Process(target=_worker, args=(child, self.seed, self.limit), daemon=True)
        proc.start()
        return {"proc": proc, "conn": parent, "n": None, "since": 0.0}

    def run(self, numbers, report):
        todo = list(numbers)
        busy = 0
        while todo or busy:
            for i, slot in enumerate(self.slots):
                if slot["n"] is None and todo:
                    slot["n"], slot["since"] = todo.pop(0), time.monotonic()
                    slot["conn"].send(slot["n"])
                    busy += 1
            for i, slot in enumerate(self.slots):
                if slot["n"] is None:
                    continue
                if slot["conn"].poll(0.05):
                    report(slot["conn"].recv())
                    slot["n"] = None
                    busy -= 1
                elif time.monotonic() - slot["since"] > self.limit + 60:
                    n = slot["n"]
                    slot["proc"].kill()
                    slot["proc"].join()
                    report(dict(n=n, strategy=STRATEGY_CYCLE[n % len(STRATEGY_CYCLE)],
                                category="hang", detail="worker did not answer; killed",
                                seconds=time.monotonic() - slot["since"], size=0))
                    self.slots[i] = self._start()
                    busy -= 1

    def close(self):
        for slot in self.slots:
            slot["conn"].send(None)
            slot["proc"].join(timeout=5)


def _single(args):
    strategy, case = case_of(args.seed, args.case)
    print(f"case {args.case} (seed {args.seed}, {strategy})")
    print(case.net.describe())
    if case.ref is not None and case.ref.regular:
        print(f"reference: {case.ref.n} unknowns, {case.ref.ns} states, index {case.ref.index}")
    print("\n" + to_source(case.net))
    out = run_case(case, args.limit)
    print(f"outcome: {out.category}  {out.detail}")
    if out.category in ("ok", "wrong"):
        print(f"worst deviation {out.error:.3g} in {out.signal} ({out.seconds:.2f} s)")
    if args.shrink and out.category not in ("ok", "rejected"):
        from acausal.tests.property.shrink import shrink
        small = shrink(case, out, lambda c: run_case(c, args.limit), log=print)
        print("\nshrunk:\n" + small.net.describe() + "\n\n" + to_source(small.net))
        again = run_case(small, args.limit)
        print(f"outcome: {again.category}  {again.detail}")


def _reporter(seed, results, t0, every):
    """Collects each outcome, prints the ones not OK at once and the progress."""
    def report(r):
        results.append(r)
        if r["category"] not in ("ok", "rejected"):
            print(f"--seed {seed} --case {r['n']:<4d} [{r['strategy']}] {r['category']}: "
                  f"{r['detail'][:240]}", flush=True)
        if len(results) % every == 0:
            print(f"... {len(results)} cases, {time.perf_counter() - t0:.0f} s", flush=True)
    return report


def _hybrid(args):
    from acausal.tests.property.hybrid_harness import (HYBRID_CATEGORIES, HYBRID_CYCLE,
                                                       SLIDING_CATEGORIES, HybridPool,
                                                       evaluate)
    if args.case is not None:
        r = evaluate(args.seed, args.case)
        for key, value in r.items():
            print(f"{key}: {value}")
        return 0
    results, t0 = [], time.perf_counter()
    report = _reporter(args.seed, results, t0, 100)
    with HybridPool(args.jobs, args.limit) as pool:
        pool.run(args.seed, range(args.cases), report)
    counts = Counter(r["category"] for r in results)
    print(f"\n{len(results)} hybrid models, seed {args.seed}, "
          f"{time.perf_counter() - t0:.0f} s")
    for cat in HYBRID_CATEGORIES:
        print(f"  {cat:22s} {counts.get(cat, 0):5d}")
    by = Counter((r["strategy"], r["category"]) for r in results)
    print("\nby kind:")
    for strat in dict.fromkeys(HYBRID_CYCLE):
        print(f"  {strat:20s} " + ", ".join(f"{cat} {by[strat, cat]}"
                                            for cat in HYBRID_CATEGORIES if by[strat, cat]))
    errs = [r["error"] for r in results if r["category"] == "ok" and "error" in r]
    if errs:
        print(f"\nworst deviation of the ok ones (of the signal's size): median "
              f"{np.median(errs):.2g}, max {np.max(errs):.2g}")
    redrawn = sum(1 for r in results if r.get("redraws"))
    print(f"drawn again because the reference chattered (a sliding mode): {redrawn}")
    sliding = [(r["strategy"], s) for r in results for s in r.get("sliding", ())]
    by_s = Counter((strat, s["category"]) for strat, s in sliding)
    print(f"\nthe {len(sliding)} chattering draws, run in acausal:")
    for cat in SLIDING_CATEGORIES:
        print(f"  {cat:22s} {sum(by_s[k, cat] for k in dict.fromkeys(HYBRID_CYCLE)):5d}  "
              + ", ".join(f"{k} {by_s[k, cat]}" for k in dict.fromkeys(HYBRID_CYCLE)
                          if by_s[k, cat]))
    for strat, s in sliding:
        if s["category"] not in ("refused, named", "ran (not judged)"):
            print(f"  [{strat}] {s['category']}: {s['detail'][:200]}\n      {s['describe']}")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", "--n", type=int, default=1000)
    ap.add_argument("--hybrid", action="store_true",
                    help="random hybrid and nonlinear models instead of linear networks")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--limit", type=float, default=60.0, help="seconds per case")
    ap.add_argument("--case", type=int, default=None, help="run this case alone, verbosely")
    ap.add_argument("--shrink", action="store_true", help="with --case: shrink a failure")
    args = ap.parse_args(argv)
    if args.hybrid:
        return _hybrid(args)
    if args.case is not None:
        _single(args)
        return 0
    results, t0 = [], time.perf_counter()
    report = _reporter(args.seed, results, t0, 50)
    pool = _Pool(args.jobs, args.seed, args.limit)
    try:
        pool.run(range(args.cases), report)
    finally:
        pool.close()
    results.sort(key=lambda r: r["n"])
    counts = Counter(r["category"] for r in results)
    print(f"\n{len(results)} cases, seed {args.seed}, {time.perf_counter() - t0:.0f} s")
    for cat in CATEGORIES + (GENERATOR_ERROR,):
        print(f"  {cat:22s} {counts.get(cat, 0):5d}")
    by = Counter((r["strategy"], r["category"]) for r in results)
    print("\nby strategy:")
    for strat in dict.fromkeys(STRATEGY_CYCLE):
        row = ", ".join(f"{cat} {by[strat, cat]}" for cat in CATEGORIES + (GENERATOR_ERROR,)
                        if by[strat, cat])
        print(f"  {strat:24s} {row}")
    reasons = Counter((r["category"], r.get("reason", "")) for r in results
                      if r["category"] not in ("ok", "rejected"))
    if reasons:
        print("\nnot OK, by reason:")
        for (cat, why), k in sorted(reasons.items(), key=lambda kv: (kv[0][0], -kv[1])):
            first = min(r["n"] for r in results
                        if (r["category"], r.get("reason", "")) == (cat, why))
            print(f"  {k:4d}  {cat:20s} {why[:110]}  (first: --case {first})")
    slow = [r for r in results if r["category"] == "ok" and r["detail"].startswith("converges")]
    print(f"\nok only at the tighter tolerance (the deviation converges): {len(slow)}")
    bad = [r for r in results if r["category"] not in ("ok", "rejected")]
    if bad:
        print(f"\nnot OK (rerun one with --seed {args.seed} --case N):")
        for r in bad:
            print(f"  --case {r['n']:<4d} {r['category']:20s} [{r['strategy']}] "
                  f"{r['detail'][:200]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
