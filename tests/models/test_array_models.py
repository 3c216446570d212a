"""Systems written with arrays against the same systems written without
(models in ``array_models.py``).

* The mass-spring chain in array form equals the chain of library ``Mass`` and
  ``Spring`` components, and both equal expm(A t) x0 of the chain's first-order form.
* The n-link pendulum in Cartesian coordinates (000 section 3.4, index 3) in array form
  equals the same equations written with one declaration per scalar, and the library's
  ``PointMassChain`` assembled from ``Rod`` and ``PointMass``; the array form takes
  under half the lines of code of the scalar form.
"""
import ast
import inspect
import textwrap

import numpy as np
import pytest
from scipy.linalg import expm

import acausal as ac
from acausal.library.multibody.examples.pendulums import PointMassChain

from .array_models import (ArrayChain, ComponentChain, RodChain, RodChain3Scalars,
                           chain_masses, chain_start, chain_stiffnesses)

N = 12
T_END = 0.5


def _chain_expm(n, t):
    """x = (s, v), x' = A x with m s'' = K s, K tridiagonal from the springs."""
    m, c = chain_masses(n), chain_stiffnesses(n)
    K = np.zeros((n, n))
    for i in range(n):                 # spring i joins mass i-1 (the wall for i = 0) and i
        K[i, i] -= c[i]
        if i > 0:
            K[i, i - 1] += c[i]
            K[i - 1, i - 1] -= c[i]
            K[i - 1, i] += c[i]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [K / m[:, None], np.zeros((n, n))]])
    x0 = np.concatenate([chain_start(n), np.zeros(n)])
    return np.array([expm(A * tk) @ x0 for tk in t])[:, :n]


@pytest.fixture(scope="module")
def chains():
    arrays = ac.simulate(ArrayChain(N, m=chain_masses(N), c=chain_stiffnesses(N),
                                    s={"start": chain_start(N)}),
                         t_end=T_END, rtol=1e-10, n_points=101, raise_on_failure=True)
    parts = ac.simulate(ComponentChain(N), t_end=T_END, rtol=1e-10, n_points=101,
                        raise_on_failure=True)
    return arrays, parts


def test_array_chain_equals_the_chain_of_library_components(chains):
    arrays, parts = chains
    s_parts = np.column_stack([parts[f"masses[{i}].s"] for i in range(N)])
    assert arrays["s"].shape == (101, N)
    assert np.max(np.abs(arrays["s"] - s_parts)) / np.max(np.abs(s_parts)) < 1e-9


def test_array_chain_matches_the_matrix_exponential(chains):
    arrays, _ = chains
    exact = _chain_expm(N, arrays.t)
    assert np.max(np.abs(arrays["s"] - exact)) / np.max(np.abs(exact)) < 1e-7


# -- the n-link pendulum -------------------------------------------------------------------
X0 = (1.0, 2.0, 3.0)                   # straight out along +x, at rest
AT_REST = {"start": 0.0, "fixed": True}


@pytest.fixture(scope="module")
def pendulums():
    kw = dict(t_end=1.0, rtol=1e-9, n_points=101, raise_on_failure=True)
    arrays = ac.simulate(RodChain(3, x={"start": list(X0)}, y=AT_REST, vy=AT_REST), **kw)
    mods = {f"x{i + 1}": {"start": x} for i, x in enumerate(X0)}
    mods.update({f"{v}{i}": AT_REST for v in ("y", "vy") for i in (1, 2, 3)})
    scalars = ac.simulate(RodChain3Scalars(**mods), **kw)
    library = ac.simulate(PointMassChain(3), **kw)
    return arrays, scalars, library


def test_array_pendulum_equals_its_scalar_form(pendulums):
    arrays, scalars, _ = pendulums
    for v in ("x", "y", "lam"):
        scalar = np.column_stack([scalars[f"{v}{i}"] for i in (1, 2, 3)])
        assert np.max(np.abs(arrays[v] - scalar)) <= 1e-9 * np.max(np.abs(scalar))


def test_array_pendulum_equals_the_library_assembly(pendulums):
    arrays, _, library = pendulums
    for v in ("x", "y"):
        parts = np.column_stack([library[f"masses[{i}].{v}"] for i in range(3)])
        # rtol 1e-9 over 1 s of a chain that has fallen through ~1 m: agreement to 1e-7 m
        assert np.max(np.abs(arrays[v] - parts)) < 1e-7 * 3.0
    r = np.hypot(np.diff(arrays["x"], prepend=0.0), np.diff(arrays["y"], prepend=0.0))
    assert np.max(np.abs(r - 1.0)) < 1e-9        # the rods keep their length


def _code_lines(cls) -> int:
    """Lines of code of a class: neither blank lines nor docstrings."""
    tree = ast.parse(textwrap.dedent(inspect.getsource(cls)))
    doc = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)) and ast.get_docstring(node):
            first = node.body[0]
            doc.update(range(first.lineno, first.end_lineno + 1))
    source = textwrap.dedent(inspect.getsource(cls)).splitlines()
    return sum(1 for k, line in enumerate(source, 1) if line.strip() and k not in doc)


def test_array_form_takes_under_half_the_lines():
    assert 2 * _code_lines(RodChain) < _code_lines(RodChain3Scalars)
