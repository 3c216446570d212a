"""A variable's or a parameter's symbol: a real sympy Symbol of acausal's own class.

Most equations of a model are sums, differences and products of two of its symbols
(``v = p.v - n.v``, ``0 = p.i + n.i``, ``v = R*i``, ``C*der(v) = i``), and sympy builds
each through its general machinery (``Add``/``Mul``: flatten, sort, the cache look-up),
15-50 us a time, a third of flattening a large model.  For two symbols of different
names, both made here (so with the same assumptions), the result is known: their sum or
product in sympy's canonical order -- the order of ``Basic.compare``, which for two
symbols of one class name and one set of assumptions is the order of their names, a
symbol before a product (``-y`` is ``Mul(-1, y)``), a symbol before ``der(...)`` -- built
with sympy's public ``evaluate=False`` constructors.  :class:`Symbol` gives its instances
these three operations; any other operand, or sympy's ``evaluate(False)``, takes sympy's
own.  No class of sympy's is changed: only acausal's symbols have them.

The class is named ``Symbol``, so sympy orders, hashes and prints its instances as its
own symbols; and it is equal to sympy's ``Symbol(name, real=True)`` of the same name (a
user substitutes into a model's expressions with symbols of their own): ``==`` both ways,
one hash, and ``subs`` finds it.  ``ACAUSAL_CHECK_FASTSUBS=1`` compares each result of
the three operations with sympy's arithmetic.
"""
from __future__ import annotations

import os

import sympy as sp
from sympy import S
from sympy.core.parameters import global_parameters

__all__ = ["Symbol", "SYMBOLS", "real_symbol"]

_Basic_eq = sp.Basic.__eq__


class Symbol(sp.Symbol):
    """A variable's or parameter's symbol, always real; the sum, difference and product
    of two of them (and a product with der() of one) built directly in sympy's canonical
    form."""

    __slots__ = ("_negative",)

    def __new__(cls, name, **assumptions):
        # always real, so that every one has the same assumptions (and sorts by name)
        return super().__new__(cls, name, **{**assumptions, "real": True})

    def negative(self):
        """``-self`` as sympy builds it (``Mul(-1, self)``), made once per symbol: the
        same node is a term of every sum the symbol is subtracted in (its element's
        equation, its connections', where an alias stands for it)."""
        try:
            return self._negative
        except AttributeError:
            out = self._negative = sp.Mul(S.NegativeOne, self, evaluate=False)
            return out

    def __eq__(self, other):
        # sympy's equality asks for one type: a symbol of sympy's own class with the
        # same name and assumptions is this one (Python asks this method first for
        # ``plain == self`` too, the class being a subclass)
        if self is other:
            return True
        kind = type(other)
        if kind is Symbol or kind is sp.Symbol:
            return self.name == other.name and self._assumptions0 == other._assumptions0
        return _Basic_eq(self, other)

    __hash__ = sp.Symbol.__hash__        # the class's name and the name: as sympy's

    def _eval_subs(self, old, new):
        # ``subs`` replaces what is the same object class and all (Basic.is_same); an
        # equal symbol of sympy's class is replaced too
        if type(old) in SYMBOLS and self == old:
            return new
        return super()._eval_subs(old, new)

    def __add__(self, other):
        if type(other) is not Symbol or other.name == self.name \
                or not global_parameters.evaluate:
            return super().__add__(other)
        args = (self, other) if self.name < other.name else (other, self)
        return _checked(sp.Add(*args, evaluate=False), "__add__", self, other)

    def __sub__(self, other):
        if type(other) is not Symbol or other.name == self.name \
                or not global_parameters.evaluate:
            return super().__sub__(other)
        # a symbol sorts before a product: -other, Mul(-1, other), is the second term
        out = sp.Add(self, other.negative(), evaluate=False)
        return _checked(out, "__sub__", self, other)

    def __mul__(self, other):
        if not global_parameters.evaluate:
            return super().__mul__(other)
        kind = type(other)
        if kind is Symbol and other.name != self.name:
            args = (self, other) if self.name < other.name else (other, self)
        elif getattr(kind, "time_derivative", False) and type(other.args[0]) is Symbol:
            args = (self, other)           # a symbol sorts before der(), a Function
        else:
            return super().__mul__(other)
        return _checked(sp.Mul(*args, evaluate=False), "__mul__", self, other)


#: a model's symbols and sympy's own (time is one): what reads as "a symbol"
SYMBOLS = frozenset((Symbol, sp.Symbol))
_CHECK = os.environ.get("ACAUSAL_CHECK_FASTSUBS", "") not in ("", "0")


def _checked(out, op, a, b):
    if _CHECK:
        ref = getattr(sp.Expr, op)(a, b)
        if out != ref or sp.srepr(out) != sp.srepr(ref):
            raise AssertionError(f"{op}({a}, {b}) gave {out}, sympy {ref}")
    return out


def real_symbol(name: str) -> Symbol:
    """The symbol of a model's variable or parameter, named by its dotted path: real, as
    Modelica's Real is."""
    return Symbol(name, real=True)
