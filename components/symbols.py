"""The symbolic vocabulary of equations: Eq, if-expressions, when-clauses, and the
operators (time, der, pre, sample, delay, noEvent: :mod:`acausal.components.operators`).

Variables and parameters are sympy Symbols named by their dotted path, so an equation a
user writes is an ordinary sympy expression and prints in the user's names.

An equation is checked when it is written: both sides must be values (a relation such
as ``x > 1`` is not one: use ``if_else``), finite, and the equation must involve
something that can vary (``Eq(1, 1)`` and ``Eq(x, x)`` determine nothing, ``Eq(1, 2)``
never holds).  Errors are ``InvalidEquation``; flattening adds the component path.
"""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy import S

from . import logic as _logic
from .arrays import array_equations
from .ifexpr import unfolded_condition
from .operators import (_NON_FINITE, _NON_FINITE_SET, Pre, Sample, _invalid, _text, delay, der,
                        has_atom_in, no_event, sample, sympify_value, time)
from .printing import text
from .realsymbol import SYMBOLS

__all__ = ["time", "der", "Eq", "Equation", "if_else", "sign", "no_event", "delay",
           "sympify_value", "When", "when", "reinit", "Pre", "text", "sample", "Sample",
           "assign", "Assign"]


class Equation:
    """lhs = rhs, with where it was written.

    ``origin`` (component path) and ``origin_class`` are filled in when the component that
    returned the equation is flattened; ``label`` is an optional user name.
    """

    __slots__ = ("lhs", "rhs", "origin", "origin_class", "label", "index", "_text")

    def __init__(self, lhs, rhs=0, label: str | None = None):
        self.lhs = _side(lhs, lhs, rhs)
        self.rhs = _side(rhs, lhs, rhs)
        if _logic._logical_side(lhs) or _logic._logical_side(rhs):
            _logic._check_boolean_equation(self.lhs, self.rhs, lhs, rhs)
        _check_not_trivial(self.lhs, self.rhs)
        if label is not None and not isinstance(label, str):
            raise _invalid(f"the label of ac.Eq({_text(lhs)}, {_text(rhs)}) must be a "
                           f"string, not {label!r}")
        self.label = label
        self.origin = None
        self.origin_class = None
        self.index = None
        self._text = None

    @property
    def residual(self) -> sp.Expr:
        return self.lhs - self.rhs

    @property
    def text(self) -> str:
        """``lhs = rhs`` as written, printed when first asked for (printing is slow)."""
        if self._text is None:
            self._text = f"{text(self.lhs)} = {text(self.rhs)}"
        return self._text

    def __repr__(self):
        return self.text


def Eq(lhs, rhs=0, label: str | None = None) -> Equation:
    """The equation ``lhs = rhs`` (one notation for the whole project).  Between arrays
    of one shape: a list of equations, one per element (see components.arrays)."""
    if isinstance(lhs, np.ndarray) or isinstance(rhs, np.ndarray):
        return array_equations(lhs, rhs, label, Equation)
    return Equation(lhs, rhs, label)


_PLAIN_NODES = (sp.Add, sp.Mul, sp.Pow)


def _has_non_finite(expr) -> bool:
    return has_atom_in(expr, _NON_FINITE_SET)


def _may_vary(expr) -> bool:
    """``expr.free_symbols or expr.has(der)``, stopping at the first symbol found (sums,
    products and powers walked here; any other node answers for itself, as it may bind
    symbols)."""
    stack = [expr]
    while stack:
        e = stack.pop()
        if e.is_Symbol or isinstance(e, der):
            return True
        if e.is_Atom:
            continue
        if type(e) in _PLAIN_NODES:
            stack.extend(e.args)
        elif e.free_symbols or e.has(der):
            return True
    return False


def _side(value, lhs, rhs) -> sp.Expr:
    """One side of an equation: a finite value; a condition (the value of a Boolean
    variable, ``ac.Eq(self.y, self.u > 1)``) is its value 1 or 0."""
    if type(value) in SYMBOLS:          # a variable: a value, finite
        return value
    # Eq(0, ...), written for every balance, without sympify
    expr = S.Zero if type(value) is int and value == 0 else sympify_value(value)
    if isinstance(expr, Sample):        # y = sample(start, period): true at the ticks
        return sp.Piecewise((S.One, expr), (S.Zero, True))
    if _logic.is_logical(expr):
        return _logic.boolean_value(expr)
    if not isinstance(expr, sp.Expr):
        raise _invalid(f"ac.Eq({_text(lhs)}, {_text(rhs)}): {_text(expr)} is a relation or "
                       "a logical value, not a value (ac.if_else(condition, a, b) chooses "
                       "between values)")
    if _has_non_finite(expr):
        raise _invalid(f"ac.Eq({_text(lhs)}, {_text(rhs)}) contains a value that is not a "
                       f"finite number ({_text(expr)})")
    return expr


def _check_not_trivial(lhs: sp.Expr, rhs: sp.Expr) -> None:
    """Eq(1, 1) and Eq(x, x) determine nothing; Eq(1, 2) never holds.  (Cheap tests only:
    flattening rejects any equation whose residual involves no variable.)"""
    constant = not (_may_vary(lhs) or _may_vary(rhs))
    if lhs == rhs or (constant and lhs - rhs == 0):
        raise _invalid(f"ac.Eq({_text(lhs)}, {_text(rhs)}) holds whatever the variables "
                       "are (both sides are the same): it determines nothing")
    if constant:
        raise _invalid(f"ac.Eq({_text(lhs)}, {_text(rhs)}) can never hold: it involves no "
                       "variable and its sides differ")


def if_else(condition, then, otherwise):
    """``then`` where ``condition`` holds, else ``otherwise`` (Modelica if-expression).

    The relation in ``condition`` becomes a zero-crossing function: it is frozen while
    the integrator steps and switched only at located events.
    """
    cond = _condition(condition, "if_else()")
    # if-expressions inside the condition stay whole (components/ifexpr.py)
    cond = unfolded_condition(cond)
    return sp.Piecewise((_branch(then), cond), (_branch(otherwise), True))


def _branch(value):
    """A branch of if_else: a value; a condition as its value 1 or 0 (a Boolean)."""
    expr = sympify_value(value)
    return _logic.boolean_value(expr) if _logic.is_logical(expr) else expr


def _condition(condition, where: str):
    """A relation, a Boolean variable or parameter, or a logical combination of them (a
    Python bool is one too), in the form :func:`as_condition` gives it."""
    try:
        return _logic.as_condition(condition)
    except _logic._NotACondition as err:
        raise _invalid(f"{where} takes a condition such as x > 0 (a relation), not "
                       f"{_text(condition)}{err.why or ' (nor a Boolean)'}") from None


def sign(x):
    """sign(x) as an event-generating expression: sympy's ``sign``, whose two relations
    x > 0 and x < 0 the compiler makes events (an if-expression would fold into every
    condition it appears in: components/ifexpr.py)."""
    return sp.sign(sympify_value(x))


class Reinit:
    """reinit(x, expr): at the event, the state x restarts from expr."""

    __slots__ = ("variable", "value")

    def __init__(self, variable, value):
        self.variable = sympify_value(variable)
        self.value = sympify_value(value)
        if not isinstance(self.variable, sp.Symbol):
            raise _invalid(f"reinit() takes a variable, got {_text(variable)}")
        if not isinstance(self.value, sp.Expr) or self.value.has(*_NON_FINITE):
            raise _invalid(f"reinit({self.variable}, ...) takes a finite value, "
                           f"got {_text(self.value)}")

    def __repr__(self):
        return f"reinit({self.variable}, {self.value})"


def reinit(variable, value) -> Reinit:
    """Modelica's reinit: used inside ``when``."""
    return Reinit(variable, value)


class Assign:
    """assign(y, expr): at the instant the when-clause fires, the discrete variable y
    takes the value of expr (Modelica's when-equation ``y = expr``)."""

    __slots__ = ("variable", "value")

    def __init__(self, variable, value):
        self.variable = sympify_value(variable)
        self.value = sympify_value(value)
        if _logic.is_logical(self.value):          # the value of a Boolean: 1 or 0
            self.value = _logic.boolean_value(self.value)
        if not isinstance(self.variable, sp.Symbol):
            raise _invalid(f"assign() takes a variable, got {_text(variable)}")
        if not isinstance(self.value, sp.Expr) or self.value.has(*_NON_FINITE):
            raise _invalid(f"assign({self.variable}, ...) takes a finite value, "
                           f"got {_text(self.value)}")

    def __repr__(self):
        return f"{self.variable} := {self.value}"


def assign(variable, value) -> Assign:
    """The when-equation ``variable = value``: ``ac.when(ac.sample(0, T),
    ac.assign(self.y, self.u))``.  ``variable`` must be declared discrete
    (``ac.Variable(discrete=True)``, or a port's ``signal={"discrete": True}``)."""
    return Assign(variable, value)


class When:
    """when condition: actions, firing when the condition becomes true (Modelica 8.3.5).

    The condition is a relation (``self.h < 0``), an ``sp.Or``/``sp.And`` of relations,
    or a clock ``sample(start, period)``; the actions are ``reinit(x, expr)`` of states
    and ``assign(y, expr)`` of discrete variables.  Reinit values are evaluated with the
    values just before the event; an assignment reads the discrete variables assigned at
    the same instant after their assignment (the clauses are sorted by data flow) and
    ``pre(y)`` for the value before it.
    """

    __slots__ = ("condition", "actions", "origin", "origin_class", "equation", "pulse")

    def __init__(self, condition, *actions):
        # the text of the equation of a Boolean or Integer variable that this clause
        # stands for (evaluated at every event: compiler/sampled.py), else None
        self.equation = None
        # y = sample(start, period): the clause sets y at each tick, and y is false
        # again once the instant is over
        self.pulse = False
        if isinstance(condition, (list, tuple)):
            # Modelica's when {c1, c2, ...}: fires when any of them becomes true
            if not condition:
                raise _invalid("when([]) needs at least one condition")
            conds = [_condition(c, "when()") for c in condition]
            condition = conds[0] if len(conds) == 1 else sp.Tuple(*conds)
        self.condition = condition if isinstance(condition, (Sample, sp.Tuple)) else \
            _condition(condition, "when()")
        if not isinstance(self.condition, Sample) and self.condition.has(Sample):
            raise _invalid(f"when({_text(condition)}): sample() must be the whole "
                           "condition of a when-clause")
        self.actions = list(actions)
        for a in self.actions:
            if not isinstance(a, (Reinit, Assign)):
                raise _invalid(f"when() takes reinit(...) and assign(...) actions, got {a!r}")
        self.origin = None
        self.origin_class = None

    @property
    def conditions(self) -> list:
        """The conditions, each firing the clause when it becomes true (one, or those
        of ``when([c1, c2, ...])``)."""
        if isinstance(self.condition, sp.Tuple):
            return list(self.condition.args)
        return [self.condition]

    @property
    def clock(self):
        """The ``sample(start, period)`` of a clocked clause, else None."""
        return self.condition if isinstance(self.condition, Sample) else None

    def __repr__(self):
        return f"when {self.condition}: {self.actions}"


def when(condition, *actions) -> When:
    """``ac.when(self.h < 0, ac.reinit(self.v, -e*ac.pre(self.v)))``, or a sampled
    assignment ``ac.when(ac.sample(0, T), ac.assign(self.y, self.u))``.  A list of
    conditions, ``ac.when([c1, c2], ...)``, fires when any of them becomes true
    (Modelica's ``when {c1, c2}``)."""
    return When(condition, *actions)

