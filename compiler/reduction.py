"""Index reduction and state selection, joined to the symbolic system.

Pantelides (1988) decides which equations to differentiate and how often; the
differentiation itself is symbolic (:meth:`SymbolicSystem.differentiate`).  Dummy
derivatives (Mattsson & Söderlind 1993) then decide which derivative variables stay true
derivatives (their antiderivative is a state) and which become algebraic.  Where the
choice is only valid locally (the pendulum's x or y), the state set is kept for dynamic
selection at run time.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .graph import UNASSIGNED, Structure
from .pantelides import pantelides
from .states import select_states

__all__ = ["IndexReduction", "reduce_index"]


@dataclass
class IndexReduction:
    structure: Structure
    diff_counts: list                 # per original equation
    pairs: list                       # every derivative link (v, der(v))
    dummies: list                     # derivative variables made algebraic
    dynamic: bool = False             # some dummy choice is only locally valid
    index: int = 0
    selection: object = None

    @property
    def n_states(self) -> int:
        return len(self.pairs) - len(self.dummies)

    @property
    def states(self) -> list:
        d = set(self.dummies)
        return [v for v, dv in self.pairs if dv not in d]


def reduce_index(system, s: Structure) -> IndexReduction:
    n_orig = s.n_eqs
    result = pantelides(s, differentiate=system.differentiate)
    sr = result.structure
    counts = list(result.diff_counts)[:n_orig]
    selection = select_states(result)
    pairs = [(v, sr.var_to_diff[v]) for v in range(sr.n_vars)
             if sr.var_to_diff[v] is not UNASSIGNED]
    n_states = len(pairs) - len(selection.dummies)
    has_algebraic = sr.n_vars - len(pairs) - n_states > 0
    index = (max(counts) + 1) if counts and max(counts) > 0 else int(has_algebraic)
    red = IndexReduction(sr, counts, pairs, sorted(selection.dummies),
                         bool(selection.state_sets), index, selection)
    _check_square(system, red)
    return red


def _check_square(system, red: IndexReduction) -> None:
    n_eq, n_var = len(system.equations), len(system.symbols)
    if n_eq + red.n_states != n_var:
        from .structure import IndexReductionFailed
        raise IndexReductionFailed(
            f"after index reduction the system is not square: {n_eq} equations + "
            f"{red.n_states} states for {n_var} variables", [], [])
