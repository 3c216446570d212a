"""The text of a very long expression, shortened for people.

An equation written inline can be a DAG of thousands of subexpressions whose tree --
what a printer writes -- has hundreds of thousands of nodes: its full text takes
minutes to print and is of no use in a message or a report.  Past ``TEXT_NODES`` nodes
the text keeps the expression's top, breadth first, up to that many nodes, and writes
each subexpression left out as ``…``, then says how large the whole is.  (The compile
cache's keys never read these texts: they write expressions exactly,
:mod:`acausal.compiler.cachekeys`.)
"""
from __future__ import annotations

import sympy as sp

__all__ = ["shortened", "TEXT_NODES"]

TEXT_NODES = 3000


class _Elided(sp.Dummy):
    """A subexpression left out of a shortened text (printed ``…``)."""

    def _sympystr(self, printer):
        return "…"


def _tree_sizes(expr) -> dict:
    from ..compiler.algebra.dag import postorder
    size = {}
    for node in postorder([expr]):
        size[node] = 1 + sum(size[a] for a in node.args)
    return size


def _written_size(expr, keep) -> int:
    """The tree size of ``expr`` with the nodes outside ``keep`` written as one."""
    from ..compiler.algebra.dag import postorder
    size = {}
    for node in postorder([expr], lambda n: n.args if n in keep else ()):
        size[node] = 1 + sum(size[a] for a in node.args) if node in keep else 1
    return size[expr]


def shortened(expr, printer) -> str | None:
    """The shortened text of ``expr`` (printed by ``printer``), or None when it is
    short enough to print whole."""
    if not isinstance(expr, sp.Basic) or expr.is_Atom:
        return None
    size = _tree_sizes(expr)
    total = size[expr]
    if total <= TEXT_NODES:
        return None
    # the nodes within a depth from the top (a shortest path), the depth the largest
    # whose text, each shared node written where it is used, stays within TEXT_NODES
    depth, level, frontier = {expr: 0}, 0, [expr]
    while frontier:
        level += 1
        nxt = []
        for node in frontier:
            for a in node.args:
                if a not in depth:
                    depth[a] = level
                    nxt.append(a)
        frontier = nxt
    keep = {expr}
    for limit in range(1, level + 1):
        trial = {n for n, d in depth.items() if d <= limit}
        if _written_size(expr, trial) > TEXT_NODES:
            break
        keep = trial
    from ..compiler.algebra.dag import postorder
    memo = {}
    for node in postorder([expr], lambda n: n.args if n in keep else ()):
        if node not in keep:
            memo[node] = _Elided() if isinstance(node, sp.Expr) else node
            continue
        args = [memo[a] for a in node.args]
        try:
            memo[node] = node.func(*args) if any(
                x is not y for x, y in zip(args, node.args)) else node
        except (TypeError, ValueError):
            memo[node] = node
    return (f"{printer.doprint(memo[expr])}  [shortened: an expression of {total} nodes "
            f"written out, {len(size)} distinct]")
