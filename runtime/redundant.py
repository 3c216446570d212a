"""Over-specified initial problems: redundant initial conditions chosen, checked, dropped.

A model may state more initial conditions than it has states: the test set's transistor
amplifier gives consistent values for all eight node voltages of a circuit with five
capacitor states, a mechanism gives every coordinate although its constraints determine
some of them.  Modelica tools accept such a problem when the extra conditions are
consistent (OpenModelica: "the initial conditions are over specified ... the following
equations are redundant, so they are removed", after checking them) and refuse it when
they are not.  So do we:

1. The compiler keeps, in the order written, the conditions that complete a structural
   matching of [G; conditions] and marks the others redundant
   (:func:`acausal.compiler.assemble.choose_initial_rows`).  Structure cannot see a
   condition that repeats others through the model's equations (two node voltages
   across a capacitor whose charge is the state), so where there are redundant ones the
   kept rows are chosen again here, numerically, at the start point: with the
   algebraic unknowns solved from G, every condition becomes a row of sensitivities to
   the states, ``dI_S - dI_A (dG_A)^-1 dG_S``, each state scaled by ``|start| +
   nominal``; the rows are taken in order -- the user's conditions first, then start
   values of states -- where each adds a direction that the rows taken before do not
   span (Gram-Schmidt; a row whose remainder is below ``_DEPENDENT`` of its norm adds
   none, and one with no sensitivity left, below ``_DEPENDENT`` of its own scaled
   gradient, is one the model's equations determine).  Linear algebra of the
   start point only: the system solved afterwards is the model's own.
2. After the solve, every dropped condition of the user's is evaluated at the solution.
   It is *consistent* when its residual is at most ``_CONSISTENT`` of its scale
   ``sum_j |dI_k/dz_j| (|z_j| + nominal_j)`` (the change a relative perturbation of
   that size in every variable makes), and at least ``|start| + nominal`` for a fixed
   start value (whose variable the others may determine through no unknown at all): dropped, with an :class:`InitialConditionWarning`
   that names it, and listed in ``compiled.report.notes``.  Otherwise initialization
   fails naming the condition, its residual, and the kept conditions it conflicts with
   (those that, with the model's equations, determine the same direction).
"""
from __future__ import annotations

import warnings

import numpy as np

from ..words import zero_causes
from ..errors import InitialConditionWarning, InitializationFailed

__all__ = ["InitialConditionWarning", "choose_rows", "check_dropped"]

_DEPENDENT = 1e-7     # a row adds no direction when its remainder is below this of its norm
_CONSISTENT = 1e-6    # a dropped condition holds when its residual is below this of its scale
_LISTED = 8           # conditions named in a message, at most


def choose_rows(dG: np.ndarray, dI: np.ndarray, states, alg, scale: np.ndarray,
                order: list, needed: int):
    """``(chosen, coords)``: rows of ``dI`` (tried in ``order``) that with ``dG`` make a
    nonsingular system (module docstring, step 1), and for every row left out its
    coordinates on the directions of the chosen rows (to name conflicts); ``(None,
    None)`` when ``needed`` independent rows cannot be found (or dG/dz over the
    algebraic unknowns is singular there)."""
    try:
        X = np.linalg.solve(dG[:, alg], dG[:, states])
    except np.linalg.LinAlgError:
        return None, None
    # each condition's sensitivity to the states, the algebraic unknowns solved from G
    C = (dI[:, states] - dI[:, alg] @ X) * scale[states]
    raw = np.sqrt(((dI * scale) ** 2).sum(axis=1))
    Q, chosen, coords = [], [], {}
    for k in order:
        c = C[k]
        proj = np.array(Q) @ c if Q else np.zeros(0)
        rest = c - np.array(Q).T @ proj if Q else c
        size = float(np.linalg.norm(rest))
        # a row the model's equations determine has (up to rounding) no sensitivity
        # left; one that the rows before determine, no remainder beside them
        free = size > _DEPENDENT * max(float(np.linalg.norm(c)), 0.0) and \
            float(np.linalg.norm(c)) > _DEPENDENT * raw[k]
        if len(chosen) < needed and free:
            Q.append(rest / size)
            chosen.append(k)
        else:
            coords[k] = proj
    if len(chosen) < needed:
        return None, None
    return chosen, coords


def check_dropped(model, t0, z, dropped, coords, chosen) -> list:
    """Evaluate the dropped conditions of the user's at the solution ``z`` (module
    docstring, step 2): warn about the consistent ones and return their texts; raise
    :class:`InitializationFailed` for the first inconsistent ones."""
    init = model.initial
    if not dropped:
        return []
    r = init.residual_all(t0, z, model.p, model.m)
    J = init.jacobian_all(t0, z, model.p, model.m, model.n)
    size = np.abs(z) + model.nominal
    texts, bad = [], []
    for k in dropped:
        scale = float(np.abs(J[k]) @ size)
        if k < len(init.sizes):
            scale = max(scale, init.sizes[k])
        if abs(r[k]) <= _CONSISTENT * scale or (scale == 0.0 and r[k] == 0.0):
            texts.append(init.all_descriptions[k])
        else:
            bad.append((k, r[k], scale))
    if bad:
        lines = []
        for k, res, scale in bad[:_LISTED]:
            with_ = _conflicts(coords.get(k), chosen, init)
            lines.append(f"{init.all_descriptions[k]} (residual {res:.3g}, "
                         f"{abs(res) / scale:.2g} of its scale)"
                         + (f" conflicts with {with_}" if with_ else ""))
        places = [init.all_descriptions[k].rsplit("[", 1)[-1].split(" (")[0]
                  for k, _, _ in bad]
        cause = zero_causes(model.meta.get("structural_zeros", ()), places)
        raise InitializationFailed(
            f"initialization at t = {t0}: the initial problem is over-specified and "
            f"inconsistent: {len(dropped)} redundant initial condition(s) of "
            f"{len(dropped) + len(chosen)}, and {len(bad)} of them do not hold at the "
            "solution of the others with the model's equations: " + "; ".join(lines)
            + (f"; {cause}" if cause else ""),
            t0, equations=[init.all_descriptions[k] for k, _, _ in bad])
    note = ("over-specified initial problem: redundant initial conditions, consistent "
            "with the others and the model's equations, were dropped: "
            + "; ".join(texts[:_LISTED]) + (" ..." if len(texts) > _LISTED else ""))
    warnings.warn(note, InitialConditionWarning, stacklevel=4)
    report = getattr(model, "report", None)
    if report is not None and note not in report.notes:
        report.notes.append(note)
    return texts


def _conflicts(proj, chosen, init) -> str:
    if proj is None or not len(proj):
        return ""
    peak = float(np.max(np.abs(proj)))
    names = [init.all_descriptions[chosen[i]] for i in range(len(proj))
             if abs(proj[i]) > 1e-3 * peak]
    text = "; ".join(names[:_LISTED]) + (" ..." if len(names) > _LISTED else "")
    return f"[{text}] through the model's equations"
