"""Causalization: BLT ordering and tearing decide what the solver vector holds.

With the states known (from the integrator), the equations of the index-1 system are
matched to the remaining unknowns and sorted into blocks (Tarjan 1972, via
:func:`acausal.compiler.structure.blt.blt`).  A scalar block whose unknown enters linearly with a
constant or parameter coefficient becomes an explicit assignment.  Any other block (an
algebraic loop, or a nonlinear scalar equation) is torn (:func:`acausal.compiler.structure.tearing.
tear`): its iteration variables join the solver vector and its residual equations become
rows of F; the rest of the block is assigned in causal order.

The solver vector is then z = [states, iteration variables, variables kept for fill]
(:func:`_bound_fill`: an assigned variable whose gradient would have more than
``FILL_LIMIT`` entries stays an unknown), and everything else is computed from z by the
assignments.  With dynamic state selection the roles of states
and dummies change at run time, so no causalization is done (the full form: every
variable in z).

Tearing must not trade numerical stability for size.  The inner assignments of a torn
block are a forward substitution, and along a chain (a resistor ladder torn at the
source end) each link can compute a small quantity as the difference of large ones: the
solution decays along the chain while the errors of the iteration variables and the
round-off grow, geometrically, so no Newton method converges on the torn residual.  So
every torn block is checked numerically with the coefficient values at the compile-time
point (:class:`~acausal.compiler.index.numeric.CoefficientValues`): along the assignments the
sensitivities to the iteration variables T are propagated twice,

    s_v = -(sum_{u != v} a_eu s_u) / a_ev,      m_v = (sum_{u != v} |a_eu| m_u) / |a_ev|,

signed and in absolute values (s_T = m_T = the unit vectors).  ``m_v / |s_v|`` is how
much of v's relative accuracy the chain cancels away, whatever the units of v and T (a
pressure computed from a volume flow through beta/V = 1e9 is no cancellation).  The signed
sensitivities also say how far an error of the iteration variables, which Newton
controls only on their own scale, spreads to the inner variables, which nobody checks:
``|s_v| scale_T / scale_v``.  The scales are those that equilibrate the block's own
coefficient matrix (Ruiz, "A scaling algorithm to equilibrate both rows and columns
norms in matrices", RAL-TR-2001-034: rows and columns scaled alternately until every
one has a largest entry of one), so that units do not count (a flow of 1e-4 m3/s and a
pressure of 1e7 Pa are each on their own scale) while a genuine geometric growth does:
a resistor ladder torn at its source end carries the guessed node voltage to the far end
multiplied by 11 per section, 1e40 over 40 sections.  A block whose cancellation exceeds ``CANCELLATION_LIMIT``, whose
spread exceeds ``SPREAD_LIMIT``, or that has more than ``TEAR_LIMIT`` equations, is not
torn: all its variables join the solver vector and all
its equations are rows of F, solved by the integrator's sparse LU as one linear system
per Newton iteration (as OpenModelica keeps a sparse solver for large systems).  The
report says which blocks and why.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .blt import blt
from .graph import LINEAR_PARAM, UNASSIGNED, Structure
from .states import index1_matching
from .tearing import tear

CANCELLATION_LIMIT = 1e6    # a torn chain may cancel at most this factor of accuracy
SPREAD_LIMIT = 1e8          # ... and spread an iteration variable's error at most this much
TEAR_LIMIT = 400            # larger algebraic blocks are solved whole (sparse LU)
FILL_LIMIT = 16             # gradient entries of an assigned variable beyond its own equation

__all__ = ["Causalization", "causalize", "full_form"]


@dataclass
class Causalization:
    z: list                    # variable indices in solver-vector order (states first)
    n_states: int
    assignments: list          # (variable, equation) in evaluation order
    residual_eqs: list         # equations that stay rows of F
    blocks: list = field(default_factory=list)   # for the index report
    causal: bool = True
    kept_for_fill: list = field(default_factory=list)   # assigned, but kept in z (fill)


def causalize(reduction, values=None) -> Causalization:
    """The causal form for a static state selection (see the module docstring).

    ``values``: a :class:`~acausal.compiler.index.numeric.CoefficientValues` for the
    conditioning check of torn blocks (None: no check).
    """
    s: Structure = reduction.structure
    states = reduction.states
    _, eq_to_var = index1_matching(reduction.pantelides, reduction.selection)
    z, assignments, residuals, report = list(states), [], [], []
    for block in blt(s, eq_to_var):
        if len(block.eqs) == 1 and s.coeff[block.eqs[0]].get(block.vars[0], 99) <= LINEAR_PARAM:
            assignments.append((block.vars[0], block.eqs[0]))
            report.append({"size": 1, "equations": block.eqs, "variables": block.vars,
                           "torn": False, "solved": "explicit"})
            continue
        t = tear(s, block.eqs, block.vars)
        why = _untearable(s, block, t, values)
        entry = {"size": len(block.eqs), "equations": block.eqs, "variables": block.vars,
                 "solved": "newton"}
        if why:
            z += list(block.vars)
            residuals += list(block.eqs)
            report.append({**entry, "torn": False, "not_torn": why})
            continue
        z += t.iteration_vars
        residuals += t.residual_eqs
        assignments += [(v, e) for e, v in t.inner]
        report.append({**entry, "torn": len(block.eqs) > 1,
                       "iteration_variables": t.iteration_vars})
    return _bound_fill(s, Causalization(z, len(states), assignments, residuals, report))


def _bound_fill(s, caus, limit: int | None = None) -> Causalization:
    """Keep in z every assigned variable whose gradient would exceed the fill bound.

    An assigned variable's gradient with respect to z is the union of those of the
    variables its equation reads (the forward-mode chain rule of
    :func:`acausal.compiler.backends.codegen.plan`, here on the structure).  Along a long chain of
    node balances these unions grow with the chain, and every variable assigned from the
    chain inherits them: in a random R/L/C network of 3000 parts 178,000 gradient
    entries, rows of up to 1,700, where each variable's own equation reads a handful.
    Such a variable is kept as an unknown instead, its equation a row of F (like a
    tearing variable): the row then has the entries its gradient would have had, and
    every variable downstream reads it through one entry.  The integrator leaves it out
    of the error test (``self_scaled``, solvers/base.py item 6), as when it was assigned:
    a force k (x1 - x2) held to rtol of its own would be stricter than the positions it
    is computed from.  A derivative variable stays assigned (the linking rows and the
    sensitivity equations read it so).  Kept are the variables whose
    gradient has more than ``limit`` entries and more than its own equation reads (a
    gradient no larger than its equation's incidence is no fill: the row would be as
    large, and e.g. the ground balance of a ladder reads every section), in BLT order, so
    each gradient has at most max(``limit``, incidence of its equation) entries, each row
    at most that many per variable it reads, and the Jacobian grows linearly with the
    model.

    Why 16 (network of 3000 parts; bound: Jacobian entries, gradient entries, unknowns
    added): none: 95,800, 176,600, 0; 64: 56,200, 78,000, 118; 32: 52,100, 48,000, 403;
    16: 35,100, 21,400, 540; 8: 25,200, 10,600, 684; 4: 20,900, 6,300, 899.  The
    simulation of 5 ms with the C backend took 46-50 s at 16, 47-56 s at 8, 71 s at 4
    and 51-70 s without the bound (single runs on a shared machine: no measurable gain
    below 16, where more unknowns are kept).  The compile gains: 13-24 s -> 7.6-11 s in
    all, of which the C compiler 8-18 s -> 2.7-5.5 s (``benchmarks/bench_scale.py``).
    At 16 the networks of 1000 parts (largest gradient 8) and the ladders and spring
    chains of ``benchmarks/families.py`` (gradients of 3, and the ground balance, which
    reads every section) keep their code byte for byte.
    """
    limit = FILL_LIMIT if limit is None else limit
    grad = {v: (v,) for v in caus.z}
    assignments, kept = [], []
    for v, e in caus.assignments:
        g = set()
        for u in s.graph[e]:
            if u != v:
                g.update(grad.get(u, ()))
        if len(g) > max(limit, len(s.graph[e]) - 1) and s.diff_to_var[v] is UNASSIGNED:
            kept.append((v, e))
            grad[v] = (v,)
        else:
            assignments.append((v, e))
            grad[v] = g
    if not kept:
        return caus
    caus.assignments = assignments
    caus.z = caus.z + [v for v, _ in kept]
    caus.residual_eqs = caus.residual_eqs + [e for _, e in kept]
    caus.kept_for_fill = [v for v, _ in kept]
    owner = {v: b for b in caus.blocks for v in b["variables"]}
    for v, _ in kept:
        owner[v].setdefault("kept_for_fill", []).append(v)
    return caus


def _untearable(s, block, t, values) -> str:
    """Why the block must be solved whole ('' if its tearing is acceptable)."""
    if not t.inner:
        return ""
    if len(block.eqs) > TEAR_LIMIT:
        return f"{len(block.eqs)} equations: solved whole by sparse LU (limit {TEAR_LIMIT})"
    if values is None:
        return ""
    scale = equilibrating_scales(s, block, values)
    loss, spread = chain_growth(s, t, values, lambda v: scale.get(v, 1.0))
    what = f"tearing to {len(t.iteration_vars)} iteration variable(s)"
    if loss > CANCELLATION_LIMIT:
        return (f"{what} cancels a factor {loss:.1e} (> {CANCELLATION_LIMIT:.0e}) of "
                "accuracy along its assignments: solved whole")
    if spread > SPREAD_LIMIT:
        return (f"{what} spreads their errors by {spread:.1e} (> {SPREAD_LIMIT:.0e}) to "
                "the variables assigned from them: solved whole")
    return ""


def equilibrating_scales(s, block, values, sweeps: int = 20) -> dict:
    """Column scales c_v of the block's coefficient matrix A such that D_r A D_c has every
    row and column of largest magnitude about one (Ruiz's iteration, square roots of the
    row and column maxima, a few sweeps)."""
    entries = []
    for e in block.eqs:
        for v in s.graph[e]:
            if v in block.vars:
                a = values.value(e, v)
                if a:
                    entries.append((e, v, abs(a)))
    r = {e: 1.0 for e in block.eqs}
    c = {v: 1.0 for v in block.vars}
    for _ in range(sweeps):
        row_max, col_max = dict.fromkeys(r, 0.0), dict.fromkeys(c, 0.0)
        for e, v, a in entries:
            x = r[e] * a * c[v]
            row_max[e] = max(row_max[e], x)
            col_max[v] = max(col_max[v], x)
        if all(abs(x - 1.0) < 0.1 for x in list(row_max.values()) + list(col_max.values())
               if x > 0):
            break
        for e, x in row_max.items():
            if x > 0:
                r[e] /= np.sqrt(x)
        for v, x in col_max.items():
            if x > 0:
                c[v] /= np.sqrt(x)
    return c


def chain_growth(s, t, values, scale) -> tuple:
    """(cancellation, spread) of a torn block (module docstring): the largest
    ``m_v / |s_v|`` and ``|s_v| scale_T / scale_v`` of its inner variables; inf where a
    pivot or a coefficient is not a number."""
    k = len(t.iteration_vars)
    sens = {v: np.eye(k)[j] for j, v in enumerate(t.iteration_vars)}
    mags = {v: np.eye(k)[j] for j, v in enumerate(t.iteration_vars)}
    t_scale = np.array([scale(v) for v in t.iteration_vars])
    worst, spread = 1.0, 0.0
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        for e, v in t.inner:
            pivot = values.value(e, v)
            if not pivot:
                return np.inf, np.inf
            acc, mag = np.zeros(k), np.zeros(k)
            for u in s.graph[e]:
                if u != v and u in sens:
                    a = values.value(e, u)
                    if a is None:
                        return np.inf, np.inf
                    acc += a * sens[u]
                    mag += abs(a) * mags[u]
            sens[v], mags[v] = -acc / pivot, mag / abs(pivot)
            lost = np.where(mags[v] > 0, mags[v] / np.abs(sens[v]), 1.0)
            ratio = float(np.max(lost))
            if not np.isfinite(ratio):
                return np.inf, np.inf   # exact cancellation, or beyond floating point
            worst = max(worst, ratio)
            spread = max(spread, float(np.max(np.abs(sens[v]) * t_scale)) / scale(v))
    return worst, spread


def full_form(reduction, n_vars: int, n_eqs: int, definitions=()) -> Causalization:
    """Every variable in z, every equation a row (used with dynamic state selection),
    except ``definitions``: ``(variable, equation)`` pairs, in the order they are
    computed, of explicit definitions that no choice of states involves (the
    intermediate quantities of :mod:`acausal.compiler.outline`), assigned."""
    assigned = {v for v, _ in definitions}
    defining = {e for _, e in definitions}
    return Causalization([v for v in range(n_vars) if v not in assigned], 0,
                         list(definitions), [e for e in range(n_eqs) if e not in defining],
                         [], causal=False)
