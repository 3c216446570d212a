"""The initial system's structure: which initial conditions are kept, and the parameters
found by initialization (``Parameter(fixed=False)``, :mod:`acausal.components.initparams`).

At t0 the unknowns are the solver vector z and the free parameters; the equations are
the model's rows G and the initial rows (the user's initial equations and fixed starts,
then a start-value row for each state).  :func:`choose_initial_rows` keeps those rows
that complete a structural matching of that system, as many as there are states and
free parameters: each free parameter takes one of the user's conditions from the
states, which is how ``der(w) = 0`` decides a spring constant.  A free parameter that no
condition can determine is refused here, by name.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .structure.matching import _match
from ..errors import UnderdeterminedInitialization

__all__ = ["choose_initial_rows", "free_parameters", "FreeParameters", "followers"]


@dataclass
class FreeParameters:
    """The parameters found by initialization: ``index`` their positions in p,
    ``names`` and ``start`` (Newton's guess); ``g_cols`` / ``i_cols`` the free
    parameters (0-based among them) that each model row / initial row depends on,
    directly or through the assigned variables it reads; ``described`` how errors name
    each (``'spring' (Spring): parameter c``)."""
    index: list
    names: list
    start: list
    described: list
    g_cols: list
    i_cols: list


def free_parameters(params, assigned, rows, init_rows) -> FreeParameters | None:
    """The free parameters among ``params`` (those of the parameter vector, in order)
    and the rows of ``rows`` (the model's) and ``init_rows`` that read them; None when
    every parameter has a value."""
    free = [(k, p) for k, p in enumerate(params) if not getattr(p, "fixed", True)]
    if not free:
        return None
    col = {p.symbol: j for j, (_, p) in enumerate(free)}
    reads = {}                    # assigned symbol -> the free parameters it depends on
    for a, expr in assigned:      # in the order computed: what an expression reads is known
        deps = _reads(expr, col, reads)
        if deps:
            reads[a] = deps
    return FreeParameters(
        [k for k, _ in free], [p.name for _, p in free], [float(p.value) for _, p in free],
        [p.describe() for _, p in free],
        [sorted(_reads(r, col, reads)) for r in rows],
        [sorted(_reads(r, col, reads)) for r in init_rows])


def followers(parameters, free: FreeParameters | None, psyms, zeros=()) -> list:
    """(name, f(p)) of each parameter bound to an expression that reads a free one
    (``c2 = 2 c``): its value is known once initialization has found them."""
    if free is None:
        return []
    import sympy as sp
    found = {s for s in psyms if s.name in set(free.names)}
    zero = {q.symbol: sp.Integer(0) for q in parameters if q.name in set(zeros)}
    exprs = {q.symbol: sp.sympify(q.value) for q in parameters
             if isinstance(q.value, sp.Basic) and not q.value.is_number}
    out = {}
    for q in parameters:
        e = exprs.get(q.symbol)
        for _ in range(len(exprs)):          # bindings of bindings, down to p
            if e is None or not (e.free_symbols & exprs.keys()):
                break
            e = e.xreplace({s: exprs[s] for s in e.free_symbols if s in exprs})
        if e is not None:
            e = e.xreplace(zero)
            if e.free_symbols & found and e.free_symbols <= set(psyms):
                out[q.name] = e
    from .backends.parametric import parameter_functions
    return parameter_functions(out, psyms) if out else []


def _reads(expr, col, reads) -> set:
    out = set()
    for s in getattr(expr, "free_symbols", ()):
        if s in col:
            out.add(col[s])
        elif s in reads:
            out |= reads[s]
    return out


def choose_initial_rows(model_code, init_code, n_res, n_mandatory, n_states, n_z,
                        free: FreeParameters | None = None):
    """``(kept, redundant)``: the mandatory initial rows that complete a structural
    matching of [G; initial rows] onto z (and the free parameters), in the order given,
    then those optional start-value rows (in state order) that complete it (Modelica's
    rule: start values fix the states that nothing else determines).  ``redundant`` are
    the mandatory rows left out: an over-specified initial problem, which the runtime
    accepts where the dropped conditions hold at the computed initial point
    (OpenModelica removes redundant initial equations after checking them, and so do
    we).  A free parameter left without a row is an UnderdeterminedInitialization."""
    keep = model_code.jac_rows < n_res
    adj = _adjacency(model_code.jac_rows[keep], model_code.jac_cols[keep], n_res)
    i_adj = _adjacency(init_code.jac_rows, init_code.jac_cols, init_code.n_rows)
    n_free = len(free.names) if free is not None else 0
    l2r, r2l = _match(adj, n_z)        # the model's rows onto z first: they stay matched
    if n_free:
        for r, cols in enumerate(free.g_cols[:n_res]):
            adj[r] = adj[r] + [n_z + j for j in cols]
        i_adj = [a + [n_z + j for j in cols] for a, cols in zip(i_adj, free.i_cols)]
        r2l = list(r2l) + [-1] * n_free
    needed = n_states + n_free
    chosen, redundant, start = [], [], 0
    if 0 < n_mandatory <= needed and min(l2r, default=0) >= 0:
        # the usual case, every mandatory row kept, found by one maximum matching from
        # the model's: a set of rows matched whole is what the one-by-one search below
        # keeps (the matchable sets of rows are a matroid), and that search costs a walk
        # through the matched graph per row
        whole = _match(adj + i_adj[:n_mandatory], len(r2l),
                       l2r + [-1] * n_mandatory, list(r2l))
        if min(whole[0]) >= 0:
            adj += i_adj[:n_mandatory]
            (l2r, r2l), chosen, start = whole, list(range(n_mandatory)), n_mandatory
    for k in range(start, init_code.n_rows):
        if len(chosen) == needed and k >= n_mandatory:
            break
        adj.append(i_adj[k])
        l2r.append(-1)
        if len(chosen) < needed and _augment(len(adj) - 1, adj, l2r, r2l):
            chosen.append(k)
        else:
            adj.pop()
            l2r.pop()
            if k < n_mandatory:
                redundant.append(k)
    if n_free and len(chosen) < needed:
        _undetermined(free, adj, l2r, r2l, n_z)
    return np.array(chosen, dtype=np.int64), redundant


def _undetermined(free, adj, l2r, r2l, n_z) -> None:
    """The free parameters that a maximum matching can leave without a row (those
    reachable by alternating paths from an unmatched column), named in an error."""
    rows_of = {}
    for r, cols in enumerate(adj):
        for c in cols:
            rows_of.setdefault(c, []).append(r)
    open_ = [c for c in range(len(r2l)) if r2l[c] < 0]
    seen = set(open_)
    while open_:
        c = open_.pop()
        for r in rows_of.get(c, ()):
            m = l2r[r]
            if m >= 0 and m not in seen:
                seen.add(m)
                open_.append(m)
    lacking = [j for j in range(len(free.names)) if n_z + j in seen]
    if not lacking:
        return                       # a variable lacks one: the runtime says which
    which = "; ".join(free.described[j] for j in lacking[:5])
    more = f" (and {len(lacking) - 5} more)" if len(lacking) > 5 else ""
    raise UnderdeterminedInitialization(
        f"{which}{more} is found by initialization (fixed=False), but no initial "
        "condition determines it: it needs an initial equation (in initial_equations(), "
        "or a variable's fixed=True or steady=True that it decides)",
        variables=[free.names[j] for j in lacking])


def _augment(root, adj, l2r, r2l) -> bool:
    """One augmenting path from row ``root`` (iterative Kuhn search); flips it if found."""
    seen, stack, parent = {root}, [(root, iter(adj[root]))], {}
    while stack:
        u, it = stack[-1]
        v = next(it, None)
        if v is None:
            stack.pop()
            continue
        w = r2l[v]
        if w < 0:
            while True:             # flip the path back to the root
                prev = l2r[u]
                l2r[u], r2l[v] = v, u
                if u == root:
                    return True
                u, v = parent[u], prev
        if w not in seen:
            seen.add(w)
            parent[w] = u
            stack.append((w, iter(adj[w])))
    return False


def _adjacency(rows, cols, n_rows) -> list:
    adj = [[] for _ in range(n_rows)]
    for r, c in zip(rows.tolist(), cols.tolist()):
        adj[r].append(c)
    return [sorted(set(a)) for a in adj]
