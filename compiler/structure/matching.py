"""Maximum matching, Dulmage-Mendelsohn decomposition and structural diagnosis.

The matching is Hopcroft & Karp, "An n^(5/2) algorithm for maximum matchings in
bipartite graphs", SIAM J. Comput. 2(4), 1973, started from a greedy matching (with
augmenting paths of length 3); it runs in O(E sqrt(V)) and, on the sparse graphs of
physical models, in a few phases.  The
decomposition follows Dulmage & Mendelsohn, "Coverings of bipartite graphs", Canad. J.
Math. 10, 1958: the over-determined part is everything reachable by alternating paths
from an unmatched equation, the under-determined part everything reachable from an
unmatched variable.

:func:`diagnose` checks a DAE before index reduction the way Pryce does ("A simple
structural analysis method for DAEs", BIT 41, 2001): every derivative chain
``x, der(x), der(der(x)), ...`` is one unknown, and the equations must have a perfect
matching onto these chains.  This is exactly the condition under which Pantelides'
algorithm terminates; a model violating it is over-, under-determined or singular.

All functions are deterministic: equations and variables are visited in increasing
index order and adjacency lists are sorted.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping, NamedTuple, Optional, Sequence

from .graph import DEFAULT, UNASSIGNED, Structure

__all__ = [
    "StructuralError", "IndexReductionFailed", "StructurallySingular",
    "OverdeterminedModel", "UnderdeterminedModel",
    "bipartite_matching", "maximum_matching", "DMParts", "dulmage_mendelsohn",
    "base_variables", "StructuralDiagnosis", "diagnose", "check_structure",
    "make_structure",
]


# --------------------------------------------------------------------------- errors
class StructuralError(Exception):
    """Base class: a structural pass could not proceed.

    Attributes
    ----------
    equations, variables : list of str
        User names of the equations / variables involved.
    diagnosis : StructuralDiagnosis or None
        The full diagnosis (indices, counts) when one was computed.
    """

    def __init__(self, message: str, equations: Sequence[str] = (),
                 variables: Sequence[str] = (), diagnosis=None):
        super().__init__(message)
        self.equations = list(equations)
        self.variables = list(variables)
        self.diagnosis = diagnosis


class IndexReductionFailed(StructuralError):
    """Index reduction (Pantelides) could not make the system matchable."""


class StructurallySingular(IndexReductionFailed):
    """Square, but no perfect matching of equations onto unknowns exists."""


class OverdeterminedModel(StructurallySingular):
    """More (independent) equations than unknowns in some part of the model."""


class UnderdeterminedModel(StructurallySingular):
    """Fewer equations than unknowns in some part of the model."""


# --------------------------------------------------------------------------- matching
def _greedy(adj: list, l2r: list, r2l: list) -> None:
    # A cheap start: take a free neighbour, else free one by moving its owner to
    # another free neighbour (augmenting paths of length 3).  On model graphs this
    # leaves Hopcroft-Karp only a few short phases.
    for u, vs in enumerate(adj):
        if l2r[u] >= 0:
            continue
        for v in vs:
            if r2l[v] < 0:
                l2r[u], r2l[v] = v, u
                break
        else:
            _short_augment(u, adj, l2r, r2l)


def _short_augment(u: int, adj: list, l2r: list, r2l: list) -> None:
    for v in adj[u]:
        w = r2l[v]
        for y in adj[w]:
            if r2l[y] < 0:
                l2r[w], r2l[y] = y, w
                l2r[u], r2l[v] = v, u
                return


def _bfs_layers(adj: list, l2r: list, r2l: list) -> Optional[list]:
    """Layer the left vertices by alternating distance from the free ones (HK step 1).

    The search is not cut at the first layer with a free right vertex: on model
    graphs the longer paths it admits save more phases than they cost.
    """
    inf = len(adj) + 1
    dist = [inf] * len(adj)
    queue = [u for u in range(len(adj)) if l2r[u] < 0]
    for u in queue:
        dist[u] = 0
    found, qi = False, 0
    while qi < len(queue):
        u = queue[qi]
        qi += 1
        for v in adj[u]:
            w = r2l[v]
            if w < 0:
                found = True
            elif dist[w] == inf:
                dist[w] = dist[u] + 1
                queue.append(w)
    return dist if found else None


def _dfs_augment(root: int, adj: list, l2r: list, r2l: list, dist: list,
                 ptr: list) -> bool:
    """Find one augmenting path from free `root` along the layers (HK step 2).

    Iterative so that paths of length 10^5 cannot overflow the Python stack; ``ptr``
    keeps each vertex's position in its adjacency so that the phase stays O(E).
    """
    dead = len(adj) + 1
    stack = [root]
    while stack:
        u = stack[-1]
        vs = adj[u]
        if ptr[u] == len(vs):
            dist[u] = dead           # no path through u in this phase
            stack.pop()
            continue
        v = vs[ptr[u]]
        ptr[u] += 1
        w = r2l[v]
        if w < 0:
            for x in reversed(stack):    # flip the path; ptr[x]-1 is the edge used
                y = adj[x][ptr[x] - 1]
                l2r[x], r2l[y] = y, x
            return True
        if dist[w] == dist[u] + 1:
            stack.append(w)
    return False


def _match(adj: list, n_right: int, l2r: Optional[list] = None,
           r2l: Optional[list] = None) -> tuple:
    """Maximum matching on int adjacency lists; -1 marks 'unmatched' (internal form)."""
    if l2r is None:
        l2r, r2l = [-1] * len(adj), [-1] * n_right
    _greedy(adj, l2r, r2l)
    while True:
        dist = _bfs_layers(adj, l2r, r2l)
        if dist is None:
            return l2r, r2l
        ptr = [0] * len(adj)
        for u in range(len(adj)):
            if l2r[u] < 0:
                _dfs_augment(u, adj, l2r, r2l, dist, ptr)


def _to_sentinel(xs: list) -> list:
    return [UNASSIGNED if x < 0 else x for x in xs]


def _from_sentinel(xs: Sequence) -> list:
    return [-1 if x is UNASSIGNED else x for x in xs]


def bipartite_matching(adj: Sequence[Sequence[int]], n_right: int,
                       allowed: Optional[Sequence[bool]] = None) -> tuple:
    """Maximum matching of a bipartite graph given by left adjacency lists.

    Parameters
    ----------
    adj : sequence of sequences of int
        ``adj[u]`` lists the right vertices adjacent to left vertex ``u`` (sorted for a
        canonical result).
    n_right : int
        Number of right vertices.
    allowed : sequence of bool, optional
        If given, only right vertices with ``allowed[v]`` may be matched.

    Returns
    -------
    left_to_right, right_to_left : list
        Partner of each vertex, or ``UNASSIGNED``.
    """
    if allowed is not None:
        adj = [[v for v in vs if allowed[v]] for vs in adj]
    l2r, r2l = _match([list(vs) for vs in adj], n_right)
    return _to_sentinel(l2r), _to_sentinel(r2l)


def maximum_matching(s: Structure, vars: Optional[Sequence[int]] = None) -> tuple:
    """Maximum matching of equations onto variables of `s`.

    Parameters
    ----------
    s : Structure
    vars : sequence of int, optional
        Restrict matching to these variables (e.g. the highest derivatives); all
        variables if omitted.

    Returns
    -------
    var_to_eq : list
        ``var_to_eq[v]`` is the equation matched to v, or ``UNASSIGNED``.
    eq_to_var : list
        ``eq_to_var[e]`` is the variable matched to e, or ``UNASSIGNED``.
    """
    allowed = None
    if vars is not None:
        allowed = [False] * s.n_vars
        for v in vars:
            allowed[v] = True
    eq_to_var, var_to_eq = bipartite_matching(s.graph, s.n_vars, allowed)
    return var_to_eq, eq_to_var


# --------------------------------------------------------------------------- Dulmage-Mendelsohn
class DMParts(NamedTuple):
    """Coarse Dulmage-Mendelsohn parts, as sorted index lists."""

    over_eqs: list      # reachable by alternating paths from an unmatched equation
    over_vars: list     # the variables those equations compete for
    under_eqs: list     # equations matched to variables reachable from a free variable
    under_vars: list    # reachable by alternating paths from an unmatched variable


def _reach(adj: list, partner: list, starts: list) -> tuple:
    """Alternating reach: start side -(any edge)-> other side -(matched edge)-> start side.

    Returns the sorted start-side and other-side vertex sets reached.
    """
    seen_a, seen_b = set(starts), set()
    stack = list(starts)
    while stack:
        a = stack.pop()
        for b in adj[a]:
            if b not in seen_b:
                seen_b.add(b)
                nxt = partner[b]
                if nxt >= 0 and nxt not in seen_a:
                    seen_a.add(nxt)
                    stack.append(nxt)
    return sorted(seen_a), sorted(seen_b)


def _dm(adj: list, n_right: int, l2r: list, r2l: list) -> DMParts:
    radj = [[] for _ in range(n_right)]
    for u, vs in enumerate(adj):
        for v in vs:
            radj[v].append(u)
    over_l, over_r = _reach(adj, r2l, [u for u in range(len(adj)) if l2r[u] < 0])
    under_r, under_l = _reach(radj, l2r, [v for v in range(n_right) if r2l[v] < 0])
    return DMParts(over_l, over_r, under_l, under_r)


def dulmage_mendelsohn(s: Structure, vars: Optional[Sequence[int]] = None) -> DMParts:
    """Over- and under-determined parts of the equation/variable graph of `s`.

    Parameters
    ----------
    s : Structure
    vars : sequence of int, optional
        Treat only these variables as unknowns (others are known); all if omitted.

    Returns
    -------
    DMParts
        ``(over_eqs, over_vars, under_eqs, under_vars)``, sorted lists of indices.
        The parts do not depend on which maximum matching is used.
    """
    keep = None if vars is None else set(vars)
    adj = [[v for v in vs if keep is None or v in keep] for vs in s.graph]
    l2r, r2l = _match(adj, s.n_vars)
    parts = _dm(adj, s.n_vars, l2r, r2l)
    if keep is not None:   # free variables outside `vars` are not unknowns
        under_vars = [v for v in parts.under_vars if v in keep]
        return parts._replace(under_vars=under_vars)
    return parts


# --------------------------------------------------------------------------- diagnosis
def base_variables(s: Structure) -> list:
    """``base[v]``: the variable at the start of v's derivative chain (v itself if none)."""
    base = [-1] * s.n_vars
    for v in range(s.n_vars):
        if s.diff_to_var[v] is UNASSIGNED:
            w = v
            while w is not UNASSIGNED:   # walk up the chain once: O(n) overall
                base[w] = v
                w = s.var_to_diff[w]
    return base


@dataclass
class StructuralDiagnosis:
    """Result of :func:`diagnose`.

    Attributes
    ----------
    kind : str
        ``'ok'``, ``'over'`` (more equations than unknowns), ``'under'`` (fewer) or
        ``'singular'`` (as many, but no perfect matching).
    equations : list of int
        Equations in the offending parts (over- then under-determined part), sorted.
    variables : list of int
        Unknowns in those parts, as base variables (start of each derivative chain).
    n_equations, n_unknowns : int
        Number of equations and of unknowns (derivative chains).
    over_equations, over_variables, under_equations, under_variables : list of int
        The two Dulmage-Mendelsohn parts separately.
    eq_names, var_names : list of str
        Names of `equations` / `variables`, for messages.
    """

    kind: str
    equations: list
    variables: list
    n_equations: int
    n_unknowns: int
    over_equations: list = field(default_factory=list)
    over_variables: list = field(default_factory=list)
    under_equations: list = field(default_factory=list)
    under_variables: list = field(default_factory=list)
    eq_names: list = field(default_factory=list)
    var_names: list = field(default_factory=list)

    def __str__(self) -> str:
        head = {"ok": "structurally well-posed",
                "over": "over-determined", "under": "under-determined",
                "singular": "structurally singular"}[self.kind]
        en = dict(zip(self.equations, self.eq_names))
        vn = dict(zip(self.variables, self.var_names))
        msg = f"{head}: {self.n_equations} equations, {self.n_unknowns} unknowns"
        if self.over_equations:
            msg += ("\n  too many equations for their variables: "
                    + ", ".join(en[e] for e in self.over_equations))
            if self.over_variables:
                msg += "\n    (they involve only: " + ", ".join(
                    vn[v] for v in self.over_variables) + ")"
            else:
                # left without unknowns by the aliases and constants: a quantity imposed
                # twice (two voltage sources in parallel, two motions on one flange)
                msg += ("\n    (they involve no unknown: each restates a quantity other "
                        "equations already fix, e.g. two sources imposing the same "
                        "voltage, speed or position; remove one of them)")
        if self.under_variables:
            msg += ("\n  variables not determined: "
                    + ", ".join(vn[v] for v in self.under_variables))
            if self.under_equations:
                msg += "\n    (occurring in: " + ", ".join(
                    en[e] for e in self.under_equations) + ")"
            if self.over_equations:
                # both parts at once usually have one cause
                msg += ("\n    (with equations too many, these are usually the flows "
                        "between two elements that impose the same quantity: remove one "
                        "of them before adding a ground or a connection)")
        return msg


def diagnose(s: Structure) -> StructuralDiagnosis:
    """Check that the DAE `s` is square and structurally nonsingular.

    Each derivative chain (a base variable and all its derivatives) is one unknown
    (Pryce 2001, the signature-matrix view); the equations must match perfectly onto
    the chains.

    Returns
    -------
    StructuralDiagnosis
        ``kind == 'ok'`` when a perfect matching exists.  Otherwise the over-determined
        part (equations reachable by alternating paths from unmatched equations) and the
        under-determined part (chains reachable from unmatched chains) with names.
    """
    base = base_variables(s)
    chains = sorted({base[v] for v in range(s.n_vars)})
    col = {b: j for j, b in enumerate(chains)}
    adj = [sorted({col[base[v]] for v in vs}) for vs in s.graph]
    l2r, r2l = _match(adj, len(chains))
    n_eq, n_un = s.n_eqs, len(chains)
    if min(l2r, default=0) >= 0 and min(r2l, default=0) >= 0:
        return StructuralDiagnosis("ok", [], [], n_eq, n_un)
    parts = _dm(adj, len(chains), l2r, r2l)
    kind = "over" if n_eq > n_un else "under" if n_eq < n_un else "singular"
    ov = [chains[j] for j in parts.over_vars]
    uv = [chains[j] for j in parts.under_vars]
    d = StructuralDiagnosis(
        kind, sorted(set(parts.over_eqs) | set(parts.under_eqs)), sorted(set(ov) | set(uv)),
        n_eq, n_un, parts.over_eqs, ov, parts.under_eqs, uv)
    d.eq_names = [s.eq_names[e] for e in d.equations]
    d.var_names = [s.var_names[v] for v in d.variables]
    return d


def check_structure(s: Structure) -> StructuralDiagnosis:
    """:func:`diagnose` `s` and raise the matching exception unless it is well-posed.

    Raises
    ------
    OverdeterminedModel, UnderdeterminedModel, StructurallySingular
        With the names of the equations and variables involved.
    """
    d = diagnose(s)
    if d.kind == "ok":
        return d
    exc = {"over": OverdeterminedModel, "under": UnderdeterminedModel,
           "singular": StructurallySingular}[d.kind]
    eqs = [s.eq_names[e] for e in d.equations]
    vs = [s.var_names[v] for v in d.variables]
    raise exc(str(d), eqs, vs, d)


# --------------------------------------------------------------------------- construction
def make_structure(equations: Sequence[Mapping[str, int]],
                   derivatives: Optional[Mapping[str, str]] = None,
                   eq_names: Optional[Sequence[str]] = None,
                   var_names: Optional[Sequence[str]] = None,
                   state_priority: Optional[Mapping[str, int]] = None) -> Structure:
    """Build a Structure from named incidences (for tests, examples and messages).

    Parameters
    ----------
    equations : sequence of mapping
        ``equations[e] = {var_name: coefficient kind}``.
    derivatives : mapping, optional
        ``{name: name of its derivative}``, e.g. ``{"x": "der(x)"}``.
    eq_names : sequence of str, optional
    var_names : sequence of str, optional
        Variable order; default: order of first appearance in `equations`, then in
        `derivatives`.
    state_priority : mapping, optional
        ``{name: NEVER..ALWAYS}``; others DEFAULT.

    Returns
    -------
    Structure
    """
    derivatives = dict(derivatives or {})
    names = list(var_names or [])
    seen = set(names)
    for name in [n for eq in equations for n in eq] + [n for kv in derivatives.items()
                                                       for n in kv]:
        if name not in seen:
            seen.add(name)
            names.append(name)
    idx = {n: i for i, n in enumerate(names)}
    var_to_diff = [UNASSIGNED] * len(names)
    for a, b in derivatives.items():
        var_to_diff[idx[a]] = idx[b]
    coeff = [{idx[n]: k for n, k in eq.items()} for eq in equations]
    prio = [dict(state_priority or {}).get(n, DEFAULT) for n in names]
    return Structure([sorted(c) for c in coeff], var_to_diff, [UNASSIGNED] * len(coeff),
                     coeff, names, list(eq_names) if eq_names else None, prio)
