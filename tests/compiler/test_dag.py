"""The DAG walks of :mod:`acausal.compiler.algebra.dag` against sympy's own, and an inline
expression deeper than Python's recursion limit compiled and simulated against the same
law integrated by scipy."""
import math

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.compiler.algebra.dag import (dag_size, depth, transform, tree_reaches,
                                         tree_size, xreplace)


def test_an_unchanged_argument_reaches_its_parent_as_the_object_it_holds():
    # two equal numbers that are distinct objects: a walk that handed the parent the one
    # met first would rebuild the parent, and sympy would compare the rebuilt expression
    # with the old one as deep as both go
    x, y, d = sp.symbols("x y d", real=True)
    a, b = sp.Float(1.5), sp.Float(1.5)
    assert a is not b
    c1 = sp.sin(sp.Mul(a, x, evaluate=False))
    c2 = sp.cos(sp.Mul(b, y, evaluate=False))
    e = sp.Add(c1, c2, d, evaluate=False)
    handed = []

    def rebuild(node, args, _ctx):
        handed.append((node, all(p is q for p, q in zip(args, node.args))))
        return node

    assert transform(e, rebuild) is e
    assert all(same for _, same in handed), [str(n) for n, same in handed if not same]


def test_xreplace_and_sizes_agree_with_sympy():
    x, y, d, D = sp.symbols("x y d D", real=True)
    u = sp.sin(x) * y
    e = sp.cos(u + d) * u + d ** 2
    assert xreplace(e, {d: D}) == e.xreplace({d: D})
    assert tree_size(e) == sum(1 for _ in sp.preorder_traversal(e))
    assert dag_size([e]) == len(set(sp.preorder_traversal(e)))


def _tree_depth(e) -> int:
    return 0 if not e.args else 1 + max(_tree_depth(a) for a in e.args)


def test_the_bounded_walks_agree_with_sympys_tree():
    """tree_reaches(e, n) is whether sympy's preorder traversal has n nodes, and depth
    (a short recursion for small expressions, a DAG walk for others) the tree's depth,
    on expressions sharing a subexpression at every level."""
    x, y = sp.symbols("x y", real=True)
    cases, u = [x, -x, 2 * x * y, x * y - 3, sp.Add(*sp.symbols("a:12"))], x
    for k in range(6):
        u = sp.sin(u) * u + y ** (k + 2)
        cases.append(u)
    for e in cases:
        n = sum(1 for _ in sp.preorder_traversal(e))
        assert [tree_reaches(e, m) for m in (1, n - 1, n, n + 1)] == [True, True, True, False]
        assert depth(e) == _tree_depth(e)


def _law(x, y, t, steps, sin, cos):
    e = x
    for k in range(steps):
        e = sin((1.0 + (k % 7) / 10) * e + y) * e + cos(e - t) * ((k % 3 + 1) / 4)
    return e


STEPS = 300     # an expression about 900 deep, and its tree of about 1e340 nodes


class InlineLaw(ac.Component):
    x = ac.Variable(start=0.5, fixed=True)
    y = ac.Variable(start=0.1, fixed=True)

    def equations(self):
        e = _law(self.x, self.y, ac.time, STEPS, ac.sin, ac.cos)
        return [ac.Eq(ac.der(self.x), -self.x + 1e-3 * e),
                ac.Eq(ac.der(self.y), -self.y + self.x)]


def test_an_inline_law_deeper_than_the_recursion_limit_compiles_and_runs():
    res = ac.simulate(ac.compile(InlineLaw(), backend="numpy", cache=False,
                                 check_units="off"),
                      t_end=1.0, rtol=1e-9, t_eval=np.linspace(0, 1, 11))
    assert res.success, res.message

    def rhs(t, z):
        e = _law(z[0], z[1], t, STEPS, math.sin, math.cos)
        return [-z[0] + 1e-3 * e, -z[1] + z[0]]

    ref = solve_ivp(rhs, (0, 1), [0.5, 0.1], t_eval=res.t, rtol=1e-12, atol=1e-14)
    for k, name in enumerate(("x", "y")):
        err = np.max(np.abs(res[name] - ref.y[k])) / np.max(np.abs(ref.y[k]))
        assert err < 1e-7, (name, err)
