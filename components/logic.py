"""The Boolean vocabulary of equations: conditions, Boolean and Integer values, and
Modelica's ``pre``, ``edge``, ``change``, ``initial`` and ``integer``.

A Boolean variable or parameter is a symbol whose value is 1 or 0; in a condition it is
the relation ``y > 1/2`` (:func:`as_condition`), and a condition given to a Boolean is
its value 1 or 0 (:func:`boolean_value`).  Which symbols are Boolean or Integer is known
while a model is compiled (the root's register, filled as the symbols are made:
:func:`value_type`).
"""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy import S

from .declarations import COMPILING
from .operators import Pre, Sample, _invalid, _text, sympify_value
from .printing import text
from .realsymbol import SYMBOLS

__all__ = ["as_condition", "value_type", "is_logical", "boolean_value", "pre", "edge",
           "change", "initial", "INITIAL", "integer"]


def _logical_side(value) -> bool:
    if isinstance(value, (bool, np.bool_)):
        return True
    return isinstance(value, sp.Basic) and not isinstance(value, sp.Expr)


def _check_boolean_equation(lhs, rhs, given_lhs, given_rhs) -> None:
    """A condition is the value of a Boolean: the other side is a Boolean variable."""
    logical = given_lhs if _logical_side(given_lhs) else given_rhs
    other = rhs if logical is given_lhs else lhs
    if type(other) in SYMBOLS and value_type(other) in (bool, None):
        return
    what = (f"{other.name} is a{'n Integer' if value_type(other) is int else ' Real'} "
            "variable" if type(other) in SYMBOLS else f"{_text(other)} is not a variable")
    raise _invalid(f"ac.Eq({_text(given_lhs)}, {_text(given_rhs)}): {_text(logical)} is a "
                   f"relation or a logical value, not a value, and {what} "
                   "(ac.if_else(condition, a, b) chooses between values; a Boolean "
                   "variable, type=bool, takes the truth of a condition)")



class _NotACondition(Exception):
    def __init__(self, why=""):
        super().__init__(why)
        self.why = why


_HALF = S.Half


def value_type(expr):
    """The value type (float, bool or int) of a variable or parameter symbol of the
    model being compiled; float for anything else, None outside a compile (where the
    types are not known)."""
    types = getattr(COMPILING.get(), "_value_types", None)
    if types is None:
        return None
    return types.get(expr, float)


def is_logical(value) -> bool:
    """True for a truth value: a relation, True/False, or a logical combination (a
    sympy Symbol is a Boolean to sympy, but a variable is not a truth value)."""
    if isinstance(value, (bool, np.bool_)):
        return True
    if isinstance(value, (sp.core.relational.Relational, sp.logic.boolalg.BooleanAtom)):
        return True
    return isinstance(value, sp.logic.boolalg.BooleanFunction) and not isinstance(
        value, Sample)


def as_condition(value):
    """``value`` as a condition in the one form the compiler reads: relations and And,
    Or, Not of them.  A Boolean variable or parameter y (its value is 1 or 0) is the
    relation ``y > 1/2``, and so is ``pre(y)``; Xor, Equivalent and ITE are written with
    And, Or and Not.  A relation whose sides change only at events (Booleans, Integers,
    parameters) is evaluated directly, one of time or of a continuous variable is an
    event (:func:`acausal.compiler.codegen.extract_relations`).  Raises
    ``InvalidEquation`` for what is not a condition (a Real variable, a number)."""
    if isinstance(value, (bool, np.bool_)):
        return sp.true if value else sp.false
    if not isinstance(value, sp.Basic):
        if not hasattr(value, "_sympy_"):
            raise _NotACondition()
        value = value._sympy_()
    return _as_condition(value)


def _as_condition(e):
    logic = sp.logic.boolalg
    if isinstance(e, (sp.core.relational.Relational, logic.BooleanAtom)):
        return e
    if type(e) in SYMBOLS or isinstance(e, Pre):
        typ = value_type(e.args[0] if isinstance(e, Pre) else e)
        if typ in (bool, None):
            return sp.StrictGreaterThan(e, _HALF)
        name = text(e)
        raise _NotACondition(f" ({name} is a{'n Integer' if typ is int else ' Real'} "
                             f"variable; compare it, e.g. {name} > 0)")
    if isinstance(e, (logic.And, logic.Or, logic.Not)):
        return type(e)(*[_as_condition(a) for a in e.args])
    if isinstance(e, logic.Xor):
        out = _as_condition(e.args[0])
        for a in e.args[1:]:
            b = _as_condition(a)
            out = (out & ~b) | (~out & b)
        return out
    if isinstance(e, logic.Equivalent):
        args = [_as_condition(a) for a in e.args]
        return sp.And(*args) | sp.And(*[~a for a in args])
    if isinstance(e, logic.ITE):
        c, a, b = (_as_condition(x) for x in e.args)
        return (c & a) | (~c & b)
    raise _NotACondition()


def boolean_value(cond):
    """A condition as the value of a Boolean: 1 where it holds, else 0."""
    return sp.Piecewise((S.One, as_condition(cond)), (S.Zero, True))


def pre(x):
    """``pre(x)``: the value of x just before the event (Modelica's ``pre``; see
    :class:`acausal.components.symbols.Pre`).  Of a Boolean it is a condition (``~ac.pre(self.y) & self.u``), of
    anything else a value."""
    value = Pre(sympify_value(x))
    return as_condition(value) if _boolean_symbol(value.args[0]) else value


def _boolean_symbol(x) -> bool:
    return type(x) in SYMBOLS and value_type(x) is bool


def _discrete_symbol(x, what: str):
    x = sympify_value(x)
    if type(x) not in SYMBOLS:
        raise _invalid(f"{what}({_text(x)}) takes a Boolean or Integer variable (its value "
                       "before the event is kept), not an expression")
    return x


def edge(b):
    """``edge(b)``: b became true at this event, ``b and not pre(b)`` (Modelica's
    ``edge``; b a Boolean variable)."""
    x = _discrete_symbol(b, "edge")
    return as_condition(x) & ~as_condition(Pre(x))


def change(v):
    """``change(v)``: v changed at this event, ``v <> pre(v)`` (Modelica's ``change``; v
    a Boolean or Integer variable)."""
    x = _discrete_symbol(v, "change")
    return sp.Ne(x, Pre(x))


# true while the initial values are found (Modelica's initial()); the runtime holds it
INITIAL = sp.Symbol("initial()", real=True)


def initial():
    """``initial()``: true at the initialization (a when-clause with it fires once the
    initial values are found), false afterwards (Modelica's ``initial()``)."""
    root = COMPILING.get()
    if root is not None:
        object.__setattr__(root, "_uses_initial", True)   # m keeps its value
    return sp.StrictGreaterThan(INITIAL, _HALF)


def integer(x):
    """``integer(x)``: the largest whole number not above x (Modelica's ``integer``,
    floor): a value that changes at events, where x crosses a whole number."""
    return sp.floor(sympify_value(x))
