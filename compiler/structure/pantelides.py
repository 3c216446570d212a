"""Structural index reduction by Pantelides' algorithm.

Pantelides, "The consistent initialization of differential-algebraic systems",
SIAM J. Sci. Stat. Comput. 9(2), 1988, in the highest-derivative formulation used by
ModelingToolkit's StateSelection: equations are matched to highest-derivative
variables only; when no augmenting path exists from an equation, every equation
colored by the failed search is differentiated and every colored variable gets a
derivative, and the search is repeated from the derivative of the equation.

Before the loop the model is checked with :func:`~acausal.compiler.structure.matching.check_structure`
(perfect matching of equations onto derivative chains, Pryce 2001): that is the
condition for the loop to terminate, so a singular model raises with names instead of
looping.

Cost: every search uses generation stamps instead of clearing color arrays and lists
only what it colored, so a failed search costs the size of the colored set; on chains
of pendulums or gears the total is ~linear in the model size.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial
from typing import Callable, Optional

from .graph import DEFAULT, LINEAR_VAR, NONLINEAR, UNASSIGNED, Names, Structure
from .matching import _from_sentinel, _to_sentinel, check_structure
from ...errors import IndexReductionFailed

__all__ = ["PantelidesResult", "pantelides", "predict_derivative"]


@dataclass
class PantelidesResult:
    """Output of :func:`pantelides`.

    Attributes
    ----------
    structure : Structure
        The augmented structure: the input's variables and equations first (same
        indices), then the created derivative variables and differentiated equations.
        ``var_to_diff``/``diff_to_var``/``eq_to_diff``/``diff_to_eq`` are extended;
        new variables are named ``der(<name>)`` and get ``state_priority`` DEFAULT,
        new equations are named ``d/dt(<name>)``.
    var_to_eq : list
        Final matching of each highest-derivative variable to an equation at the top of
        its differentiation chain; ``UNASSIGNED`` for lower derivatives.
    eq_to_var : list
        Inverse of `var_to_eq`; ``UNASSIGNED`` for equations that were differentiated.
    diff_counts : list of int
        For each input equation, how many times it was differentiated.
    """

    structure: Structure
    var_to_eq: list
    eq_to_var: list
    diff_counts: list


def predict_derivative(s: Structure, e: int) -> tuple:
    """Structural incidence of d/dt(equation e), all derivative variables existing.

    d/dt f(v, ...) = sum_v df/dv * der(v): der(v) enters linearly with coefficient
    df/dv, so it keeps v's kind if v was linear and becomes LINEAR_VAR if v was
    nonlinear; v itself stays only where df/dv depends on variables.

    Returns
    -------
    vars : list of int
        Sorted variables of d/dt(e).
    coeff : dict
        ``{var: kind}`` for those variables.

    Raises
    ------
    ValueError
        If der(v) does not exist for some variable v of e.
    """
    out = {}
    for v in s.graph[e]:
        k = s.coeff[e].get(v, NONLINEAR)
        dv = s.var_to_diff[v]
        if dv is UNASSIGNED:
            raise ValueError(f"der({s.var_names[v]}) does not exist yet")
        kd = k if k <= LINEAR_VAR else LINEAR_VAR
        out[dv] = max(out.get(dv, kd), kd)
        if k >= LINEAR_VAR:     # a constant or parameter coefficient differentiates to 0
            kv = NONLINEAR if k == NONLINEAR else LINEAR_VAR
            out[v] = max(out.get(v, kv), kv)
    return sorted(out), out


class _Work:
    """Mutable growing copy of a Structure, with int (-1) maps for speed."""

    def __init__(self, s: Structure):
        self.s = replace(
            s, graph=list(s.graph), coeff=list(s.coeff), var_names=list(s.var_names),
            eq_names=Names(s.eq_names), state_priority=list(s.state_priority),
            tie_break=list(s.tie_break),
            var_to_diff=list(s.var_to_diff), diff_to_var=list(s.diff_to_var),
            eq_to_diff=list(s.eq_to_diff), diff_to_eq=list(s.diff_to_eq))
        self.v2d = _from_sentinel(s.var_to_diff)
        self.var_to_eq = [-1] * s.n_vars
        self.vstamp = [0] * s.n_vars
        self.estamp = [0] * s.n_eqs

    def add_var_derivative(self, v: int) -> int:
        s, dv = self.s, self.s.n_vars
        s.var_to_diff[v] = dv
        s.var_to_diff.append(UNASSIGNED)
        s.diff_to_var.append(v)
        s.var_names.append(f"der({s.var_names[v]})")
        s.state_priority.append(DEFAULT)   # user hints belong to declared variables
        s.tie_break.append(0)
        self.v2d[v] = dv
        self.v2d.append(-1)
        self.var_to_eq.append(-1)
        self.vstamp.append(0)
        return dv

    def add_eq_derivative(self, e: int, differentiate: Optional[Callable]) -> int:
        s, de = self.s, self.s.n_eqs
        vs, co = (differentiate or predict_derivative)(s, e)
        vs = sorted(vs)
        bad = [v for v in vs if not 0 <= v < s.n_vars]
        if bad:
            raise IndexReductionFailed(
                f"differentiate({s.eq_names[e]}) returned unknown variables {bad}",
                [s.eq_names[e]])
        s.graph.append(vs)
        s.coeff.append(dict(co))
        s.eq_to_diff[e] = de
        s.eq_to_diff.append(UNASSIGNED)
        s.diff_to_eq.append(e)
        s.eq_names.append(_derived_name(s.eq_names, e))
        self.estamp.append(0)
        return de


def _derived_name(names: Names, e: int):
    """The name of d/dt(equation e), made when read: ``d/dt(<name of e>)``."""
    return partial(_name_of_derivative, names, e)     # picklable, unlike a lambda


def _name_of_derivative(names: Names, e: int) -> str:
    return f"d/dt({names[e]})"


def _augment(w: _Work, root: int, stamp: int) -> tuple:
    """Augmenting path from equation `root` over highest-derivative variables.

    Pantelides' procedure AUGMENTPATH, searched breadth-first: a free highest
    variable close to `root` is found without first walking down long matched chains
    (depth-first search would, on a chain of bodies, walk the whole chain each time).
    On failure the colored sets are the same as for the paper's depth-first search:
    everything reachable by alternating paths, so every highest variable of every
    colored equation is colored.  Returns ``(found, colored_eqs, colored_vars)``.
    """
    graph, v2d, v2e, vstamp, estamp = w.s.graph, w.v2d, w.var_to_eq, w.vstamp, w.estamp
    ceqs, cvars = [root], []
    estamp[root] = stamp
    via, came_from = {root: -1}, {}     # eq -> var it was reached by; var -> eq before
    qi = 0
    while qi < len(ceqs):
        e = ceqs[qi]
        qi += 1
        for v in graph[e]:
            if v2d[v] < 0 and v2e[v] < 0:           # free highest derivative: flip path
                while v >= 0:
                    v2e[v], v = e, via[e]
                    if v >= 0:
                        e = came_from[v]
                return True, ceqs, cvars
        for v in graph[e]:
            if v2d[v] < 0 and vstamp[v] != stamp:
                vstamp[v] = stamp
                cvars.append(v)
                came_from[v] = e
                nxt = v2e[v]                         # matched: no free var was left
                if estamp[nxt] != stamp:
                    estamp[nxt] = stamp
                    via[nxt] = v
                    ceqs.append(nxt)
    return False, ceqs, cvars


def pantelides(s: Structure, differentiate: Optional[Callable] = None,
               max_rounds: Optional[int] = None, checked: bool = False) -> PantelidesResult:
    """Differentiate equations of `s` until they match onto highest derivatives.

    Parameters
    ----------
    s : Structure
        The flattened DAE (not modified).
    differentiate : callable, optional
        ``differentiate(s, eq) -> (vars, coeff_dict)``: exact incidence of d/dt(eq),
        called once the needed derivative variables exist in ``s`` (the structure being
        built).  Default: :func:`predict_derivative`.
    max_rounds : int, optional
        Safety bound on failed searches per input equation; default
        ``n_eqs + max derivative order + 2`` (never reached once the model has passed
        the structural check).
    checked : bool
        The caller has found ``s`` structurally regular already
        (:func:`~acausal.compiler.structure.matching.check_structure`): it is not
        checked again.

    Returns
    -------
    PantelidesResult

    Raises
    ------
    OverdeterminedModel, UnderdeterminedModel, StructurallySingular
        The model has no perfect matching of equations onto derivative chains.
    IndexReductionFailed
        `max_rounds` exceeded or the callback returned invalid variables.
    ValueError
        If `s` already contains differentiated equations.
    """
    if any(d is not UNASSIGNED for d in s.eq_to_diff):
        raise ValueError("pantelides() expects a DAE without differentiated equations")
    if not checked:
        check_structure(s)
    w = _Work(s)
    if max_rounds is None:
        max_rounds = s.n_eqs + max((s.order(v) for v in range(s.n_vars)), default=0) + 2
    stamp = 0
    # Invariants: only highest derivatives (v2d[v] < 0) are matched; a matched
    # equation is the top of its differentiation chain; a colored variable is matched
    # to a colored equation, so step (iii) below always finds d/dt of its equation.
    for k in range(s.n_eqs):                       # main loop: each input equation
        eq, rounds = k, 0
        while True:                                # repeat ... until PATHFOUND
            stamp += 1                             # "designate all nodes uncolored"
            found, ceqs, cvars = _augment(w, eq, stamp)          # AUGMENTPATH
            if found:
                break
            rounds += 1
            if rounds > max_rounds:
                raise IndexReductionFailed(
                    f"index reduction of {s.eq_names[k]} did not terminate after "
                    f"{max_rounds} differentiations", [w.s.eq_names[e] for e in ceqs],
                    [w.s.var_names[v] for v in cvars])
            cvars.sort()
            ceqs.sort()
            for v in cvars:                 # (i) every colored var gets der(var)
                w.add_var_derivative(v)
            for e in ceqs:                  # (ii) every colored equation is differentiated
                w.add_eq_derivative(e, differentiate)
            for v in cvars:                 # (iii) der(var) matched to d/dt(its equation)
                w.var_to_eq[w.v2d[v]] = _eq_index(w.s.eq_to_diff[w.var_to_eq[v]])
            eq = w.s.eq_to_diff[eq]         # (iv) continue from d/dt(eq)
    return _result(w, s.n_eqs)


def _eq_index(x) -> int:
    return -1 if x is UNASSIGNED else x


def _result(w: _Work, n_orig: int) -> PantelidesResult:
    # Colored variables keep stale entries to their old equations; only the
    # highest derivatives carry the final matching.
    v2e = [e if w.v2d[v] < 0 else -1 for v, e in enumerate(w.var_to_eq)]
    e2v = [-1] * w.s.n_eqs
    for v, e in enumerate(v2e):
        if e >= 0:
            e2v[e] = v
    counts = []
    for e in range(n_orig):
        c, x = 0, w.s.eq_to_diff[e]
        while x is not UNASSIGNED:
            c, x = c + 1, w.s.eq_to_diff[x]
        counts.append(c)
    return PantelidesResult(w.s, _to_sentinel(v2e), _to_sentinel(e2v), counts)
