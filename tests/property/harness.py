"""One random case from end to end: draw a network, solve it with the reference, run
acausal on it, and say what happened.

Outcome categories (``Outcome.category``):

* ``ok``: a regular network, simulated, every compared signal within tolerance;
* ``wrong``: simulated with success=True but some signal disagrees with the reference;
* ``rejected``: an ill-posed network refused with a typed error (``acausal.ModelError``,
  ``StructuralError`` or ``InitializationFailed``) that names a culprit;
* ``rejected, no culprit``: the same, but the message names none of the elements that
  make the network ill-posed;
* ``false rejection``: a regular network refused (typed error) or simulated without
  success;
* ``missed``: an ill-posed network that compiled and ran without a typed error;
* ``internal error``: any other exception (KeyError, IndexError, RecursionError, sympy
  errors, ...), or a result that lacks a variable of the model;
* ``hang``: over the time limit.

Tolerance.  acausal runs with rtol = 1e-8 and atol = 1e-12.  (atol is per unit
nominal value, and the default nominal is 1: the default atol = rtol would allow an
absolute error of 1e-8 on a current of 1e-4 A or a displacement of 1e-5 m, a relative
error of 1e-4 or worse, which is the solver's contract and not a defect.)  The BDF
controls the local error per step at that level; the global error over a few time
constants grows to some ten to a hundred times the local tolerance, so a deviation of
TOL = 1e-5 of the signal's size leaves a margin of 100 or more, and is still far below
what a modelling error produces (those are O(1)).  The size of a signal is the size of
the terms it is computed from (``Reference.sizes``: an element voltage that is the
small difference of two large potentials has the size of the potentials), and not less
than FLOOR = 1e-6 times the largest signal of its physical kind, nor than 100 ATOL / TOL:
the integrator does not control errors much below its absolute tolerance (a current
that is 0 in exact arithmetic comes out as round-off of 1e-14 A).

Some signals are less accurate than that: accelerations and the forces on masses are
derivatives of the solution, and a lightly damped oscillation accumulates phase error
with every period.  So a case that deviates by more than TOL is simulated again at
rtol = 1e-10 (atol 1e-13): a correct model converges to the reference (the deviation
falls below TOL, or at least threefold to within 10 TOL: derivatives of the solution
converge more slowly than the solution), a wrong one does not (a modelling or
index-reduction error does not depend on the tolerance).  Any other deviation is
``wrong``; the detail of an ``ok`` says when the second run was needed.
"""
from __future__ import annotations

import math
import signal
import time
import traceback
import warnings
from contextlib import contextmanager
from dataclasses import dataclass, replace
from typing import Dict, Optional

import numpy as np

from .generators import electrical_network, ill_posed_network, mechanical_network
from .netlists import SOURCE_KINDS, Chooser, Netlist, build_model
from .reference import Reference

__all__ = ["Case", "Outcome", "AmbiguousCase", "make_case", "case_from_netlist", "run_case",
           "compare", "STRATEGIES", "CATEGORIES", "RTOL", "ATOL", "TOL", "time_span"]

RTOL, ATOL = 1e-8, 1e-12
TIGHT = (1e-10, 1e-13)        # the rerun of a case that deviates ...
TIGHT_FALLBACK = (1e-10, 1e-11)   # ... and of one whose tight run fails to start
TOL, FLOOR = 1e-5, 1e-6
N_TIMES = 21
STRATEGIES = ("electrical", "translational", "rotational", "ill-posed electrical",
              "ill-posed translational", "ill-posed rotational")
CATEGORIES = ("ok", "wrong", "rejected", "rejected, no culprit", "false rejection",
              "missed", "internal error", "hang")


@dataclass
class Case:
    net: Netlist
    ref: Optional[Reference] = None
    times: Optional[np.ndarray] = None
    expected: Optional[Dict[str, np.ndarray]] = None
    sizes: Optional[Dict[str, float]] = None


@dataclass
class Outcome:
    category: str
    detail: str = ""
    error: float = math.nan          # the worst relative deviation (simulated cases)
    signal: str = ""                 # ... and where
    seconds: float = 0.0

    @property
    def reason(self) -> str:
        """A short key of the detail (error type and its first words, numbers and
        names dropped), to group outcomes by what went wrong."""
        import re
        text = re.sub(r"at t ?= ?0(\.0*)?(?![.\deE])", "at start", self.detail)
        text = re.sub(r"at t ?= ?[-+.\deE]+", "later", text)
        text = re.sub(r"\[.*?\]|\(.*?\)|'.*?'", "", text)
        text = re.sub(r"[-+.\deE]*\d[-+.\deE]*", "", text)
        words = text.replace(":", " ").replace(";", " ").split()[:9]
        tail = re.search(r"\[with atol = rtol: (runs|fails|[A-Za-z]+)", self.detail)
        key = " ".join(words)
        if tail:
            key += " (with atol = rtol: " + tail.group(1) + ")"
        return key


class CaseTimeout(BaseException):
    """Raised by the alarm; a BaseException so that no ``except Exception`` in the code
    under test can swallow it."""


@contextmanager
def time_limit(seconds: Optional[float]):
    if not seconds:
        yield
        return

    def _alarm(signum, frame):
        raise CaseTimeout(f"over the time limit of {seconds:g} s")
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def time_span(eigenvalues) -> float:
    """A few of the slowest time constants, but at most 20 periods of the fastest
    lightly damped oscillation (which the integrator has to follow: its phase error
    grows with every period)."""
    mags = np.abs(eigenvalues)
    if not len(mags) or mags.max() == 0:
        return 1.0
    nonzero = mags[mags > 1e-9 * mags.max()]
    t = 3.0 / nonzero.min()
    osc = [abs(z.imag) for z in eigenvalues if z.imag != 0 and abs(z.real) < 0.2 * abs(z)]
    if osc:
        t = min(t, 20 * 2 * np.pi / max(osc))
    return float(f"{t:.3g}")


def _scaled(net: Netlist, t_end: float) -> Netlist:
    """Relative frequencies (per t_end) made absolute."""
    els = [replace(el, terms=tuple((a, f / t_end) for a, f in el.terms))
           if el.kind in SOURCE_KINDS else el for el in net.elements]
    return replace(net, elements=tuple(els), t_end=t_end)


def _zero_slopes(ch: Chooser, net: Netlist, ref: Reference) -> Netlist:
    """A source whose slope at t = 0 reaches a candidate state gets a second sine that
    cancels it (see reference.py: the result would depend on the selected states)."""
    els = []
    for el in net.elements:
        if el.kind in SOURCE_KINDS and len(el.terms) == 1 and 1 in ref.forced_orders(el.name):
            (a, f1), = el.terms
            f2 = f1 * (1.0 + round(ch.uniform(0.3, 2.0), 3))
            el = replace(el, terms=((a, f1), (-a * f1 / f2, f2)), realize="signal")
        els.append(el)
    return net.with_elements(els)


def case_from_netlist(net: Netlist, ref: Optional[Reference] = None) -> Optional[Case]:
    """The case of a netlist whose sources are final (absolute frequencies, t_end
    set), e.g. one edited by the shrinker; None if its expectation no longer holds (a
    regular network turned singular or ambiguous, an ill-posed one regular)."""
    if net.expect != "regular":
        structural = net.extra is None and not any(el.realize == "open" for el in net.elements)
        if structural and Reference(net).regular:
            return None
        return Case(net, times=np.linspace(0.0, net.t_end, 5))
    ref = ref or Reference(net)      # (a given ref must be of the same elements)
    if not ref.regular:
        return None
    terms = {el.name: el.terms for el in net.elements if el.kind in SOURCE_KINDS}
    if any(_ambiguous(ref, name, ts) for name, ts in terms.items()):
        return None
    times = np.linspace(0.0, net.t_end, N_TIMES)
    return Case(net, ref, times, *ref.evaluate(times, terms))


def _ambiguous(ref: Reference, name: str, terms) -> bool:
    """Whether a derivative of this source at t = 0 reaches a candidate state: a
    single sine has every odd derivative, a zero-slope pair those from the third on."""
    first = 1 if len(terms) == 1 else 3
    return any(k >= first and k % 2 for k in ref.forced_orders(name))


class AmbiguousCase(Exception):
    """A derivative of a source at t = 0 reaches a candidate state even with a zero
    slope (an index of 4 or more): acausal's answer would depend on its states."""


def make_case(ch: Chooser, strategy: str) -> Case:
    """Draw a case of ``strategy`` (one of STRATEGIES) and solve it with the reference.

    A well-posed strategy that draws a singular network by chance returns it as
    ill-posed (its defect "singular pencil (drawn at random)", no culprits).
    """
    if strategy.startswith("ill-posed"):
        net = _scaled(ill_posed_network(ch, strategy.split()[1]), 1.0)
        case = case_from_netlist(net)
        if case is None:
            raise AssertionError(f"the '{net.defect}' construction gave a regular network:\n"
                                 + net.describe())
        return case
    net = electrical_network(ch) if strategy == "electrical" else mechanical_network(ch, strategy)
    ref = Reference(net)
    if not ref.regular:
        net = replace(net, expect="ill-posed", defect="singular pencil (drawn at random)")
        return Case(net, ref, times=np.linspace(0.0, 1.0, 5))
    net = _zero_slopes(ch, _scaled(net, time_span(ref.eigenvalues)), ref)
    case = case_from_netlist(net, ref)
    if case is None:
        raise AmbiguousCase("a derivative of a source at t = 0 reaches a candidate state "
                             f"(index {ref.index}):\n" + net.describe())
    return case


def _typed_errors():
    import acausal as ac
    from acausal.compiler.structure.matching import StructuralError
    return (ac.ModelError, StructuralError, ac.InitializationFailed)


def _where(err: BaseException) -> str:
    """The innermost frame of the traceback inside the package (file:line function)."""
    frames = [f for f in traceback.extract_tb(err.__traceback__)
              if "/property/" not in f.filename]
    if not frames:
        return ""
    f = frames[-1]
    return f" at {'/'.join(f.filename.split('/')[-2:])}:{f.lineno} {f.name}"


def _first_line(err: BaseException, n: int = 300) -> str:
    text = " ".join(str(err).split())
    return f"{type(err).__name__}: {text[:n]}{'...' if len(text) > n else ''}"


def _names_culprit(message: str, culprits) -> bool:
    """Whether the message names one of the culprits as a component path (a source's
    own signal blocks, ``V1_s1`` and ``V1_add``, count as the source)."""
    import re
    return any(re.search(rf"(?<![\w.]){re.escape(c)}(_s\d|_add)?(?![\w])", message)
               for c in culprits)


def _kind(domain: str, name: str) -> str:
    last = name.rsplit(".", 1)[-1]
    if domain == "electrical":
        return "potential" if last == "v" else "current"
    return {"s": "position", "phi": "position", "s_rel": "position", "phi_rel": "position",
            "v": "velocity", "w": "velocity"}.get(last, "force")


def compare(case: Case, res):
    """(worst relative deviation, its signal, names missing from the result)."""
    peers: Dict[str, float] = {}
    for name, want in case.expected.items():
        k = _kind(case.net.domain, name)
        peers[k] = max(peers.get(k, 0.0), float(np.max(np.abs(want))))
    worst, where, missing = 0.0, "", []
    for name, want in sorted(case.expected.items()):
        if name not in res:
            missing.append(name)
            continue
        got = np.asarray(res[name], dtype=float)
        size = max(case.sizes[name], FLOOR * peers[_kind(case.net.domain, name)],
                   100 * ATOL / TOL)
        err = float(np.max(np.abs(got - want))) / size
        if not np.isfinite(err):
            err = math.inf
        if err > worst or not where:
            worst, where = err, name
    return worst, where, missing


def _tight_rerun(case: Case, compiled, limit) -> Optional[float]:
    """The worst deviation at rtol, atol = TIGHT (or, if that run fails, at the looser
    atol of TIGHT_FALLBACK; None if both fail): a correct model converges to the
    reference as the tolerance shrinks, a wrong one does not."""
    import acausal as ac
    for rtol, atol in (TIGHT, TIGHT_FALLBACK):
        try:
            with time_limit(limit), warnings.catch_warnings():
                warnings.simplefilter("ignore")
                res = ac.simulate(compiled, t_end=case.net.t_end, rtol=rtol, atol=atol,
                                  t_eval=case.times)
        except BaseException:               # noqa: BLE001  (a diagnostic only)
            continue
        if res.success:
            return compare(case, res)[0]
    return None


def _loose_retry(case: Case, compiled, limit) -> str:
    """Whether the failed run succeeds with the default atol (= rtol), and how close
    it then is: tells a start-up failure under a tight atol from a wrong model."""
    import acausal as ac
    try:
        with time_limit(limit), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = ac.simulate(compiled, t_end=case.net.t_end, rtol=RTOL, atol=RTOL,
                              t_eval=case.times)
    except BaseException as err:            # noqa: BLE001  (a diagnostic only)
        return f" [with atol = rtol: {type(err).__name__}]"
    if not res.success:
        return " [with atol = rtol: fails too]"
    worst, where, _ = compare(case, res)
    return f" [with atol = rtol: runs, worst deviation {worst:.2g} in {where}]"


def run_case(case: Case, limit: Optional[float] = 60.0) -> Outcome:
    import acausal as ac
    net, typed = case.net, _typed_errors()
    ill = net.expect != "regular"
    t0 = time.perf_counter()
    try:
        with time_limit(limit), warnings.catch_warnings():
            warnings.simplefilter("ignore")      # a failed run is classified, not warned
            model = build_model(net)
            compiled = ac.compile(model)
            res = ac.simulate(compiled, t_end=net.t_end, rtol=RTOL, atol=ATOL,
                              t_eval=case.times)
    except CaseTimeout as err:
        return Outcome("hang", str(err), seconds=time.perf_counter() - t0)
    except typed as err:
        dt = time.perf_counter() - t0
        if not ill:
            return Outcome("false rejection", _first_line(err) + _where(err), seconds=dt)
        if net.culprits and not _names_culprit(str(err), net.culprits):
            return Outcome("rejected, no culprit", _first_line(err), seconds=dt)
        return Outcome("rejected", _first_line(err, 120), seconds=dt)
    except Exception as err:                # noqa: BLE001  (classifying is the point)
        return Outcome("internal error", _first_line(err) + _where(err),
                       seconds=time.perf_counter() - t0)
    dt = time.perf_counter() - t0
    if ill:
        return Outcome("missed", f"success={res.success}: {res.message}"[:300], seconds=dt)
    if not res.success:
        return Outcome("false rejection", f"simulation failed: {res.message}"[:300]
                       + _loose_retry(case, compiled, limit), seconds=dt)
    try:
        worst, where, missing = compare(case, res)
    except Exception as err:                # noqa: BLE001
        return Outcome("internal error", "reading the result: " + _first_line(err) + _where(err),
                       seconds=dt)
    if missing:
        return Outcome("internal error", f"result lacks {', '.join(missing[:5])}", seconds=dt)
    if worst > TOL:
        got, want = res[where], case.expected[where]
        k = int(np.argmax(np.abs(got - want)))
        detail = (f"{where}: {got[k]:.6g} instead of {want[k]:.6g} at t = {case.times[k]:.4g}"
                  f" (max |ref| {np.max(np.abs(want)):.3g}; deviation {worst:.2g})")
        tight = _tight_rerun(case, compiled, limit)
        if tight is not None and (tight <= TOL or (tight <= 10 * TOL and tight < worst / 3)):
            # it converges to the reference: the deviation was the integrator's
            return Outcome("ok", f"converges: {worst:.2g} at rtol {RTOL:g}, {tight:.2g} at "
                           f"rtol {TIGHT[0]:g}", worst, where, time.perf_counter() - t0)
        return Outcome("wrong", detail + f"; at rtol {TIGHT[0]:g}: "
                       + ("failed" if tight is None else f"{tight:.2g}"),
                       worst, where, time.perf_counter() - t0)
    return Outcome("ok", error=worst, signal=where, seconds=dt)
