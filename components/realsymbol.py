"""A variable's or a parameter's symbol: a real sympy Symbol of acausal's own class.

Most equations of a model are sums, differences and products of two of its symbols
(``v = p.v - n.v``, ``0 = p.i + n.i``, ``v = R*i``, ``C*der(v) = i``), and sympy builds
each through its general machinery (``Add``/``Mul``: flatten, sort, the cache look-up),
15-50 us a time, a third of flattening a large model.  For two symbols of different
names, both made here (so with the same assumptions), the result is known: their sum or
product in sympy's canonical order -- the order of ``Basic.compare``, which for two
symbols of one class and one set of assumptions is the order of their names, a symbol
before a product (``-y`` is ``Mul(-1, y)``), a symbol before ``der(...)`` -- built with
sympy's public ``evaluate=False`` constructors.  :class:`~.symbols.Symbol` gives its
instances these three operations; any other operand, or sympy's ``evaluate(False)``,
takes sympy's own.  The class is named ``Symbol``, so sympy orders, hashes and prints its
instances as it does its own symbols; only acausal's symbols have it (no class of
sympy's is changed).  ``ACAUSAL_CHECK_FASTSUBS=1`` compares each result with sympy's.
"""
from __future__ import annotations

from .symbols import Symbol

__all__ = ["real_symbol"]


def real_symbol(name: str) -> Symbol:
    """The symbol of a model's variable or parameter, named by its dotted path: real, as
    Modelica's Real is."""
    return Symbol(name, real=True)
