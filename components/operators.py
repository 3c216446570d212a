"""The operators of equations and the values they take: ``time``, ``der``, ``pre``,
``sample``, ``delay`` and ``noEvent`` (Modelica Language Specification 3.7), and
:func:`sympify_value`, which turns what a user writes into a sympy value.

``der(x)`` is the time derivative (Modelica's ``der``); it may be applied to an expression
(``der(m*v)``), which flattening expands by the chain rule.  ``der`` of a constant (a
number, a parameter) is kept unevaluated here so that flattening can report it: it is
always zero, so writing it is a mistake (the argument was meant to be a variable).

Equations and when-clauses are written with these (:mod:`acausal.components.symbols`),
and so are conditions (:mod:`acausal.components.logic`).  Errors are ``InvalidEquation``.
"""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.core.parameters import global_parameters

from .arrays import elementwise
from .realsymbol import SYMBOLS
from ..errors import InvalidEquation

__all__ = ["time", "der", "pre", "Pre", "Sample", "sample", "delay", "no_event",
           "sympify_value", "has_atom_in"]

time = sp.Symbol("time", real=True)
_ONE_ARGUMENT = sp.FiniteSet(1)     # der's nargs, as Function makes it uniform


class der(sp.Function):
    """Time derivative: der(x) = dx/dt (of an array: the array of the derivatives)."""

    nargs = 1
    time_derivative = True      # realsymbol.Symbol builds ``c*der(x)`` directly

    def __new__(cls, *args, **options):
        if len(args) == 1 and type(args[0]) in SYMBOLS and cls is der and not options \
                and global_parameters.evaluate:
            # der(x) of a symbol, most of a model's der() calls: the object Function's
            # constructor builds (der has no eval, a symbol nothing to evalf), without
            # its argument checks and cache look-up, ~70 us each
            obj = sp.Basic.__new__(cls, args[0])
            obj.nargs = _ONE_ARGUMENT
            return obj
        if len(args) == 1 and isinstance(args[0], np.ndarray) and args[0].ndim:
            return elementwise(cls, args[0])
        return super().__new__(cls, *args, **options)

    def _latex(self, printer):
        return r"\dot{%s}" % printer._print(self.args[0])


def sympify_value(value):
    """Turn numbers, Symbols and objects with ``_sympy_`` (signal ports) into sympy."""
    if isinstance(value, sp.Basic):       # most values: sympify would return them as-is
        return value
    if isinstance(value, np.ndarray):
        if value.ndim == 0:
            return sympify_value(value.item())
        raise _invalid(f"an array of shape {value.shape} is used where one value is "
                       "expected; index it (q[0]), reduce it (q.sum(), a @ b), or write "
                       "ac.Eq between arrays of one shape")
    if isinstance(value, (str, list, tuple, dict, set)):
        # sympify would parse a string into symbols the model does not have
        raise _invalid(f"cannot use {value!r} (a {type(value).__name__}) in an equation; "
                       "use variables, parameters, numbers and acausal functions")
    try:
        return sp.sympify(value, strict=True)
    except sp.SympifyError:
        pass
    if hasattr(value, "_sympy_"):
        return value._sympy_()
    raise _invalid(f"cannot use {value!r} (a {type(value).__name__}) in an equation; "
                   "use variables, parameters, numbers and acausal functions")


_NON_FINITE = (sp.nan, sp.zoo, sp.oo, -sp.oo)
_NON_FINITE_SET = frozenset(_NON_FINITE)


def has_atom_in(expr, atoms: frozenset) -> bool:
    """``expr.has(*atoms)`` for atoms: one walk over the arguments, each atom looked up
    in the set (sympy's ``has`` builds a matcher and an iterator per node)."""
    stack, seen = [expr], set()
    while stack:
        e = stack.pop()
        if e.is_Atom:
            if e in atoms:
                return True
        elif e not in seen:          # a shared subexpression is walked once
            seen.add(e)
            stack.extend(e.args)
    return False


def _invalid(message: str):
    return InvalidEquation(message)


def _text(value) -> str:
    return sp.sstr(value) if isinstance(value, sp.Basic) else repr(value)


class no_event(sp.Function):
    """Modelica's noEvent(expr): relations, abs, min and max inside are evaluated
    directly, not frozen between events (for expressions smooth enough at their kinks)."""

    nargs = 1

    @classmethod
    def eval(cls, arg):
        if isinstance(arg, sp.Expr) and arg.is_Number:
            return arg         # a number makes no event: no_event(0) is 0

    def fdiff(self, argindex=1):
        return sp.Integer(1)   # the identity: d no_event(u) = du


class delay(sp.Function):
    """delay(expr, T): the value expr had T seconds ago, expr(time - T) (Modelica's
    ``delay``, Modelica Language Specification 3.7.2.2); before t0 + T it is expr at
    the start time t0.  T must be a positive expression of parameters (fixed during a
    run).  The runtime keeps a history of expr (:mod:`acausal.runtime.delays`) and the
    integrator's step is limited to T, so the delayed value is always read from the
    past; a discontinuity of expr at t1 reappears at t1 + T as a time event.
    """

    nargs = 2

    @classmethod
    def eval(cls, expr, T):
        logical = (sp.core.relational.Relational, sp.logic.boolalg.BooleanFunction,
                   sp.logic.boolalg.BooleanAtom)
        if not isinstance(expr, sp.Expr) or isinstance(expr, logical):
            raise _invalid(f"delay({_text(expr)}, {_text(T)}): the delayed expression must "
                           "be a real value")
        if not isinstance(T, sp.Expr) or (T.is_number and not (T.is_extended_real
                                                               and T > 0 and T.is_finite)):
            raise _invalid(f"delay({_text(expr)}, {_text(T)}): the delay time must be a "
                           "positive, finite expression of parameters")
        return None

    def fdiff(self, argindex=1):
        raise _invalid(f"{_text(self)} cannot be differentiated (d/dt of a delay is the "
                       "delay of the derivative; write the delay of a variable instead)")


class pre(sp.Function):
    """pre(x): the value of x just before the event (its left limit).  For a discrete
    variable it is the value held before the instant, also while other when-clauses of
    the same instant assign it; elsewhere pre(x) is x."""

    nargs = 1


Pre = pre        # the class (``isinstance(e, Pre)``, ``e.has(Pre)``); ``ac.pre`` is
                 # components.logic.pre


class Sample(sp.logic.boolalg.BooleanFunction):
    """sample(start, period): a clock ticking at start + k period, k = 0, 1, ...
    (Modelica's ``sample``, Language Specification 3.6, sec. 3.7.5).

    Only the whole condition of a ``when``: ``ac.when(ac.sample(0, T), ...)``.  The
    ticks are exact time events (start + k period, computed as that product, so they do
    not drift over many periods); a tick at the start time of the run fires after the
    initial values are found, as the MSL's ``when {sample(...), initial()}`` does.
    ``start`` and ``period`` are expressions of parameters, period > 0.
    """

    nargs = 2

    @classmethod
    def eval(cls, start, period):
        return None                 # never evaluated: the runtime keeps the clock

    @property
    def start(self):
        return self.args[0]

    @property
    def period(self):
        return self.args[1]

    def _sympystr(self, printer):
        return f"sample({printer._print(self.start)}, {printer._print(self.period)})"


def sample(start, period) -> Sample:
    """The clock ``sample(start, period)`` (see :class:`Sample`), checked."""
    s, T = sympify_value(start), sympify_value(period)
    for what, v in (("start", s), ("period", T)):
        if not isinstance(v, sp.Expr) or v.has(*_NON_FINITE) or v.has(time):
            raise _invalid(f"sample(start, period): {what} = {_text(v)} must be a finite "
                           "expression of parameters")
    if T.is_number and not T > 0:
        raise _invalid(f"sample(start, period): the period {_text(T)} must be positive")
    return Sample(s, T)
