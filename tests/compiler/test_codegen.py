"""Generated code: residuals and Jacobians against sympy and finite differences."""
import math

import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.compiler.backends.codegen import extract_relations, generate
from acausal.library.examples.pendulum import DoublePendulum


def test_generated_residual_and_jacobian_match_sympy():
    x, y, k = sp.symbols("x y k")
    rows = [x**2 + sp.sin(y) - k, sp.exp(x * y) - 3 * y]
    code = generate(rows, [x, y], [k])
    z, p = np.array([0.3, -1.2]), np.array([2.5])
    r = code.residual(0.0, z, p, [], np.empty(2))
    assert np.allclose(r, [0.09 + math.sin(-1.2) - 2.5, math.exp(-0.36) + 3.6])
    J = np.zeros((2, 2))
    J[code.jac_rows, code.jac_cols] = code.jacobian(0.0, z, p, [], np.empty(len(code.jac_rows)))
    exact = [[0.6, math.cos(-1.2)], [-1.2 * math.exp(-0.36), 0.3 * math.exp(-0.36) - 3]]
    np.testing.assert_allclose(J, exact, rtol=1e-12, atol=0)


def test_chain_rule_through_assignments():
    """z = [u]; a := 2u + 1; b := a^2 (assigned); row: b - u  =>  d/du = 2*a*2 - 1."""
    u, a, b = sp.symbols("u a b")
    code = generate([b - u], [u], [], assignments=[(a, 2 * u + 1), (b, a**2)])
    val = code.jacobian(0.0, np.array([0.7]), np.array([]), [], np.empty(1))
    assert np.isclose(val[0], 4 * (2 * 0.7 + 1) - 1)


def test_relations_become_modes_and_zero_crossings():
    x = sp.Symbol("x")
    exprs, crossings, modes, origin = extract_relations(
        [x, sp.Piecewise((1, x > 2), (0, True))])
    assert crossings == [x - 2] and len(modes) == 1
    assert origin == [1]              # the relation comes from the second expression
    assert not exprs[1].has(sp.StrictGreaterThan)


def test_compiled_jacobian_matches_finite_differences():
    compiled = ac.compile(DoublePendulum())
    z = ac.initial_values(compiled)
    rng = np.random.default_rng(1)
    z = z + 0.01 * rng.standard_normal(z.size)
    zp = rng.standard_normal(z.size)
    for cj in (0.0, 7.0):
        J = compiled.jacobian(0.0, z, zp, cj).toarray()
        fd = np.empty_like(J)
        for j in range(z.size):
            h = 1e-7 * max(1.0, abs(z[j]))
            dz = np.zeros_like(z)
            dz[j] = h
            fd[:, j] = (compiled.residual(0.0, z + dz, zp + cj * dz)
                        - compiled.residual(0.0, z - dz, zp - cj * dz)) / (2 * h)
        assert np.allclose(J, fd, atol=1e-6)


def test_squares_and_reciprocals_in_products_print_with_parentheses():
    """x / a**2 must stay x / (a*a) inside a product (it once printed as x/a*a)."""
    x, a = sp.symbols("x a")
    code = generate([3 * x / a**2 - 1 / (x * a)], [x], [a])
    val = code.residual(0.0, np.array([2.0]), np.array([5.0]), [], np.empty(1))[0]
    # the printer may order the operations as it likes (a few roundings); the misprint
    # x/a*a would give 5.9 instead of 0.14
    assert val == pytest.approx(3 * 2.0 / 25.0 - 1 / 10.0, rel=1e-12)


def test_power_rule_is_finite_where_the_base_vanishes():
    """d/dx u**(3/2) = 3/2 u**(1/2) u': finite (0) at u = 0, where u**r/u would be 0/0."""
    x = sp.Symbol("x")
    code = generate([(x - 1) ** sp.Rational(3, 2)], [x], [])
    val = code.jacobian(0.0, np.array([1.0]), np.array([]), [], np.empty(1))[0]
    assert val == 0.0        # exact: u = 1 - 1 = 0 and sqrt(0) = 0 in IEEE arithmetic
