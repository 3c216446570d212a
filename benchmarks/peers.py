"""Benchmark: acausal against peer solvers on the models M1..M5 (``families.py``).

Run:  python benchmarks/peers.py [--n 1000] [--models M1,M3] [--repeats 3]
                                 [--backends numpy,c] [--reference 1e-10] [--quick]

For each model, in one process, with rtol = 1e-6 and atol = rtol x nominal (acausal's
default) for every solver:

* acausal: ``ac.compile`` (the build, timed once) and ``ac.simulate`` (one row per code
  backend when ``compile``/``simulate`` take ``backend=``);
* scipy ``solve_ivp(method="BDF")`` on a hand-written right-hand side (vectorized numpy,
  ``jac_sparsity`` for M1 and M4; M2 in the pendulum's angle);
* scikit-sundae ``IDA`` on a numpy residual (M2: the index-1 Cartesian DAE, the
  constraint differentiated twice) and CasADi (SX, ``cvodes`` for the ODE forms,
  ``idas`` for M2's index-1 DAE), each when installed (``pip install acausal[bench]``).

The hand-written forms are in ``peers_models.py``, the runners in ``peers_solvers.py``.
Wall times are medians of ``--repeats`` runs, interleaved (A, B, C, A, B, C, ...), since
the machine may be shared, after one untimed run of each; build times are one run each.  Every peer's final state is
compared with acausal's: ``dev`` is the largest |peer - acausal| at t_end over a group
of variables (currents, voltages, positions, ...) divided by the group's peak |value|
over acausal's run, the largest over the groups.  A deviation above 1e-3 is flagged
("!"): either the peer's model is not the same or a solver's global error is large.
The latter happens on M4, whose undamped chain (modes up to 200 rad/s, some 30 periods)
ends, at rtol 1e-6, with a global error (against the exact solution, expm) of about
0.4 % in acausal and IDA and 6-12 % in scipy and CasADi; ``--reference 1e-10`` adds a column ``err``, every row's deviation from
acausal at that tight tolerance, which separates the two.  Ratios are acausal / peer:
wall time, and wall time per accepted step.
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import acausal as ac  # noqa: E402
from families import PEERS, peer_model  # noqa: E402
from peers_models import formulations  # noqa: E402
from peers_solvers import (Runner, acausal_runners, casadi_runners,  # noqa: E402
                           ida_runner, optional_import, scipy_runner)

DESCRIPTIONS = {
    "M1": "RLC ladder, {n} sections ({two_n} states)",
    "M2": "Cartesian pendulum (index 3 as written)",
    "M3": "DC motor, elastic shaft and load",
    "M4": "mass-spring chain, {n} masses ({two_n} states)",
    "M5": "valve-controlled hydraulic motor, P control",
}
FLAG = 1e-3        # a deviation above this is flagged (a different model or a large error)
QUICK_N = 100


def build(name: str, n: int, rtol: float, peers: dict, backends: tuple) -> tuple:
    """(t_end, groups, runners) for model ``name``: acausal's runners first, then the
    peers'; ``groups`` the variables each deviation is taken over."""
    forms = formulations(name, n)
    _, t_end = peer_model(name, n)
    names = sorted({k for form in forms for group in form.groups.values() for k in group})
    runners = acausal_runners(ac, lambda: peer_model(name, n)[0], t_end, rtol, names,
                              backends)
    for form in forms:
        if form.is_ode:
            runners.append(scipy_runner(form, rtol))
    ida, why = peers["sksundae.ida"]
    # IDA on the DAE form where there is one (M2), else on the ODE written implicitly
    ida_form = next((f for f in forms if not f.is_ode), forms[0])
    runners.append(ida_runner(ida, ida_form, rtol) if ida else
                   Runner("IDA (sksundae)", ida_form.label, reason=why))
    ca, why = peers["casadi"]
    for form in forms:
        runners += casadi_runners(ca, form, rtol) if ca else [
            Runner("CasADi " + ("cvodes" if form.is_ode else "idas"), form.label, reason=why)]
    return t_end, forms[0].groups, runners


def measure(runners: list, repeats: int) -> dict:
    """One untimed run of each runner (what a first call pays once: imports, a solver's
    set-up, first touches of memory), then interleaved timed runs; {runner index: list
    of Outcomes}.  A runner that fails gets its reason and is not run again."""
    outcomes = {k: [] for k, r in enumerate(runners) if r.run is not None}
    for timed in [False] + [True] * repeats:
        for k in list(outcomes):
            try:
                outcome = runners[k].run()
            except Exception as err:      # noqa: BLE001  (reported in the table)
                runners[k].reason = f"failed: {type(err).__name__}: {err}"
                del outcomes[k]
                continue
            if timed:
                outcomes[k].append(outcome)
    return outcomes


def group_scales(result, groups: dict) -> dict:
    """Each group's peak |value| over acausal's run."""
    return {g: max(float(np.max(np.abs(result[k]))) for k in names) or 1.0
            for g, names in groups.items()}


def deviation(values: dict, reference: dict, groups: dict, scales: dict) -> float:
    """max over the groups of max |value - reference| / the group's peak."""
    return max(max(abs(values[k] - reference[k]) for k in names) / scales[g]
               for g, names in groups.items())


def _medians(runners: list, outcomes: dict) -> list:
    """(runner, median seconds, last Outcome) of every runner that ran."""
    return [(r, statistics.median(o.seconds for o in outcomes[k]), outcomes[k][-1])
            for k, r in enumerate(runners) if k in outcomes]


def _is_acausal(runner) -> bool:
    return runner.label.startswith("acausal")


def _short(label: str) -> str:
    return "ac" + label[len("acausal "):]


def report(name: str, n: int, t_end: float, rtol: float, repeats: int, groups: dict,
           runners: list, outcomes: dict, reference_rtol: float | None = None) -> list:
    """Print the model's table; return its (label, median s) rows."""
    size = DESCRIPTIONS[name].format(n=n, two_n=2 * n)
    print(f"\n{name}: {size}; t_end = {t_end:g} s, rtol = {rtol:g}, atol = rtol x nominal; "
          f"medians of {repeats} interleaved runs after one untimed run each, builds timed once")
    rows = _medians(runners, outcomes)
    ours = [(r, s, o) for r, s, o in rows if _is_acausal(r)]
    if not ours:
        print("  acausal did not run: " + "; ".join(r.reason for r in runners
                                                    if _is_acausal(r)))
        return []
    ref = ours[0][2]
    scales = group_scales(ref.result, groups)
    tight = None
    if reference_rtol:
        res = ac.simulate(ours[0][0].compiled, t_end=t_end, rtol=reference_rtol)
        tight = {k: float(res[k][-1]) for k in ref.values}
    heads = "".join(f" {'t ' + _short(r.label) + '/peer':>15}" for r, _, _ in ours)
    print(f"  {'solver':<18} {'build s':>8} {'time ms':>9} {'steps':>7} {'evals':>7} "
          f"{'us/step':>8} {'dev':>8}{'      err' if tight else ''}{heads} "
          f"{'us/step ac/peer':>16}")
    ref_per_step = ours[0][1] / max(ref.steps, 1)
    flagged = False
    for r, seconds, o in rows:
        per_step = seconds / max(o.steps, 1)
        dev = None if o is ref else deviation(o.values, ref.values, groups, scales)
        flag = dev is not None and dev > FLAG
        flagged |= flag
        cells = f"{'ref':>8}" if dev is None else f"{dev:8.1e}"
        if tight:
            cells += f" {deviation(o.values, tight, groups, scales):8.1e}"
        build = f"{'-':>8}" if r.build_s is None else f"{r.build_s:8.2f}"
        ratios = "".join(f" {s / seconds:15.2f}" for _, s, _ in ours)
        print(f"  {r.label:<18} {build} {seconds * 1e3:9.1f} {o.steps:7d} "
              f"{o.evaluations:7d} {per_step * 1e6:8.1f} {cells}{ratios} "
              f"{ref_per_step / per_step:16.2f}{' !' if flag else ''}")
    _notes(runners, rows, ours, flagged, reference_rtol)
    return [(r.label, s) for r, s, _ in rows]


def _notes(runners, rows, ours, flagged, reference_rtol) -> None:
    """What did not run and why, the flag's meaning, acausal's slowest passes, the
    peers' forms."""
    for r in runners:
        if r.reason:
            print(f"  {r.label:<18} {r.reason}")
    if flagged:
        print(f"  ! deviation from acausal above {FLAG:g}: a different model or a large "
              "global error" + ("" if reference_rtol else " (--reference 1e-10 tells which)"))
    if reference_rtol:
        print(f"  err: deviation from acausal at rtol = {reference_rtol:g}")
    for r, _, _ in ours:
        timings = getattr(getattr(r.compiled, "report", None), "timings", None) or {}
        top = sorted(timings.items(), key=lambda kv: -kv[1])[:3]
        if top:
            print(f"  {r.label} build, longest passes: "
                  + ", ".join(f"{k} {v:.2f} s" for k, v in top))
    for r, _, _ in rows:
        if not _is_acausal(r):
            print(f"  form of {r.label}: {r.form}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=1000, help="size of M1 and M4 (default 1000)")
    ap.add_argument("--models", default=",".join(PEERS), help="comma-separated, e.g. M1,M3")
    ap.add_argument("--repeats", type=int, default=3, help="timed runs per solver")
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--backends", default="numpy,c",
                    help="acausal code backends to run, when compile takes backend= "
                         "(c-pyloop: the C backend with the Python step loop)")
    ap.add_argument("--reference", type=float, default=None, metavar="RTOL",
                    help="add each row's deviation from acausal at this tight rtol")
    ap.add_argument("--quick", action="store_true", help=f"N = {QUICK_N} (for run_all.py)")
    args = ap.parse_args(argv)
    n = QUICK_N if args.quick else args.n
    models = [m.strip().upper() for m in args.models.split(",") if m.strip()]
    unknown = [m for m in models if m not in PEERS]
    if unknown:
        ap.error(f"unknown model(s) {', '.join(unknown)}; the models are {', '.join(PEERS)}")
    backends = tuple(b.strip() for b in args.backends.split(",") if b.strip())
    peers = {mod: optional_import(mod) for mod in ("sksundae.ida", "casadi")}
    for mod, (module, why) in peers.items():
        version = getattr(sys.modules.get(mod.split(".")[0]), "__version__", "")
        print(f"{mod}: {version or 'available' if module else why}")
    overview = {}
    for name in models:
        t_end, groups, runners = build(name, n, args.rtol, peers, backends)
        outcomes = measure(runners, args.repeats)
        overview[name] = report(name, n, t_end, args.rtol, args.repeats, groups, runners,
                                outcomes, args.reference)
    _print_overview(overview)
    return 0


def _print_overview(overview: dict) -> None:
    """acausal's first row against each peer, all models: wall-time ratios."""
    labels = []
    for rows in overview.values():
        labels += [lab for lab, _ in rows if lab not in labels]
    if not labels:
        return
    print("\nwall time ratio, " + labels[0] + " / solver (below 1: acausal faster)")
    print("  " + f"{'model':<6}" + "".join(f" {lab:>18}" for lab in labels[1:]))
    for name, rows in overview.items():
        times = dict(rows)
        cells = "".join(f" {times[labels[0]] / times[lab]:18.2f}" if lab in times and
                        labels[0] in times else f" {'-':>18}" for lab in labels[1:])
        print(f"  {name:<6}{cells}")


if __name__ == "__main__":
    sys.exit(main())
