"""Walks of an expression as the DAG it is: every distinct subexpression once, no recursion.

A model's expression is a tree to sympy but a DAG in memory: ``r = sin(u) * u`` with
``u`` built once holds ``u`` twice by reference.  Written inline, a wheelset's creep
force holds the profile functions dozens of times; its tree has 200 000 nodes, its DAG a
few thousand.  sympy's own walks (``xreplace``, ``has``, ``diff``, the printers) follow
the tree, and most of them recurse, so their cost is the tree's size and their depth
limit Python's.  The walks here visit each distinct node once (equal subexpressions are
one node: sympy's ``==`` and hash are structural) with an explicit stack, so they cost
the DAG's size and any depth is fine.
"""
from __future__ import annotations

from functools import lru_cache

__all__ = ["postorder", "transform", "xreplace", "dag_size", "tree_size", "tree_reaches",
           "depth", "DEEP"]


def postorder(roots, children=None):
    """Every distinct node under ``roots`` once, children before parents.
    ``children(node)`` (default: ``node.args``) says what to descend into."""
    kids = children or (lambda node: node.args)
    seen, out = set(), []
    for root in roots:
        if root in seen:
            continue
        stack = [(root, False)]
        while stack:
            node, ready = stack.pop()
            if ready:
                out.append(node)
                continue
            if node in seen:
                continue
            seen.add(node)
            stack.append((node, True))
            for k in reversed(kids(node)):
                if k not in seen:
                    stack.append((k, False))
    return out


def transform(root, rebuild, memo=None, context=None, descend=None):
    """The expression with every node replaced by ``rebuild(node, new_args, ctx)``,
    children first, each (node, context) pair once.

    ``new_args`` are the transformed arguments; ``rebuild`` returns the new node (often
    ``node`` itself when nothing changed, or ``node.func(*new_args)``).  ``context`` is
    an optional hashable value passed down the walk; ``descend(node, ctx)`` gives the
    context of a node's children (default: the same).  ``memo`` may be shared between
    calls (the same nodes are then rebuilt once for several roots)."""
    memo = {} if memo is None else memo
    step = descend or (lambda node, ctx: ctx)
    kept = set()        # keys whose node ``rebuild`` returned unchanged

    def new_arg(a, inner):
        # an unchanged argument is passed as the very object the parent holds: an equal
        # subexpression met first elsewhere may be another object, and rebuilding the
        # parent from it would make sympy compare the two as deep as they go
        return a if (a, inner) in kept else memo[(a, inner)]

    stack = [(root, context, False)]
    while stack:
        node, ctx, ready = stack.pop()
        key = (node, ctx)
        if key in memo:
            continue
        inner = step(node, ctx)
        if not ready:
            stack.append((node, ctx, True))
            for a in node.args:
                if (a, inner) not in memo:
                    stack.append((a, inner, False))
            continue
        out = rebuild(node, [new_arg(a, inner) for a in node.args], ctx)
        memo[key] = out
        if out is node:
            kept.add(key)
    return memo[(root, context)]


def dag_size(roots) -> int:
    """The number of distinct nodes under ``roots``."""
    return len(postorder(roots))


def tree_size(root) -> int:
    """The number of nodes of ``root`` as a tree (a shared node counted every time it is
    reached), computed over the DAG: one pass, whatever the count."""
    count = {}
    for node in postorder([root]):
        count[node] = 1 + sum(count[a] for a in node.args)
    return count[root]


def tree_reaches(root, n: int) -> bool:
    """``tree_size(root) >= n``, by a count of the tree's nodes that stops at ``n``: the
    walk of a small expression costs its few nodes, that of a large DAG ``n`` at most."""
    count, stack = 0, [root]
    while stack:
        count += 1
        if count >= n:
            return True
        stack.extend(stack.pop().args)
    return False


def xreplace(expr, mapping: dict):
    """``expr.xreplace(mapping)`` -- the same expression: a node found in ``mapping`` is
    replaced, a node whose arguments changed is rebuilt by ``func(*args)`` -- over the
    DAG, each distinct node once."""
    if not mapping:
        return expr

    def rebuild(node, args, _ctx):
        if node in mapping:
            return mapping[node]
        if all(a is b for a, b in zip(args, node.args)):
            return node
        return node.func(*args)

    return transform(expr, rebuild, descend=_stop_at(mapping))


def _stop_at(mapping):
    # a replaced node's arguments are not walked (xreplace does not look inside it);
    # the context says "inside a replaced node", where nothing is rebuilt
    return lambda node, inside: inside or node in mapping


DEEP = 48     # deeper expressions are walked here by the algebra's passes, not by sympy


@lru_cache(maxsize=200_000)
def depth(expr) -> int:
    """The depth of ``expr``'s tree (0 for an atom), over its DAG without recursion;
    remembered per expression (the passes ask it of the same ones many times)."""
    if expr.is_Atom:
        return 0
    shallow = _shallow_depth(expr, 3)
    if shallow is not None:          # most terms of a model (k*x*y, -x, R*(T - T_ref))
        return shallow
    d = {}
    for node in postorder([expr]):
        d[node] = 1 + max((d[a] for a in node.args), default=-1)
    return d[expr]


def _shallow_depth(expr, levels: int):
    """``depth(expr)`` when it is at most ``levels`` and no node has more than 8
    arguments, else None: a short recursion over the top of the tree (at most 584
    nodes), cheaper than the walk of the DAG for a small expression."""
    if expr.is_Atom:
        return 0
    args = expr.args
    if levels == 0 or len(args) > 8:
        return None
    most = -1
    for a in args:
        d = _shallow_depth(a, levels - 1)
        if d is None:
            return None
        if d > most:
            most = d
    return most + 1
