"""Index reduction and state selection, joined to the symbolic system.

Pantelides (1988) decides which equations to differentiate and how often; the
differentiation itself is symbolic (:meth:`SymbolicSystem.differentiate`).  Dummy
derivatives (Mattsson & Söderlind 1993) then decide which derivative variables stay true
derivatives (their antiderivative is a state) and which become algebraic.  Where the
choice is only valid locally (the pendulum's x or y), the state set is kept for dynamic
selection at run time.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import partial

from ..algebra.symbolic import equation_symbols
from ..structure.graph import UNASSIGNED, Names, Structure
from ..structure.matching import base_variables
from ..structure.pantelides import pantelides
from ..structure.sigma import signature_matrix, sigma_method
from ..structure.states import select_states
from ...errors import IndexReductionFailed, StructuralError

__all__ = ["IndexReduction", "reduce_index", "differentiate", "select", "as_written"]


@dataclass
class IndexReduction:
    structure: Structure
    diff_counts: list                 # per original equation
    pairs: list                       # every derivative link (v, der(v))
    dummies: list                     # derivative variables made algebraic
    dynamic: bool = False             # some dummy choice is only locally valid
    index: int = 0
    selection: object = None
    pantelides: object = None

    @property
    def n_states(self) -> int:
        return len(self.pairs) - len(self.dummies)

    @property
    def states(self) -> list:
        d = set(self.dummies)
        return [v for v, dv in self.pairs if dv not in d]


def reduce_index(system, s: Structure, coefficient=None) -> IndexReduction:
    """Pantelides, then dummy derivatives (:func:`differentiate`, then :func:`select`)."""
    return select(system, differentiate(system, s), s.n_eqs, coefficient)


def differentiate(system, s: Structure):
    """Pantelides on ``s``, the equations it picks differentiated in ``system``
    (:meth:`SymbolicSystem.differentiate`); returns the
    :class:`~acausal.compiler.structure.pantelides.PantelidesResult`."""
    return pantelides(s, differentiate=system.differentiate)


def select(system, result, n_orig: int, coefficient=None) -> IndexReduction:
    """Dummy derivatives on the augmented structure of Pantelides' ``result`` (whose first
    ``n_orig`` equations are the system's before differentiation); ``coefficient``
    (``(eq, var) -> Fraction | None``, see
    :func:`acausal.compiler.index.conversion.coefficient_oracle`) lets state selection
    check constant blocks by exact rank.

    The index follows Pryce's convention (as :func:`as_written` does): the largest number
    of differentiations, plus one if some variable has no derivative at all (an
    algebraic variable, Pryce 2001 eq. (13)).
    """
    sr = result.structure
    counts = list(result.diff_counts)[:n_orig]
    selection = select_states(result, coefficient)
    pairs = [(v, sr.var_to_diff[v]) for v in range(sr.n_vars)
             if sr.var_to_diff[v] is not UNASSIGNED]
    algebraic = any(sr.var_to_diff[v] is UNASSIGNED and sr.diff_to_var[v] is UNASSIGNED
                    for v in range(sr.n_vars))
    index = max(counts, default=0) + int(algebraic)
    red = IndexReduction(sr, counts, pairs, sorted(selection.dummies),
                         bool(selection.state_sets), index, selection, result)
    _check_square(system, red)
    return red


def _check_square(system, red: IndexReduction) -> None:
    n_eq, n_var = len(system.equations), len(system.symbols)
    if n_eq + red.n_states != n_var:
        raise IndexReductionFailed(
            f"after index reduction the system is not square: {n_eq} equations + "
            f"{red.n_states} states for {n_var} variables", [], [])


def as_written(flat, checked: bool = False) -> dict:
    """The structural index of the model as the user wrote it (before alias elimination),
    by Pantelides and, independently, by Pryce's Sigma-method; they must agree.

    Alias elimination can resolve a constraint before index reduction sees it (two
    capacitors in parallel share one voltage variable), so the index the user's equations
    have is measured here, on integers only.  ``checked``: the alias-reduced system has
    passed the balance check, so this one is structurally regular too (every equation
    alias elimination removed held the variable it removed) and Pantelides need not
    check it again.
    """
    s = _flat_structure(flat)
    try:
        found = pantelides(s, checked=checked)
        counts = found.diff_counts[: s.n_eqs]
        entries, columns = signature_matrix(s, sparse=True)
        sig = sigma_method(entries, start=_pantelides_transversal(found, columns, s.n_eqs))
    except StructuralError as err:   # report only: the balance pass has the diagnosis
        return {"error": str(err).splitlines()[0]}
    index_p = _index_from_counts(counts, sig.d)
    disagree = [k for k, (a, b) in enumerate(zip(counts, sig.c)) if a != b]
    return {"index_pantelides": index_p, "index_sigma": sig.index,
            "counts": counts, "c": sig.c, "d": sig.d, "dof": sig.dof,
            "agrees": index_p == sig.index and not disagree,
            "disagreements": [s.eq_names[k] for k in disagree][:20]}


def _pantelides_transversal(found, columns: list, n_eqs: int):
    """Pantelides' final matching read as a transversal of the signature matrix, with
    offsets: equation i, differentiated c_i times, is matched to the highest derivative
    of a variable chain j, whose order d_j is the highest the chain reached.  The
    Sigma-method uses it only if these offsets prove it of highest value, which saves
    it an assignment problem of the model's size; the offsets it reports, the smallest,
    it computes from the transversal, not from Pantelides' counts."""
    aug = found.structure
    base = base_variables(aug)
    col = {b: k for k, b in enumerate(columns)}
    d = [0] * len(columns)
    for v in range(aug.n_vars):
        if aug.diff_to_var[v] is UNASSIGNED:        # walk each chain up once
            k, w = 0, aug.var_to_diff[v]
            while w is not UNASSIGNED:
                k, w = k + 1, aug.var_to_diff[w]
            j = col.get(v)
            if j is not None:
                d[j] = k
    transversal = []
    for e, c in enumerate(found.diff_counts[:n_eqs]):
        top = e
        for _ in range(c):
            top = aug.eq_to_diff[top]
        v = found.eq_to_var[top]
        if v is UNASSIGNED or base[v] not in col:
            return None
        transversal.append(col[base[v]])
    return transversal, found.diff_counts[:n_eqs], d


def _index_from_counts(counts, d) -> int:
    """Pryce's convention: max differentiations, plus one if some variable is algebraic."""
    return (max(counts, default=0)) + (1 if any(x == 0 for x in d) else 0)


def _text_of(eq):
    """The text of a flat equation, printed when read (a picklable bound call)."""
    return partial(_text, eq)


def _text(eq) -> str:
    return eq.text


def _flat_structure(flat) -> Structure:
    """Incidence of the flat equations (der(x) as its own variable), no coefficients."""
    index, var_to_diff = {}, []

    def add(sym):
        if sym not in index:
            index[sym] = len(var_to_diff)
            var_to_diff.append(UNASSIGNED)
        return index[sym]

    for v in flat.variables:
        add(v.symbol)
    for x, dx in list(flat.derivatives.items()):
        var_to_diff[add(x)] = add(dx)
    graph = [sorted(index[q] for q in equation_symbols(e) if q in index)
             for e in flat.equations]
    return Structure(graph=graph, var_to_diff=var_to_diff,
                     eq_to_diff=[UNASSIGNED] * len(graph),
                     eq_names=Names(_text_of(e) for e in flat.equations),
                     var_names=[q.name for q in index])
