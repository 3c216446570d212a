"""Causalization: BLT ordering and tearing decide what the solver vector holds.

With the states known (from the integrator), the equations of the index-1 system are
matched to the remaining unknowns and sorted into blocks (Tarjan 1972, via
:func:`acausal.compiler.blt.blt`).  A scalar block whose unknown enters linearly with a
constant or parameter coefficient becomes an explicit assignment.  Any other block (an
algebraic loop, or a nonlinear scalar equation) is torn (:func:`acausal.compiler.tearing.
tear`): its iteration variables join the solver vector and its residual equations become
rows of F; the rest of the block is assigned in causal order.

The solver vector is then z = [states, iteration variables], and everything else is
computed from z by the assignments.  With dynamic state selection the roles of states
and dummies change at run time, so no causalization is done (the full form: every
variable in z).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .blt import blt
from .graph import LINEAR_PARAM, Structure
from .states import index1_matching
from .tearing import tear

__all__ = ["Causalization", "causalize", "full_form"]


@dataclass
class Causalization:
    z: list                    # variable indices in solver-vector order (states first)
    n_states: int
    assignments: list          # (variable, equation) in evaluation order
    residual_eqs: list         # equations that stay rows of F
    blocks: list = field(default_factory=list)   # for the index report
    causal: bool = True


def causalize(reduction) -> Causalization:
    """The causal form for a static state selection (see the module docstring)."""
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
        z += t.iteration_vars
        residuals += t.residual_eqs
        assignments += [(v, e) for e, v in t.inner]
        report.append({"size": len(block.eqs), "equations": block.eqs, "variables": block.vars,
                       "torn": len(block.eqs) > 1, "iteration_variables": t.iteration_vars,
                       "solved": "newton"})
    return Causalization(z, len(states), assignments, residuals, report)


def full_form(reduction, n_vars: int, n_eqs: int) -> Causalization:
    """Every variable in z, every equation a row (used with dynamic state selection)."""
    return Causalization(list(range(n_vars)), 0, [], list(range(n_eqs)), [], causal=False)
