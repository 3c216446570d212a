"""The mathematical functions a model's equations use, so that models never import sympy.

``ac.sqrt``, ``ac.exp``, ``ac.log``, ``ac.log10``, ``ac.sin``, ``ac.cos``, ``ac.tan``,
``ac.asin``, ``ac.acos``, ``ac.atan``, ``ac.atan2``, ``ac.sinh``, ``ac.cosh``,
``ac.tanh``, ``ac.abs``, ``ac.min``, ``ac.max`` and the constant ``ac.pi``: the elementary
functions of Modelica (specification 3.7.3, "Built-in mathematical functions") and its
event-generating ``abs``, ``min`` and ``max`` (3.7.1)::

    ac.Eq(self.q, self.Cd * self.A * ac.sqrt(2 / self.rho * ac.abs(self.dp)))

Each is a thin wrapper over sympy's function of the same meaning, so an expression built
with them is exactly what the compiler differentiates and prints; constants stay exact
(``ac.sqrt(2)`` is the exact atom sqrt(2), which the compiler's exact rank checks rely
on).  ``abs``, ``min`` and ``max`` return plain numbers for plain numbers (they shadow the
builtins in a model module that imports them), and their kinks become events in a model,
as Modelica's do.  Applied to an array (``ac.sin(self.q)``) the functions act element by
element, as numpy's do.  This module loads sympy only when a function is first called with
a symbol, or when ``pi`` is read.
"""
from __future__ import annotations

import builtins

from .components.declarations import is_symbolic

__all__ = ["sqrt", "exp", "log", "log10", "sin", "cos", "tan", "asin", "acos", "atan",
           "atan2", "sinh", "cosh", "tanh", "abs", "min", "max", "pi"]


def _sympy():
    import sympy
    return sympy


def _elementwise(f):
    """``f`` applied element by element to arrays (``ac.sin(self.q)``), as numpy's
    functions are; scalars pass through unchanged."""
    import functools

    @functools.wraps(f)
    def wrapper(*args):
        if any(getattr(a, "ndim", 0) for a in args):
            import numpy as np
            return np.frompyfunc(f, len(args), 1)(*args)
        return f(*args)
    return wrapper


@_elementwise
def sqrt(x):
    """Square root, sqrt(x) (x >= 0; a model that takes it of a negative value stops
    with the equation named)."""
    return _sympy().sqrt(x)


@_elementwise
def exp(x):
    """Exponential, e**x."""
    return _sympy().exp(x)


@_elementwise
def log(x):
    """Natural logarithm, ln(x) (x > 0)."""
    return _sympy().log(x)


@_elementwise
def log10(x):
    """Decimal logarithm, log(x) / log(10) (x > 0)."""
    return _sympy().log(x, 10)


@_elementwise
def sin(x):
    """Sine of x [rad]."""
    return _sympy().sin(x)


@_elementwise
def cos(x):
    """Cosine of x [rad]."""
    return _sympy().cos(x)


@_elementwise
def tan(x):
    """Tangent of x [rad]."""
    return _sympy().tan(x)


@_elementwise
def asin(x):
    """Inverse sine, in [-pi/2, pi/2] (-1 <= x <= 1)."""
    return _sympy().asin(x)


@_elementwise
def acos(x):
    """Inverse cosine, in [0, pi] (-1 <= x <= 1)."""
    return _sympy().acos(x)


@_elementwise
def atan(x):
    """Inverse tangent, in (-pi/2, pi/2)."""
    return _sympy().atan(x)


@_elementwise
def atan2(y, x):
    """The angle of the point (x, y), in (-pi, pi] (Modelica's ``atan2(u1, u2)``: y
    first)."""
    return _sympy().atan2(y, x)


@_elementwise
def sinh(x):
    """Hyperbolic sine."""
    return _sympy().sinh(x)


@_elementwise
def cosh(x):
    """Hyperbolic cosine."""
    return _sympy().cosh(x)


@_elementwise
def tanh(x):
    """Hyperbolic tangent."""
    return _sympy().tanh(x)


def abs(x):  # noqa: A001 (Modelica's name, shadowing the builtin on purpose)
    """|x|: sympy's ``Abs`` for an expression (its kink at 0 is an event in a model),
    the builtin ``abs`` for a number or an array."""
    if is_symbolic(x):
        return _sympy().Abs(x)
    return builtins.abs(x)


def _extremum(name: str, args, kwargs):
    if len(args) == 1 and not is_symbolic(args[0]):
        values = list(args[0])          # min(iterable), as the builtin takes it
    else:
        values = list(args)
    if any(is_symbolic(v) for v in values):
        if kwargs:
            raise TypeError(f"{name}() of expressions takes no keyword arguments, "
                            f"got {sorted(kwargs)}")
        sympy = _sympy()
        return (sympy.Min if name == "min" else sympy.Max)(*values)
    if len(args) == 1:
        return getattr(builtins, name)(values, **kwargs)
    return getattr(builtins, name)(*args, **kwargs)


def min(*args, **kwargs):  # noqa: A001
    """The smallest argument: ``min(a, b, ...)`` or ``min(iterable)``.  With an
    expression among them sympy's ``Min`` (each switch between arguments is an event in a
    model), else the builtin ``min`` (``key`` and ``default`` accepted)."""
    return _extremum("min", args, kwargs)


def max(*args, **kwargs):  # noqa: A001
    """The largest argument: ``max(a, b, ...)`` or ``max(iterable)``; see ``min``."""
    return _extremum("max", args, kwargs)


def __getattr__(name: str):
    # pi is sympy's exact constant; reading it is what loads sympy (PEP 562)
    if name == "pi":
        return _sympy().pi
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
