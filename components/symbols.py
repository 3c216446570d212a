"""The symbolic vocabulary of equations: time, der(), Eq, and discontinuous expressions.

Variables and parameters are sympy Symbols named by their dotted path, so an equation a
user writes is an ordinary sympy expression and prints in the user's names.
``der(x)`` is the time derivative (Modelica's ``der``); it may be applied to an expression
(``der(m*v)``), which flattening expands by the chain rule.
"""
from __future__ import annotations

import sympy as sp

__all__ = ["time", "der", "Eq", "Equation", "if_else", "sign", "no_event", "sympify_value",
           "When", "when", "reinit", "pre"]

time = sp.Symbol("time", real=True)


class der(sp.Function):
    """Time derivative: der(x) = dx/dt."""

    nargs = 1

    @classmethod
    def eval(cls, arg):
        arg = sp.sympify(arg)
        if arg.is_number:
            return sp.Integer(0)
        return None

    def _latex(self, printer):
        return r"\dot{%s}" % printer._print(self.args[0])


class Equation:
    """lhs = rhs, with where it was written.

    ``origin`` (component path) and ``origin_class`` are filled in when the component that
    returned the equation is flattened; ``label`` is an optional user name.
    """

    __slots__ = ("lhs", "rhs", "origin", "origin_class", "label", "index")

    def __init__(self, lhs, rhs=0, label: str | None = None):
        self.lhs = sympify_value(lhs)
        self.rhs = sympify_value(rhs)
        self.label = label
        self.origin = None
        self.origin_class = None
        self.index = None

    @property
    def residual(self) -> sp.Expr:
        return self.lhs - self.rhs

    def __repr__(self):
        return f"{self.lhs} = {self.rhs}"


def Eq(lhs, rhs=0, label: str | None = None) -> Equation:
    """The equation ``lhs = rhs`` (one notation for the whole project)."""
    return Equation(lhs, rhs, label)


def sympify_value(value):
    """Turn numbers, Symbols and objects with ``_sympy_`` (signal ports) into sympy."""
    try:
        return sp.sympify(value, strict=True)
    except sp.SympifyError:
        pass
    if hasattr(value, "_sympy_"):
        return value._sympy_()
    raise TypeError(f"cannot use {value!r} (a {type(value).__name__}) in an equation; "
                    "use variables, parameters, numbers and acausal functions")


def if_else(condition, then, otherwise):
    """``then`` where ``condition`` holds, else ``otherwise`` (Modelica if-expression).

    The relation in ``condition`` becomes a zero-crossing function: it is frozen while
    the integrator steps and switched only at located events.
    """
    cond = condition if isinstance(condition, sp.Basic) else sp.sympify(condition)
    return sp.Piecewise((sympify_value(then), cond), (sympify_value(otherwise), True))


def sign(x):
    """sign(x) as an event-generating expression."""
    x = sympify_value(x)
    return sp.Piecewise((1, x > 0), (-1, x < 0), (0, True))


class no_event(sp.Function):
    """Modelica's noEvent(expr): relations, abs, min and max inside are evaluated
    directly, not frozen between events (for expressions smooth enough at their kinks)."""

    nargs = 1

    def fdiff(self, argindex=1):
        return sp.Integer(1)   # the identity: d no_event(u) = du


class pre(sp.Function):
    """pre(x): the value of x just before the event (inside when-clauses)."""

    nargs = 1


class Reinit:
    """reinit(x, expr): at the event, the state x restarts from expr."""

    __slots__ = ("variable", "value")

    def __init__(self, variable, value):
        self.variable = sympify_value(variable)
        self.value = sympify_value(value)
        if not isinstance(self.variable, sp.Symbol):
            raise TypeError(f"reinit() takes a variable, got {variable!r}")

    def __repr__(self):
        return f"reinit({self.variable}, {self.value})"


def reinit(variable, value) -> Reinit:
    """Modelica's reinit: used inside ``when``."""
    return Reinit(variable, value)


class When:
    """when condition: actions, firing when the condition becomes true (Modelica 8.3.5).

    The condition is a relation (``self.h < 0``) or an ``sp.Or``/``sp.And`` of relations;
    the actions are ``reinit(x, expr)``.  Expressions are evaluated with the values just
    before the event (``pre(x)`` says so explicitly).
    """

    __slots__ = ("condition", "actions", "origin", "origin_class")

    def __init__(self, condition, *actions):
        self.condition = condition if isinstance(condition, sp.Basic) else sp.sympify(condition)
        self.actions = list(actions)
        for a in self.actions:
            if not isinstance(a, Reinit):
                raise TypeError(f"when() takes reinit(...) actions, got {a!r}")
        self.origin = None
        self.origin_class = None

    def __repr__(self):
        return f"when {self.condition}: {self.actions}"


def when(condition, *actions) -> When:
    """``ac.when(self.h < 0, ac.reinit(self.v, -e*ac.pre(self.v)))``."""
    return When(condition, *actions)
