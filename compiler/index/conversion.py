"""Structural decisions checked exactly: Pryce's success test and the LC conversion.

The structural passes decide on integers.  A structurally regular DAE can still be
numerically singular: two nodal equations ``C (U1' - U2') + ... = 0`` and
``C (U2' - U1') + ... = 0`` have a perfect matching onto der(U1), der(U2), but their sum
contains no derivative at all.  Pantelides (and Pryce's Sigma-method, which is
equivalent) then report the wrong index, the wrong number of states and an
initialization that cannot succeed.  This pass finds such cases and converts the
equations before index reduction sees them.

Success check (Pryce, "A simple structural analysis method for DAEs", BIT Numer. Math.
41, 2001): with the signature matrix ``sigma`` and the canonical offsets ``c``
(equations), ``d`` (variables), the system Jacobian is

    J_ij = d f_i / d x_j^(d_j - c_i)     (0 where sigma_ij < d_j - c_i),

and the method succeeds (the index and the state count are right) iff J is nonsingular
at a consistent point.  J is split into its irreducible diagonal blocks (block
triangularization along the highest-value transversal; Tarjan's strongly connected
components).  Entries of numbers and parameters are evaluated exactly, with the
parameter values as rationals (``Fraction`` of the float values), by sparse Gaussian
elimination with Markowitz pivoting (Markowitz, Management Sci. 3, 1957) — fraction
arithmetic has no round-off, so a rank is a fact, not a tolerance.

Linear-combination conversion (Tan, Nedialkov & Pryce, "Conversion methods for
improving structural analysis of differential-algebraic equation systems", BIT Numer.
Math. 57, 2017; the block form follows their sequel "Conversion methods,
block triangularization, and structural analysis of differential-algebraic equation
systems"): for a constant left null vector u of a singular diagonal block, with
``I = {i : u_i != 0}`` and ``theta = min_{i in I} c_i``, one equation ``l in I`` with
``c_l = theta`` is replaced by

    fbar_l = sum_{i in I} u_i f_i^(c_i - theta).

The coefficient of x_j^(d_j - theta) in fbar_l is ``sum_i u_i J_ij = 0`` for every column
j of the block, exactly, so those derivatives are dropped from fbar_l.  Since u_l is a
non-zero constant and the other f_i stay in the system, the converted DAE has the same
solutions.  The value of the signature matrix strictly decreases: row l is now tight
only in columns of blocks that the block uses, so the columns of the block and of the
blocks that use it have one row fewer than they number in the tight pattern, and no
transversal reaches the old value.  That bounds the number of conversions; the pass
checks the decrease.

Rows of a block whose entries are all constant are enough for an exact null vector even
when other rows of the block depend on the variables; blocks whose singularity would
need variable values are recorded (:class:`NumericBlock`) so that the runtime can
evaluate them at the initial point (:func:`block_jacobian`).  :func:`convert` mutates
the SymbolicSystem and returns a :class:`ConversionResult` saying what it did.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
import sympy as sp

from ...components.symbols import time
from ..structure.blt import strongly_connected_components
from ..algebra.exact import (coefficient_oracle, exact_rank, exact_value, integer_vector,
                    left_null_vectors, parameter_values)
from ..structure.graph import UNASSIGNED, Structure
from .modp import full_row_rank_mod_p
from ..structure.sigma import SigmaResult, sigma_method, signature_matrix
from ..structure.matching import IndexReductionFailed, StructuralError, StructurallySingular
from ..algebra.symbolic import SymbolicEquation, sum_partial, symbols_of

__all__ = ["Conversion", "NumericBlock", "ConversionResult", "convert", "convert_model",
           "parameter_values", "exact_value", "exact_rank", "left_null_vectors",
           "coefficient_oracle", "block_jacobian"]

_GENERIC_SEED = 20170845     # fixed: the generic-rank probe must be deterministic


@dataclass
class Conversion:
    """One LC step: equation `replaced` became ``sum coefficient * d^order/dt^order(eq)``.

    ``terms``: ``(coefficient, equation name, order)`` of each combined equation (coprime
    integers, in equation order); ``columns``: the derivatives x_j^(d_j - theta) that
    cancel; ``matrix``: the singular constant block (Fractions; rows: the constant rows
    of the block, columns: `columns`); ``parameter_dependent``: the block is regular
    for generic parameter values, singular only for these; ``value_before`` /
    ``value_after``: value of the signature matrix around the round of this step;
    ``algebraic``: the combination has no derivative left; ``residual``: its sympy
    residual.
    """

    replaced: int
    terms: list
    columns: list
    matrix: list
    parameter_dependent: bool
    value_before: int
    value_after: int = -1
    text: str = ""
    algebraic: bool = False
    residual: object = None

    def note(self, index_after: int) -> str:
        names = [name if k == 0 else f"d{_pow(k)}/dt{_pow(k)}({name})"
                 for _, name, k in self.terms]
        if all(a == 1 and k == 0 for a, _, k in self.terms):
            head = "equations " + (", ".join(names[:-1]) + " and " + names[-1]) + " combined"
        else:
            head = f"equations combined as {self.text}"
        what = "is an algebraic constraint" if self.algebraic else "has lower derivatives only"
        out = (f"{head}: their highest derivatives {', '.join(self.columns)} had a singular "
               f"constant coefficient matrix {_matrix_text(self.matrix)}; the combination "
               f"{_clip(sp.sstr(self.residual))} = 0 {what} (index {index_after} after "
               "conversion; the equations as written hide it)")
        if self.parameter_dependent:
            out += ("; the matrix is singular only for the present parameter values (its "
                    "determinant is not identically zero), so the conversion holds for "
                    "these values")
        return out


@dataclass
class NumericBlock:
    """A diagonal block of J whose entries depend on variables or time: its regularity
    can only be judged at a point, e.g. the initial one (:func:`block_jacobian`).

    ``equations``: rows (equation indices of the converted system), with their
    ``equation_names``; ``variables``: columns, the highest derivative x_j^(d_j) of each
    base variable (what the differentiated equations are solved for); ``entries``:
    ``(row position, column position) -> expr``, with d f_i / d x_j^(d_j - c_i), which
    equals d f_i^(c_i) / d x_j^(d_j).
    """

    equations: list
    equation_names: list
    variables: list
    entries: dict = field(default_factory=dict)


@dataclass
class ConversionResult:
    """What :func:`convert` did: the ``conversions``; ``sigma``, Pryce's analysis of the
    converted system (None if it could not run, with the reason in ``error``);
    ``value_before``, the signature matrix's value before; ``numeric_blocks``, the blocks
    left for a numeric check; ``structure`` of the converted system (the input one if
    unchanged); ``coefficient``, the oracle of :func:`coefficient_oracle`."""

    conversions: list = field(default_factory=list)
    sigma: SigmaResult | None = None
    value_before: int = 0
    numeric_blocks: list = field(default_factory=list)
    structure: Structure | None = None
    coefficient: object = None
    error: str = ""

    @property
    def changed(self) -> bool:
        return bool(self.conversions)

    @property
    def index(self) -> int:
        return self.sigma.index if self.sigma else 0

    def notes(self) -> list:
        return [c.note(self.index) for c in self.conversions]


# -- the Sigma-method on the symbolic system -------------------------------------------
def _light_structure(system) -> Structure:
    """Incidence and derivative links only (no coefficient kinds): enough for Sigma."""
    graph = [sorted(system.index[q] for q in symbols_of(e.residual) if q in system.index)
             for e in system.equations]
    var_to_diff = [UNASSIGNED] * len(system.symbols)
    for x, dx in system.derivatives.items():
        if x in system.index and dx in system.index:
            var_to_diff[system.index[x]] = system.index[dx]
    return Structure(graph=graph, var_to_diff=var_to_diff, eq_to_diff=[UNASSIGNED] * len(graph),
                     coeff=[{} for _ in graph], var_names=[], eq_names=[])


def _analyse(system, s: Structure) -> tuple:
    """(sigma entries, SigmaResult, chains) with chains[j] the symbols of column j by order."""
    entries, columns = signature_matrix(s, sparse=True)
    res = sigma_method(entries)
    chains = []
    for b in columns:
        chain, sym = [system.symbols[b]], system.symbols[b]
        while sym in system.derivatives and system.derivatives[sym] in system.index:
            sym = system.derivatives[sym]
            chain.append(sym)
        chains.append(chain)
    return entries, res, chains


def _blocks(entries: dict, res: SigmaResult) -> tuple:
    """Irreducible diagonal blocks of J (rows, by the transversal) and tight entries per row."""
    c, d, t = res.c, res.d, res.transversal
    tight = {}
    for (i, j), o in entries.items():
        if o == d[j] - c[i]:
            tight.setdefault(i, []).append(j)
    row_of = {j: i for i, j in enumerate(t)}
    adj = [sorted({row_of[j] for j in tight.get(i, [])}) for i in range(len(t))]
    return strongly_connected_components(adj), tight


def _block_matrix(system, rows, tight, res, chains, values, cache) -> tuple:
    """Exact entries of the block's rows ({row: {col: Fraction}} for all-constant rows)
    and the symbolic entries {(row, col): expr} of all rows."""
    cols = {res.transversal[i] for i in rows}
    exact, symbolic = {}, {}
    for i in rows:
        row, ok = {}, True
        for j in tight.get(i, []):
            if j not in cols:
                continue
            expr = sum_partial(system.equations[i].residual, chains[j][res.d[j] - res.c[i]])
            symbolic[(i, j)] = expr
            if expr not in cache:
                cache[expr] = exact_value(expr, values)
            q = cache[expr]
            if q is None:
                ok = False
            elif ok:
                row[j] = q
        if ok:
            exact[i] = row
    return exact, symbolic


def _parameter_dependent(symbolic, rows, values) -> bool:
    """True if the rows are independent for generic parameter values (a probe with random
    rationals: a non-zero polynomial rarely vanishes at a random point)."""
    by_row = {}
    for (i, j), e in symbolic.items():
        by_row.setdefault(i, []).append((j, e))
    params = set()
    for i in rows:
        for _, e in by_row.get(i, []):
            params |= e.free_symbols
    if not params:
        return False
    rng = random.Random(_GENERIC_SEED)
    probe = {p: Fraction(rng.randint(1, 10**6), rng.randint(1, 10**6))
             for p in sorted(params, key=lambda q: q.name)}
    mat = {}
    for i in rows:
        row = {j: exact_value(e, probe) for j, e in by_row.get(i, [])}
        if any(q is None for q in row.values()):
            return False
        mat[i] = row
    return exact_rank(mat) == len(rows)


# -- one LC step -----------------------------------------------------------------------
def _lc_step(system, rows, u, res, chains, exact, symbolic, values, value) -> Conversion:
    """Replace one equation of the block by the combination u (see the module docstring)."""
    c, d = res.c, res.d
    support = sorted(i for i, q in u.items() if q)
    theta = min(c[i] for i in support)
    target = min(i for i in support if c[i] == theta)
    coef = integer_vector({i: u[i] for i in support}, target)
    cols = sorted({res.transversal[i] for i in rows})
    terms, total = [], sp.Integer(0)
    for i in support:
        r = system.equations[i].residual
        for _ in range(c[i] - theta):
            r = system.time_derivative(r)
        total += coef[i] * r
        terms.append((coef[i], system.equations[i].name(system), c[i] - theta))
    # the coefficient of each cancelled derivative is sum_i u_i J_ij = 0 exactly, so it
    # is dropped; distributing the products lets equal lower terms cancel as well
    cancelled = [_derivative(system, chains[j][0], d[j] - theta) for j in cols]
    total = sp.expand_mul(total.xreplace({q: 0 for q in cancelled if q is not None}))
    eq_l = system.equations[target]
    text = _combination_text(terms)
    _check_nontrivial(system, total, terms, text)
    same = {system.equations[i].component for i in support}
    comp, cls = ((eq_l.component, eq_l.component_class) if len(same) == 1
                 else ("", "combination of equations"))
    system.equations[target] = SymbolicEquation(total, text, comp, cls, eq_l.kind,
                                              combination=tuple(terms))
    anti = {dx: x for x, dx in system.derivatives.items()}
    algebraic = not any(q in anti for q in total.free_symbols)
    const_rows = [i for i in rows if i in exact]
    matrix = [[exact[i].get(j, Fraction(0)) for j in cols] for i in const_rows]
    return Conversion(target, terms, [q.name for q in cancelled if q is not None], matrix,
                      _parameter_dependent(symbolic, const_rows, values), value, text=text,
                      algebraic=algebraic, residual=total)


def _derivative(system, x: sp.Symbol, k: int):
    """The symbol of the k-th derivative of x, or None if it does not exist."""
    for _ in range(k):
        x = system.derivatives.get(x)
        if x is None or x not in system.index:
            return None
    return x


def _check_nontrivial(system, total, terms, text) -> None:
    if any(q in system.index for q in total.free_symbols):
        return
    names = [name for _, name, _ in terms]
    if sp.simplify(total) == 0:
        raise StructurallySingular(
            f"the equations {'; '.join(names)} are linearly dependent: {text} is 0 = 0 "
            "(one of them is redundant; the model is over-determined)", names)
    raise StructurallySingular(
        f"the equations {'; '.join(names)} contradict each other: {text} gives "
        f"{sp.sstr(total)} = 0", names)


def _combination_text(terms) -> str:
    out = []
    for k, (a, name, order) in enumerate(terms):
        body = name if order == 0 else f"d{_pow(order)}/dt{_pow(order)}({name})"
        mag = "" if abs(a) == 1 else f"{abs(a)}*"
        sign = ("-" if a < 0 else "") if k == 0 else (" - " if a < 0 else " + ")
        out.append(f"{sign}{mag}({body})")
    return "".join(out)


def _pow(k: int) -> str:
    return f"^{k}" if k > 1 else ""


def _clip(text: str, n: int = 80) -> str:
    return text if len(text) <= n else text[: n - 3] + "..."


def _matrix_text(matrix) -> str:
    if len(matrix) > 6 or any(len(r) > 6 for r in matrix):
        return f"({len(matrix)} x {len(matrix[0]) if matrix else 0})"
    return "[" + ", ".join("[" + ", ".join(str(q.numerator) if q.denominator == 1
                                           else f"{float(q):.6g}" for q in r) + "]"
                           for r in matrix) + "]"


# -- regular blocks, certified cheaply ---------------------------------------------------
def _null_vectors(rows: dict) -> list:
    """:func:`left_null_vectors` of the rows, which is [] when they have full row rank;
    that is settled first modulo a prime, where the arithmetic stays small
    (:mod:`acausal.compiler.index.modp`).  Only rows that are not of full rank mod p
    (singular, or, rarely, p divides the minors) are eliminated exactly.  Exact
    elimination of a large regular block (the capacitors of a network) spends its time
    on the growth of its integers; mod p it is the sparse elimination alone.
    """
    if len(rows) == 1:      # most blocks: one row, of full rank if an entry is not 0
        (row,) = rows.values()
        if any(row.values()):
            return []
    elif full_row_rank_mod_p(rows):
        return []
    return left_null_vectors(rows)


# -- unused derivatives ----------------------------------------------------------------
def _prune(system, keep) -> list:
    """Remove top-of-chain derivative symbols that no equation contains any more (a
    derivative in no equation would make index reduction differentiate again)."""
    used = set(keep)
    for e in system.equations:
        used |= symbols_of(e.residual)
    anti = {dx: x for x, dx in system.derivatives.items()}
    removed = set()
    tops = [q for q in system.symbols
            if q in anti and system.derivatives.get(q) not in system.index]
    for q in tops:
        while q in anti and q not in used:
            removed.add(q)
            q = anti[q]
    if not removed:
        return []
    system.symbols = [q for q in system.symbols if q not in removed]
    system.index = {q: k for k, q in enumerate(system.symbols)}
    for dx in removed:
        system.derivatives.pop(anti[dx], None)
    return sorted(q.name for q in removed)


# -- the pass --------------------------------------------------------------------------
def convert(system, structure: Structure | None = None, values: dict | None = None,
            keep=frozenset()) -> ConversionResult:
    """Check J exactly and apply LC conversions until every constant block is regular.

    Mutates `system` (see the module docstring).  `values` are the parameter values
    (:func:`parameter_values`); `keep` are symbols used outside the equations (initial
    equations, when-clauses) that must not be removed.  Raises StructurallySingular if
    a combination vanishes identically or contradicts itself.
    """
    values = values or {}
    out = ConversionResult(structure=structure)
    cache, nulls = {}, {}
    s = structure if structure is not None else _light_structure(system)
    out.coefficient = coefficient_oracle(system, values)    # looked up when called
    try:
        entries, res, chains = _analyse(system, s)
    except StructuralError as err:       # the balance pass has the diagnosis
        out.error = str(err).splitlines()[0]
        return out
    out.value_before = value = res.value
    limit = len(system.equations) + value + 1      # value decreases strictly each round
    for _ in range(limit):
        blocks, tight = _blocks(entries, res)
        steps, numeric = [], []
        for rows in blocks:
            exact, symbolic = _block_matrix(system, rows, tight, res, chains, values, cache)
            if len(rows) == 1 and len(exact) == 1:
                (row,) = exact.values()
                if len(row) == 1 and next(iter(row.values())) != 0:
                    continue     # one equation, one non-zero constant: regular
            key = tuple((i, tuple(sorted(row.items()))) for i, row in sorted(exact.items()))
            if key not in nulls:             # blocks untouched by a round keep their answer
                nulls[key] = _null_vectors(exact) if exact else []
            null = nulls[key]
            if null:
                steps.append((rows, null[0], exact, symbolic))
            elif len(exact) < len(rows):
                numeric.append((rows, symbolic))
        if not steps:
            out.numeric_blocks = [_numeric_block(system, rows, sym, res, chains)
                                  for rows, sym in numeric]
            out.sigma = res
            break
        done = [_lc_step(system, rows, u, res, chains, ex, sym, values, value)
                for rows, u, ex, sym in steps]
        try:
            entries, res, chains = _analyse(system, _light_structure(system))
        except StructuralError as err:
            texts = [c.text for c in done]
            raise StructurallySingular(
                f"after combining {'; '.join(texts)} the equations are singular ({err}): "
                "they are linearly dependent", texts) from None
        if res.value >= value:
            raise IndexReductionFailed(
                f"conversion did not lower the value of the signature matrix ({value} -> "
                f"{res.value}) for {'; '.join(c.text for c in done)}",
                [c.text for c in done])
        for step in done:
            step.value_after = res.value
        out.conversions += done
        value = res.value
    else:
        raise IndexReductionFailed(f"conversion did not finish in {limit} rounds")
    if out.conversions:
        _prune(system, keep)
        out.structure = system.structure()
        out.sigma = sigma_method(signature_matrix(out.structure, sparse=True)[0])
    if out.structure is None:
        out.structure = system.structure()
    return out


def convert_model(system, structure: Structure, flat) -> ConversionResult:
    """:func:`convert` with the parameter values of the (alias-reduced) flat model and its
    initial equations' and when-clauses' symbols kept."""
    keep = set()
    for e in flat.initial_equations:
        keep |= e.residual.free_symbols
    for w in flat.whens:
        keep |= w.condition.free_symbols
        for act in w.actions:
            keep |= act.variable.free_symbols | act.value.free_symbols
    return convert(system, structure, parameter_values(flat.parameters), keep)


def _numeric_block(system, rows, symbolic, res, chains) -> NumericBlock:
    # the block's columns in their own order, not the transversal's: several
    # transversals of highest value may exist, and the block is the same for each
    cols = sorted({res.transversal[i] for i in rows})
    pos_r = {i: k for k, i in enumerate(rows)}
    pos_c = {j: k for k, j in enumerate(cols)}
    return NumericBlock(list(rows), [system.equations[i].name(system) for i in rows],
                        [_derivative_name(chains[j][0].name, res.d[j]) for j in cols],
                        {(pos_r[i], pos_c[j]): e for (i, j), e in symbolic.items()})


def _derivative_name(name: str, k: int) -> str:
    return "der(" * k + name + ")" * k


def block_jacobian(block: NumericBlock, names, parameter_names):
    """A function ``f(t, values, p) -> ndarray`` of the block's J entries, where `values`
    are the values of the variables called `names` and `p` of `parameter_names`."""
    exprs = list(block.entries.values())
    known = set(names) | set(parameter_names) | {time.name}
    missing = sorted({q.name for e in exprs for q in e.free_symbols} - known)
    if missing:
        raise KeyError(f"J entries of {block.equation_names} need {missing}")
    xs = [sp.Symbol(n, real=True) for n in names]
    ps = [sp.Symbol(n, real=True) for n in parameter_names]
    fn = sp.lambdify([time, xs, ps], exprs, modules="numpy")
    shape = (len(block.equations), len(block.variables))
    keys = list(block.entries)

    def evaluate(t, values, p):
        out = np.zeros(shape)
        for (r, c), v in zip(keys, fn(t, values, p)):
            out[r, c] = v
        return out

    return evaluate
