"""Dynamic state selection in the compiled step loop (the layout ``cbdf_dyn.c`` reads).

With dynamic state selection the solver vector holds every variable and the choice of
states only switches which linking rows ``y'[s] - y[der(s)] = 0`` are active
(:mod:`acausal.runtime.model`).  After every accepted step,
:meth:`~acausal.runtime.dynamic.DynamicStateSelection.choose` first tests whether the
current choice is still good enough (its quality on every level at least half the best
quality of the last search) and searches only when it is not.  The compiled loop makes
that test itself, on the generated Jacobian at the accepted point, and returns to
Python only when it fails: Python then calls the problem's ``after_step`` (the same
search, the same hysteresis), and a new choice goes back to C as the new list of active
linking rows, the history kept (:meth:`BDF.reformulate`).  So the decisions are those
of the Python loop, up to the rounding of one determinant.

:func:`layout` builds the two int64/double arrays of ``cbdf_dyn.c`` (its header says
what they hold) for the current choice; it runs before every return into C, since a
search may have changed the choice or the reference quality.
"""
from __future__ import annotations

import numpy as np

__all__ = ["bind", "layout"]


def layout(plan) -> tuple[np.ndarray, np.ndarray]:
    """``(dl, dd)`` for ``cbdf_dyn.c`` from the model's test of its current choice of
    states (``LoopModel.dynamic_test()``), or, when that is None, a request to return
    after every step."""
    if plan is None:
        return np.array([0, 0, 1, 0], dtype=np.int64), np.zeros(1)
    longs, doubles, work = [len(plan), 0, 0, 0], [], 0
    for entries, scales, keep, threshold in plan:
        nr, nc = len(keep), len(scales)
        longs += [nr, nc, *keep, *(k for row in entries for k in row)]
        doubles += [threshold, *scales]
        work = max(work, nr * nc + nr * nr)
    longs[3] = len(doubles)
    return np.array(longs, dtype=np.int64), np.array(doubles + [0.0] * max(work, 1))


def bind(solver, plan) -> None:
    """Before a run of the compiled loop: the test of the current choice of states."""
    dl, dd = layout(plan)
    solver._set("dyn_longs", dl, np.int64)
    solver._set("dyn_doubles", dd)
