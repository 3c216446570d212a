"""State selection by dummy derivatives.

Mattsson & Söderlind, "Index reduction in differential-algebraic equations using
dummy derivatives", SIAM J. Sci. Comput. 14(3), 1993, on the structure augmented by
:func:`~acausal.compiler.structure.pantelides.pantelides`.  Where the structural choice is only
valid while some variable-dependent coefficients stay non-zero, the candidates are
reported as state sets for the runtime, in the spirit of Mattsson, Olsson & Elmqvist,
"Dynamic selection of states in Dymola", Modelica Workshop 2000.

Algorithm (paper section 3, step numbers in comments):

1. Rows: the top equation of every chain that was differentiated; columns: the
   highest-derivative variables in them that are derivatives of something.
2. Select as many columns as rows forming a structurally nonsingular block (a matching
   from columns into rows); the selected columns are dummy derivatives.
3. Next level: rows are the equations those rows were differentiated from, keeping only
   those that are themselves derivatives; columns are the antiderivatives of the
   selected columns.
4. Repeat until no rows remain.

Kinematic equations.  A model that names its velocities writes ``der(x) = v`` (two
unknowns, constant coefficients): v then *is* der(x), and der(v) is a second derivative
of x although the structure counts it as a first derivative of v.  Level 1 of such a
model can hold both der(x) and der(v) -- a velocity constraint G(x) v = 0 differentiated
once has G der(v) + (dG/dx der(x)) v -- and picking der(x) as the dummy would make the
position x algebraic, computed from a velocity constraint (ill-conditioned where
dG/dx v vanishes, and a position is what a user integrates).  So every variable gets a
*kinematic order*, its derivative order with such equations counted as links
(:func:`kinematic_orders`), and the columns of level 1 are only those of the highest
kinematic orders that still admit a nonsingular block: where the highest alone do, the
lower ones are no candidates (MS93 take the highest derivatives; these are they).

Column preference (which derivatives become dummies), in order:

* ``state_priority`` of the column's antiderivative (the potential state): NEVER first,
  then AVOID, DEFAULT, PREFER; ALWAYS is never a dummy;
* within a priority, columns selectable through LINEAR_CONST/LINEAR_PARAM coefficients
  first, so that the choice is valid everywhere;
* then by ``tie_break`` of the antiderivative: a variable with a fixed start value, then
  one with a nominal value of its own, is kept as a state before one without (Modelica
  tools' rule among equal StateSelect: the initial conditions stay on states as written);
* then columns whose antiderivative is itself a derivative (keeping declared variables,
  e.g. a velocity ``v`` rather than ``der(x)``, as states);
* then higher variable index (keeping earlier declared variables as states).

Numeric choice: a structurally nonsingular block can be numerically singular (constant
coefficients that cancel).  Where every coefficient of a level block (a connected
component of the level's rows and candidate columns) is LINEAR_CONST / LINEAR_PARAM and
the optional oracle ``coefficient(eq, var)`` gives its exact rational value, the columns
are chosen by a greedy on exact ranks instead: in the preference order above, a column
is taken when it raises the rank of the chosen columns.  This is the greedy algorithm
of the linear matroid of the block's columns, so it finds a nonsingular choice whenever
one exists; and since every linearly independent set is structurally independent, it
keeps the structural choice whenever that one is nonsingular.  The passes stay on
integers; only the oracle (built by :mod:`acausal.compiler.index.conversion` from the symbolic
system and the parameter values) knows numbers.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Optional, Union

from .blt import strongly_connected_components
from .graph import ALWAYS, LINEAR_PARAM, NONLINEAR, UNASSIGNED, Structure
from .pantelides import PantelidesResult
from .matching import _from_sentinel, _match, _to_sentinel
from ...errors import StructurallySingular

__all__ = ["StateSet", "StateSelection", "select_states", "index1_matching",
           "kinematic_orders"]


@dataclass
class StateSet:
    """A level block whose dummy choice is only locally valid.

    The runtime picks `n_dummies` of `candidates` such that the Jacobian of `equations`
    with respect to the picked candidates is nonsingular (e.g. by pivoting); the others
    stay true derivatives, i.e. their antiderivatives (``diff_to_var``) are states.
    Sets are listed level by level (level 1 = highest derivatives); MS93 step 3
    requires the candidates picked at level k+1 to be antiderivatives of dummies
    picked at level k.

    Attributes
    ----------
    level : int
        1 for the highest differentiated equations, 2 one level down, ...
    equations : list of int
        Rows of the block (a connected component of the level's incidence).
    candidates : list of int
        Derivative variables that may be dummies (state_priority ALWAYS excluded).
    n_dummies : int
        ``len(equations)``: how many candidates are dummies at any time.
    dummies : list of int
        The static choice (also in ``StateSelection.dummies``), valid where the
        Jacobian is nonsingular.
    """

    level: int
    equations: list
    candidates: list
    n_dummies: int
    dummies: list


@dataclass
class StateSelection:
    """Result of :func:`select_states`.

    Attributes
    ----------
    dummies : list of int
        Derivative variables demoted to algebraic unknowns ("dummy derivatives"): the
        link ``der(diff_to_var[d]) = d`` is cut, d is solved like any algebraic variable.
    states : list of int
        Variables v with ``var_to_diff[v]`` assigned and not a dummy: the differential
        states, integrated by the solver.
    state_derivatives : list of int
        ``var_to_diff[v]`` for v in `states`, same order: the unknowns of the
        differential part.
    unknowns : list of int
        All variables except `states`.  All equations of the structure (original and
        differentiated) solved for `unknowns` form a square, structurally nonsingular
        index-1 system; :func:`index1_matching` matches it.
    levels : list of (list, list)
        Per level (level 1 first): ``(equations, dummies selected at that level)``.
    state_sets : list of StateSet
        Blocks where the choice is only locally valid and another choice exists.
    numeric_changes : list of (int, list, list)
        ``(level, structural dummies, numeric dummies)`` for every level block where
        the exact-rank choice replaced a numerically singular structural choice.
    """

    dummies: list
    states: list
    state_derivatives: list
    unknowns: list
    levels: list = field(default_factory=list)
    state_sets: list = field(default_factory=list)
    numeric_changes: list = field(default_factory=list)
    excluded: list = field(default_factory=list)


def kinematic_orders(s: Structure) -> list:
    """The derivative order of every variable with kinematic equations ``der(x) = k v``
    counted as links (module docstring): a variable v so linked to der(x) has the
    order of der(x), and the chain of v's derivatives counts on from there."""
    link = {}
    for e in range(s.n_eqs):
        vs = s.graph[e]
        if len(vs) != 2 or any(s.coeff[e].get(v, NONLINEAR) > LINEAR_PARAM for v in vs):
            continue
        for d, v in ((vs[0], vs[1]), (vs[1], vs[0])):
            if (s.diff_to_var[d] is not UNASSIGNED and s.diff_to_var[v] is UNASSIGNED
                    and v not in link):
                link[v] = d
    def down(v):
        """The variable one step down v's chain and the order that step removes: der(x)
        for a linked v (the same order), x for der(x) (one order), or None."""
        if s.diff_to_var[v] is not UNASSIGNED:
            return s.diff_to_var[v], 1
        if v in link:
            return link[v], 0
        return None, 0

    orders = [None] * s.n_vars
    for v0 in range(s.n_vars):
        path, seen, v = [], set(), v0
        while orders[v] is None and v not in seen:
            seen.add(v)
            nxt, w = down(v)
            if nxt is None:
                break
            path.append((v, w))
            v = nxt
        # v: a variable of known order, the bottom of its chain, or where links close
        # a cycle (der(x) = y, der(y) = x: counted from there without the links)
        total = orders[v] if orders[v] is not None else 0
        if orders[v] is None:
            orders[v] = 0
        for u, w in reversed(path):
            total += w
            if orders[u] is None:
                orders[u] = total
    return orders


def _top_columns(s: Structure, rows: list, cols: list, korder: list) -> list:
    """The level-1 columns of the highest kinematic orders that still match every row
    (module docstring); all of ``cols`` when none do."""
    tiers = sorted({korder[c] for c in cols}, reverse=True)
    for t in tiers[:-1]:
        top = [c for c in cols if korder[c] >= t]
        if len(_select(s, rows, top)) == len(rows):
            return top
    return cols


def _level_columns(s: Structure, rows: list, allowed) -> list:
    cols = set()
    for e in rows:
        for v in s.graph[e]:
            if allowed is None:       # step 1: highest derivatives that are derivatives
                if s.var_to_diff[v] is UNASSIGNED and s.diff_to_var[v] is not UNASSIGNED:
                    cols.add(v)
            elif v in allowed and s.diff_to_var[v] is not UNASSIGNED:
                # step 3: antiderivatives of selected columns that are derivatives
                # themselves (a variable that is no derivative enters a differentiated
                # equation only as a value: a function's input whose derivative the
                # function's derivative does not need)
                cols.add(v)
    return sorted(cols)


def _sort_key(s: Structure, v: int) -> tuple:
    anti = s.diff_to_var[v]
    return (s.state_priority[anti], s.tie_break[anti], -s.order(anti), -v)


def _augment_col(c: int, cadj: dict, r2c: dict, c2r: dict, kmax: int,
                 dead: set) -> bool:
    """Alternating path from column `c` to a free row, new edges of kind <= kmax.

    Breadth-first, so that a free row near `c` is found without walking long chains.
    Rows reached by a failed search are added to `dead`: every alternating path into
    them stays among them, so no later search (with the same edges) can use them, and
    each row is explored by at most one failed search per edge set.
    """
    via, queue, qi = {c: None}, [c], 0   # column -> row by which it was reached
    came_from = {}                       # row -> column it was reached from
    while qi < len(queue):
        col = queue[qi]
        qi += 1
        for r, kind in cadj[col]:
            if kind > kmax or r in came_from or r in dead:
                continue
            came_from[r] = col
            if r not in r2c:
                while r is not None:     # flip: each column takes the row after it
                    col = came_from[r]
                    nxt = via[col]
                    r2c[r], c2r[col] = col, r
                    r = nxt
                return True
            queue.append(r2c[r])
            via[r2c[r]] = r
    dead.update(came_from)
    return False


def _select(s: Structure, rows: list, cols: list) -> dict:
    """Step 2: columns -> rows matching of size len(rows), by the preference order."""
    rowset = set(rows)
    cadj = {c: [] for c in cols}
    for e in rows:
        for v in s.graph[e]:
            if v in cadj:
                cadj[v].append((e, s.coeff[e].get(v, NONLINEAR)))
    for c in cols:
        cadj[c].sort()
    r2c, c2r = {}, {}
    order = sorted((c for c in cols if s.state_priority[s.diff_to_var[c]] < ALWAYS),
                   key=lambda c: _sort_key(s, c))
    i, dead_all = 0, set()      # rows that cannot reach a free row, whatever the edges
    while i < len(order) and len(r2c) < len(rowset):
        prio = s.state_priority[s.diff_to_var[order[i]]]
        j = i
        while j < len(order) and s.state_priority[s.diff_to_var[order[j]]] == prio:
            j += 1
        # globally valid edges first, then any; dead sets of the first pass become
        # stale once the second pass re-routes through variable coefficients
        for kmax, dead in ((LINEAR_PARAM, set(dead_all)), (NONLINEAR, dead_all)):
            for c in order[i:j]:
                if c not in c2r and len(r2c) < len(rowset):
                    _augment_col(c, cadj, r2c, c2r, kmax, dead)
        i = j
    return r2c


class _RankBasis:
    """Incremental exact rank of column vectors ``{row: Fraction}`` (row echelon form:
    every stored vector has a pivot row on which the vectors after it are zero)."""

    def __init__(self):
        self.basis = []              # (pivot row, vector)

    def add(self, vec: dict) -> bool:
        """Reduce `vec` by the basis; keep it and return True if it is independent."""
        vec = {r: x for r, x in vec.items() if x}
        for piv, b in self.basis:
            x = vec.get(piv)
            if x:
                f = x / b[piv]
                for r, y in b.items():
                    z = vec.get(r, 0) - f * y
                    if z:
                        vec[r] = z
                    else:
                        vec.pop(r, None)
        if not vec:
            return False
        self.basis.append((min(vec), vec))
        return True


def _numeric_block(s: Structure, rows: list, cols: list,
                   coefficient: Callable) -> Optional[dict]:
    """Exact coefficients {col: {row: Fraction}} if every entry is constant, else None."""
    out = {c: {} for c in cols}
    for e in rows:
        for v in s.graph[e]:
            if v not in out:
                continue
            if s.coeff[e].get(v, NONLINEAR) > LINEAR_PARAM:
                return None
            q = coefficient(e, v)
            if q is None:
                return None
            if q:
                out[v][e] = Fraction(q)
    return out


def _numeric_choice(s: Structure, level: int, rows: list, cols: list, r2c: dict,
                    coefficient: Callable, changes: list) -> dict:
    """Replace the structural choice of every all-constant level block by the greedy on
    exact ranks (see the module docstring); record the blocks where it differs."""
    r2c = dict(r2c)
    for crows, ccols in _components(s, rows, cols):
        mat = _numeric_block(s, crows, ccols, coefficient)
        if mat is None:
            continue
        basis, chosen = _RankBasis(), []
        for c in sorted((c for c in ccols if s.state_priority[s.diff_to_var[c]] < ALWAYS),
                        key=lambda c: _sort_key(s, c)):
            if len(chosen) == len(crows):
                break
            if basis.add(mat[c]):
                chosen.append(c)
        if len(chosen) < len(crows):
            continue                 # singular for every choice: keep the structural one
        before = sorted(r2c[e] for e in crows if e in r2c)
        check = _RankBasis()
        if sorted(chosen) == before or all(check.add(mat[c]) for c in before):
            continue                 # the structural choice is nonsingular: keep it
        match = _match_columns(crows, chosen, mat)
        for e in crows:
            r2c.pop(e, None)
        r2c.update(match)
        changes.append((level, before, sorted(chosen)))
    return r2c


def _match_columns(rows: list, cols: list, mat: dict) -> dict:
    """rows -> cols along non-zero entries (exists: the chosen block is nonsingular)."""
    cadj = {c: sorted((e, 0) for e in mat[c]) for c in cols}
    r2c, c2r = {}, {}
    for c in cols:
        _augment_col(c, cadj, r2c, c2r, 0, set())
    return r2c


def _components(s: Structure, rows: list, cols: list) -> list:
    """Connected components (rows, cols) of the level graph, by smallest row."""
    colset, parent = set(cols), {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for e in rows:
        for v in s.graph[e]:
            if v in colset:
                parent[find(("c", v))] = find(("r", e))
    groups = {}
    for e in rows:
        groups.setdefault(find(("r", e)), ([], []))[0].append(e)
    for v in cols:
        groups.setdefault(find(("c", v)), ([], []))[1].append(v)
    return sorted((g for g in groups.values() if g[0]), key=lambda g: g[0][0])


def _locally_valid(s: Structure, rows: list, r2c: dict) -> bool:
    """True if det of the selected block may vanish: a variable-coefficient entry lies
    on some perfect matching (matched, or inside a strongly connected block)."""
    idx = {e: i for i, e in enumerate(rows)}
    owner = {r2c[e]: idx[e] for e in rows}
    adj = [sorted({owner[v] for v in s.graph[e] if v in owner}) for e in rows]
    comp = [0] * len(rows)
    for k, c in enumerate(strongly_connected_components(adj)):
        for i in c:
            comp[i] = k
    for e in rows:
        for v in s.graph[e]:
            if (v in owner and s.coeff[e].get(v, NONLINEAR) > LINEAR_PARAM
                    and comp[owner[v]] == comp[idx[e]]):
                return True
    return False


def _state_sets(s: Structure, level: int, rows: list, cols: list, r2c: dict) -> list:
    out = []
    cols = [c for c in cols if s.state_priority[s.diff_to_var[c]] < ALWAYS]
    for crows, ccols in _components(s, rows, cols):
        if len(ccols) > len(crows) and _locally_valid(s, crows, r2c):
            out.append(StateSet(level, crows, ccols, len(crows),
                                sorted(r2c[e] for e in crows)))
    return out


def select_states(p: Union[PantelidesResult, Structure],
                  coefficient: Optional[Callable] = None) -> StateSelection:
    """Choose dummy derivatives and states (Mattsson & Söderlind 1993).

    Parameters
    ----------
    p : PantelidesResult or Structure
        The index-reduced structure (``p.structure`` of a PantelidesResult).
    coefficient : callable, optional
        ``coefficient(eq, var) -> Fraction | None``: the exact constant coefficient of
        var in eq, None where it is not constant.  With it, all-constant level blocks
        are chosen by exact rank (module docstring).

    Returns
    -------
    StateSelection

    Raises
    ------
    StructurallySingular
        If at some level no nonsingular block can be selected, e.g. because the only
        possible dummies are variables whose antiderivative has state_priority ALWAYS.
    """
    s = p.structure if isinstance(p, PantelidesResult) else p
    rows = sorted(e for e in range(s.n_eqs) if s.diff_to_eq[e] is not UNASSIGNED
                  and s.eq_to_diff[e] is UNASSIGNED)              # step 1
    allowed, level, dummies, levels, sets, changes = None, 1, [], [], [], []
    excluded = []
    while rows:
        cols = _level_columns(s, rows, allowed)
        if allowed is None and cols:
            top = _top_columns(s, rows, cols, kinematic_orders(s))
            excluded = sorted(set(cols) - set(top))
            cols = top
        r2c = _select(s, rows, cols)                              # step 2
        if len(r2c) < len(rows):
            _fail(s, rows, cols, r2c)
        if coefficient is not None:
            r2c = _numeric_choice(s, level, rows, cols, r2c, coefficient, changes)
        chosen = sorted(r2c.values())
        dummies += chosen
        levels.append((rows, chosen))
        sets += _state_sets(s, level, rows, cols, r2c)
        rows = sorted(s.diff_to_eq[e] for e in rows                # step 3
                      if s.diff_to_eq[s.diff_to_eq[e]] is not UNASSIGNED)
        allowed = {s.diff_to_var[v] for v in chosen}
        level += 1
    out = _selection(s, dummies, levels, sets)
    out.numeric_changes = changes
    out.excluded = excluded
    return out


def _fail(s: Structure, rows: list, cols: list, r2c: dict) -> None:
    free = [e for e in rows if e not in r2c]
    always = [v for v in cols if s.state_priority[s.diff_to_var[v]] >= ALWAYS]
    msg = ("no nonsingular choice of dummy derivatives for "
           + ", ".join(s.eq_names[e] for e in free))
    if always:
        msg += ("; stateSelect=always prevents: "
                + ", ".join(s.var_names[s.diff_to_var[v]] for v in always))
    raise StructurallySingular(msg, [s.eq_names[e] for e in rows],
                               [s.var_names[v] for v in cols])


def _selection(s: Structure, dummies: list, levels: list, sets: list) -> StateSelection:
    dset = set(dummies)
    states = [v for v in range(s.n_vars)
              if s.var_to_diff[v] is not UNASSIGNED and s.var_to_diff[v] not in dset]
    sset = set(states)
    return StateSelection(sorted(dummies), states, [s.var_to_diff[v] for v in states],
                          [v for v in range(s.n_vars) if v not in sset], levels, sets)


def index1_matching(p: Union[PantelidesResult, Structure], sel: StateSelection) -> tuple:
    """Match every equation of the index-reduced structure to one of ``sel.unknowns``.

    Parameters
    ----------
    p : PantelidesResult or Structure
    sel : StateSelection
        From :func:`select_states` on the same structure.

    Returns
    -------
    var_to_eq, eq_to_var : list
        A perfect matching (``UNASSIGNED`` only for the states), ready for
        :func:`~acausal.compiler.structure.blt.blt`.

    Raises
    ------
    StructurallySingular
        If no perfect matching exists (names of the unmatched equations).
    """
    s = p.structure if isinstance(p, PantelidesResult) else p
    known = set(sel.states)
    adj = [[v for v in vs if v not in known] for vs in s.graph]
    l2r, r2l = [-1] * s.n_eqs, [-1] * s.n_vars
    if isinstance(p, PantelidesResult):      # warm start: highest derivatives are matched
        for e, v in enumerate(_from_sentinel(p.eq_to_var)):
            if v >= 0 and v not in known:
                l2r[e], r2l[v] = v, e
    l2r, r2l = _match(adj, s.n_vars, l2r, r2l)
    bad = [e for e in range(s.n_eqs) if l2r[e] < 0]
    if bad or s.n_eqs != len(sel.unknowns):
        raise StructurallySingular(
            "index-1 system is not square and nonsingular: "
            + ", ".join(s.eq_names[e] for e in bad), [s.eq_names[e] for e in bad])
    return _to_sentinel(r2l), _to_sentinel(l2r)
