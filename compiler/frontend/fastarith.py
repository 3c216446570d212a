"""``x + y``, ``x - y`` and ``x * y`` of two symbols in sympy's canonical form, while the
components' ``equations()`` run during flattening.

Most equations of a model are written with such operations on its variables and
parameters (``v = p.v - n.v``, ``0 = p.i + n.i``, ``v = R*i``), and each goes through
sympy's general machinery: ``Add``/``Mul`` with its cache look-up, ``flatten`` and the
sort by ``Basic.compare``, 15-50 us a time, a third of flattening a large model.  For
two commutative symbols of different names the result is known: the sum or product
of the two (the second negated, ``Mul(-1, y)``, for a difference), in sympy's order
(:func:`~acausal.compiler.algebra.substitution.sort_args`); so is a symbol times ``der(...)``.
:func:`symbol_arithmetic` installs these as ``Symbol``'s own ``__add__``/``__sub__``/
``__mul__`` for the duration of a ``with`` block; any other operand (a number, an expression, a symbol of the same name,
a non-commutative one), sympy's ``evaluate(False)``, or a constructor postprocessor
registered for these classes takes sympy's own method, so every result is the
expression sympy builds.  ``ACAUSAL_CHECK_FASTSUBS=1`` compares each result with it.
"""
from __future__ import annotations

import contextlib
import threading

import sympy as sp
from sympy.core.basic import Basic
from sympy.core.expr import Expr
from sympy.core.parameters import global_parameters

from ...components.symbols import der
from ..algebra import substitution as fastsubs

__all__ = ["symbol_arithmetic"]

_Symbol, _Add, _Mul = sp.Symbol, sp.Add, sp.Mul
_MINUS = sp.S.NegativeOne
_OPS = ("__add__", "__sub__", "__mul__")
_lock = threading.Lock()
_depth = 0


def _pair(a, b) -> bool:
    """Two symbols whose sum and product sympy builds without combining anything."""
    return (type(b) is _Symbol and type(a) is _Symbol and a.name != b.name
            and a.is_commutative and b.is_commutative and global_parameters.evaluate)


def _derivative_factor(a, b) -> bool:
    """A symbol times ``der(...)`` (``C*der(v)``): two factors of different bases, which
    sympy's Mul puts in its order and leaves as they are."""
    if type(b) is not der or type(a) is not _Symbol or not a.is_commutative:
        return False
    x = b.args[0]      # der(x) of a symbol is as commutative as x (no query of der's own)
    return (x.is_commutative if type(x) is _Symbol else b.is_commutative) \
        and global_parameters.evaluate


def _checked(out, op, a, b):
    if fastsubs._CHECK:
        ref = getattr(Expr, op)(a, b)
        if out != ref or sp.srepr(out) != sp.srepr(ref):
            raise AssertionError(f"{op}({a}, {b}) gave {out}, sympy {ref}")
    return out


def _add(self, other):
    if not _pair(self, other):
        return Expr.__add__(self, other)
    args = [self, other]
    fastsubs.sort_args(args)
    return _checked(_Add._from_args(args, True), "__add__", self, other)


def _sub(self, other):
    if not _pair(self, other):
        return Expr.__sub__(self, other)
    args = [self, fastsubs.negated(other)]
    fastsubs.sort_args(args)
    return _checked(_Add._from_args(args, True), "__sub__", self, other)


def _mul(self, other):
    if _pair(self, other):
        args = [self, other]
        fastsubs.sort_args(args)
    elif _derivative_factor(self, other):
        # sympy orders a Symbol before an application of a function class it does not
        # list (Basic.compare by ordering_of_classes), der among them
        args = [self, other]
    else:
        return Expr.__mul__(self, other)
    return _checked(_Mul._from_args(args, True), "__mul__", self, other)


def _postprocessed() -> bool:
    """Whether sympy would run a constructor postprocessor on these sums or products."""
    mapping = Basic._constructor_postprocessor_mapping
    return any(c in mapping for k in (_Symbol, _Mul) for c in k.__mro__)


@contextlib.contextmanager
def symbol_arithmetic():
    """The fast two-symbol operations installed on ``Symbol`` inside the block (nested
    blocks and threads share one installation, removed when the last block ends)."""
    global _depth
    with _lock:
        if _depth == 0 and not _postprocessed() \
                and not any(op in _Symbol.__dict__ for op in _OPS):
            _Symbol.__add__, _Symbol.__sub__, _Symbol.__mul__ = _add, _sub, _mul
        _depth += 1
    try:
        yield
    finally:
        with _lock:
            _depth -= 1
            if _depth == 0 and _Symbol.__dict__.get("__add__") is _add:
                del _Symbol.__add__, _Symbol.__sub__, _Symbol.__mul__
