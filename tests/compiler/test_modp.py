"""The rank certificate mod p (compiler/index/modp.py) on the matrices of networks.

The node-admittance matrix of a connected resistor network (a weighted graph
Laplacian) is singular -- its rows sum to zero -- and becomes regular once one node is
grounded (its row and column removed): then it is positive definite.  Eliminated with
the fewest-non-zeros pivots, a random network's matrix fills in towards the end, where
the elimination moves into a numpy array; the result must be what the theory says,
and what the elimination on dictionaries alone gives.
"""
import random
from fractions import Fraction

import pytest

from acausal.compiler.index import modp


def _laplacian(n: int, extra_edges: int, seed: int) -> dict:
    """{node: {node: Fraction}} of a connected random network of n nodes: a random
    spanning tree plus ``extra_edges`` random branches, conductances 1/1 .. 1/7."""
    rng = random.Random(seed)
    rows = {i: {} for i in range(n)}

    def branch(a, b):
        g = Fraction(1, rng.randint(1, 7))
        for i, j, v in ((a, a, g), (b, b, g), (a, b, -g), (b, a, -g)):
            rows[i][j] = rows[i].get(j, 0) + v

    for k in range(1, n):
        branch(k, rng.randrange(k))
    for _ in range(extra_edges):
        a, b = rng.sample(range(n), 2)
        branch(a, b)
    return rows


@pytest.mark.parametrize("n, extra", [(600, 300), (1000, 600)])
def test_a_grounded_network_is_regular_and_a_floating_one_singular(n, extra, monkeypatch):
    rows = _laplacian(n, extra, seed=n)
    grounded = {i: {j: v for j, v in r.items() if j != 0} for i, r in rows.items() if i != 0}
    switched = []
    dense = modp._dense_rank

    def spy(a, *args):
        switched.append(len(a))
        return dense(a, *args)

    monkeypatch.setattr(modp, "_dense_rank", spy)
    assert modp.full_row_rank_mod_p(grounded)
    assert not modp.full_row_rank_mod_p(rows)          # every row sum is zero
    assert len(switched) == 2 and all(k > 50 for k in switched)   # the array took over
    # the dictionaries alone agree
    monkeypatch.setattr(modp, "DENSE_ROWS", 0)
    assert modp.full_row_rank_mod_p(grounded)
    assert not modp.full_row_rank_mod_p(rows)
