"""Block-lower-triangular (BLT) ordering of a matched system.

Tarjan, "Depth-first search and linear graph algorithms", SIAM J. Comput. 1(2), 1972:
the strongly connected components of the equation dependency graph (equation e
depends on equation e' when e contains the variable matched to e') are the algebraic
blocks; Tarjan emits each component after every component it depends on, which is
the evaluation order.  The search is iterative, so 10^5 nested dependencies do not
overflow the Python stack.
"""
from __future__ import annotations

from typing import NamedTuple, Optional, Sequence

from .graph import UNASSIGNED, Structure

__all__ = ["Block", "strongly_connected_components", "blt"]


class Block(NamedTuple):
    """One block of the BLT form: solve `eqs` for `vars` (``vars[i]`` matched to ``eqs[i]``)."""

    eqs: list
    vars: list


def strongly_connected_components(adj: Sequence[Sequence[int]]) -> list:
    """Strongly connected components of a digraph, sinks first.

    Parameters
    ----------
    adj : sequence of sequences of int
        ``adj[u]``: successors of node u.

    Returns
    -------
    list of list of int
        Components (each sorted).  A component is listed after every component
        reachable from it, so with edges "u needs w" the list is an evaluation order.
        Roots are taken in increasing index and successors in the given order, making
        the result canonical for sorted adjacency lists.
    """
    n = len(adj)
    index, low, on_stack = [-1] * n, [0] * n, [False] * n
    stack, comps, counter = [], [], 0
    for root in range(n):
        if index[root] >= 0:
            continue
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack[root] = True
        work = [[root, 0]]                 # explicit DFS stack: [node, next successor]
        while work:
            top = work[-1]
            v, i = top
            if i < len(adj[v]):
                top[1] = i + 1
                w = adj[v][i]
                if index[w] < 0:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack[w] = True
                    work.append([w, 0])
                elif on_stack[w] and index[w] < low[v]:
                    low[v] = index[w]
                continue
            work.pop()
            if work and low[v] < low[work[-1][0]]:
                low[work[-1][0]] = low[v]
            if low[v] == index[v]:         # v is the root of a component
                comp = []
                while True:
                    w = stack.pop()
                    on_stack[w] = False
                    comp.append(w)
                    if w == v:
                        break
                comps.append(sorted(comp))
    return comps


def blt(s: Structure, eq_to_var: Sequence, eqs: Optional[Sequence[int]] = None) -> list:
    """Sort the matched equations of `s` into blocks in evaluation order.

    Parameters
    ----------
    s : Structure
    eq_to_var : sequence
        Matching of equations to their unknowns (``UNASSIGNED`` = not part of the
        system).  Variables not matched to any equation are treated as known.
    eqs : sequence of int, optional
        Restrict to these equations (default: all matched equations); variables
        matched to equations outside the set are treated as known.

    Returns
    -------
    list of Block
        ``Block(eqs, vars)`` in evaluation order: every variable a block uses is
        known or computed by itself or an earlier block.  Inside a block equations are
        sorted and ``vars[i] = eq_to_var[eqs[i]]``.

    Raises
    ------
    ValueError
        If an equation in `eqs` is unmatched.
    """
    if eqs is None:
        eqs = [e for e in range(s.n_eqs) if eq_to_var[e] is not UNASSIGNED]
    eqs = sorted(eqs)
    local = {e: i for i, e in enumerate(eqs)}
    owner = {}
    for e in eqs:
        v = eq_to_var[e]
        if v is UNASSIGNED:
            raise ValueError(f"equation {s.eq_names[e]} is not matched")
        owner[v] = local[e]
    adj = []
    for e in eqs:
        me = local[e]
        adj.append(sorted({owner[v] for v in s.graph[e] if v in owner} - {me}))
    return [Block([eqs[i] for i in c], [eq_to_var[eqs[i]] for i in c])
            for c in strongly_connected_components(adj)]
