"""The symbolic vocabulary of equations: time, der(), Eq, and discontinuous expressions.

Variables and parameters are sympy Symbols named by their dotted path, so an equation a
user writes is an ordinary sympy expression and prints in the user's names.
``der(x)`` is the time derivative (Modelica's ``der``); it may be applied to an expression
(``der(m*v)``), which flattening expands by the chain rule.  ``der`` of a constant (a
number, a parameter) is kept unevaluated here so that flattening can report it: it is
always zero, so writing it is a mistake (the argument was meant to be a variable).

An equation is checked when it is written: both sides must be values (a relation such
as ``x > 1`` is not one: use ``if_else``), finite, and the equation must involve
something that can vary (``Eq(1, 1)`` and ``Eq(x, x)`` determine nothing, ``Eq(1, 2)``
never holds).  Errors are ``InvalidEquation``; flattening adds the component path.
"""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy import S
from sympy.core.parameters import global_parameters

from .ifexpr import unfolded_condition
from .printing import text
from .realsymbol import SYMBOLS
from ..errors import InvalidEquation

__all__ = ["time", "der", "Eq", "Equation", "if_else", "sign", "no_event", "delay",
           "sympify_value", "When", "when", "reinit", "Pre", "text", "sample", "Sample",
           "assign", "Assign"]

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
            from .arrays import elementwise
            return elementwise(cls, args[0])
        return super().__new__(cls, *args, **options)

    def _latex(self, printer):
        return r"\dot{%s}" % printer._print(self.args[0])


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
        from .arrays import array_equations
        return array_equations(lhs, rhs, label, Equation)
    return Equation(lhs, rhs, label)


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
_PLAIN_NODES = (sp.Add, sp.Mul, sp.Pow)


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


def _invalid(message: str):
    return InvalidEquation(message)


def _text(value) -> str:
    return sp.sstr(value) if isinstance(value, sp.Basic) else repr(value)


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


from . import logic as _logic     # noqa: E402  (it reads this module's names when called)
