"""User-defined functions with a derivative (Modelica's ``function ... annotation(derivative
= f_der)``, Language Specification 3.5, sec. 12.7.1).

A function of a model's values given as Python, which index reduction differentiates by
the derivative function the user gives instead of by its body::

    @ac.function
    def position_der2(q_qd_qdd, dummy, dummy_der, dummy_der2):
        return q_qd_qdd[2]

    @ac.function(derivative=position_der2, no_derivative=("q_qd_qdd", "dummy_der"))
    def position_der(q_qd_qdd, dummy, dummy_der):
        return q_qd_qdd[1]

    @ac.function(derivative=position_der, no_derivative="q_qd_qdd")
    def position(q_qd_qdd, dummy):
        return q_qd_qdd[0]

    ac.Eq(self.phi, position(self.u, ac.time))     # (Rotational.Sources.Move)

Called with numbers it is its body.  Called with an expression among its arguments it is
a node of the equation (a sympy function of its arguments' values, each element of an
array argument one argument) until index reduction is done, and its time derivative is,
as the specification has it,

    d/dt f(x1, ..., xn) = f_der(x1, ..., xn, der(x1), ..., der(xm))

with one derivative argument, of its argument's shape, for each input not listed in
``no_derivative``, in their order (:func:`time_derivative`, which the compiler's time
differentiation calls for an expression holding a call).  The derivative of a derivative
function is its own ``derivative=`` (the specification's ``order=2`` form: list the
first derivative's derivative inputs that need no derivative of their own, such as
``dummy_der`` above, in its ``no_derivative``).  ``no_derivative`` names the inputs
whose derivative the result does not need: the user asserts that d/dt f does not
depend on it (Move's signals u carry their own derivatives), so it is never
differentiated, and the structural passes (index reduction, the signature matrix) do not
count it as an incidence of the equation (:func:`structural_symbols`).  A partial
derivative d f / d x_k (a Jacobian entry) is the body's.  A call that index reduction
must differentiate, whose derivative needs an input's derivative, is refused if the
function has no derivative, naming it.

After index reduction every call is replaced by its body (Modelica's
``InlineAfterIndexReduction``, :func:`inline_functions`; the assembly then takes the
equation's incidence again, so the BLT orders it after what the body reads), and the
Jacobian and the code see the body itself.  The body must therefore be written with the
operations of an equation (``+``, ``*``, indexing, ``ac.sin``, ``ac.if_else``, ...), not
with Python control flow on its arguments' values.  The class of a call is named with a
digest of the body and its derivatives, so the compile cache tells a changed function
from the old one.
"""
from __future__ import annotations

import difflib
import inspect

import numpy as np

from .values import is_symbolic
from ..errors import InvalidValue, ModelError

__all__ = ["function", "Function", "inline_functions", "has_calls", "time_derivative",
           "structural_symbols", "calls_outside"]


def _sympy():
    import sympy
    return sympy


def _invalid(message: str):
    return InvalidValue(message)


def _symbolic(value) -> bool:
    if isinstance(value, np.ndarray):
        return any(is_symbolic(v) for v in value.flat)
    if isinstance(value, (list, tuple)):
        return any(_symbolic(v) for v in value)
    return is_symbolic(value)


def _layout(value):
    """The shape of an argument: None for one value, else its numpy shape."""
    if isinstance(value, (np.ndarray, list, tuple)):
        return np.shape(np.asarray(value, dtype=object))
    return None


def _flat(value, shape) -> list:
    if shape is None:
        return [value]
    return list(np.asarray(value, dtype=object).reshape(-1))


def _build(values, shape):
    if shape is None:
        return values[0]
    return np.array(values, dtype=object).reshape(shape)


class Function:
    """A user-defined function with an optional derivative (module docstring); made by
    :func:`function`."""

    def __init__(self, body, derivative=None, no_derivative=(), name=None):
        if not callable(body):
            raise _invalid(f"ac.function takes a Python function, not {body!r}")
        self.body = body
        self.name = name or getattr(body, "__name__", "function")
        params = [p for p in inspect.signature(body).parameters.values()]
        if any(p.kind not in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) for p in params):
            raise _invalid(f"ac.function {self.name}: its inputs must be plain positional "
                           "parameters (no *args, **kwargs or keyword-only ones)")
        self.inputs = [p.name for p in params]
        if isinstance(no_derivative, str):
            no_derivative = (no_derivative,)
        for n in no_derivative:
            if n not in self.inputs:
                close = difflib.get_close_matches(n, self.inputs, n=1)
                hint = f" (did you mean {close[0]!r}?)" if close else ""
                raise _invalid(f"ac.function {self.name}: no_derivative names {n!r}, which "
                               f"is not one of its inputs {self.inputs}{hint}")
        self.no_derivative = frozenset(no_derivative)
        if derivative is not None and not isinstance(derivative, Function):
            derivative = Function(derivative)
        if derivative is not None:
            need = len(self.inputs) + len(self.differentiable)
            if len(derivative.inputs) != need:
                raise _invalid(
                    f"ac.function {self.name}: its derivative {derivative.name} takes "
                    f"{len(derivative.inputs)} inputs, but must take {need}: the "
                    f"{len(self.inputs)} inputs of {self.name}, then the derivatives of "
                    f"{self.differentiable} (those not in no_derivative)")
        self.derivative = derivative
        self._nodes = {}
        self.__doc__ = body.__doc__
        self.__name__ = self.name

    @property
    def digest(self) -> str:
        """A digest of the body, its inputs and its derivative functions."""
        h = self.__dict__.get("_digest")
        if h is None:
            import hashlib
            try:
                text = inspect.getsource(self.body)
            except (OSError, TypeError):
                code = self.body.__code__
                text = repr((code.co_code, code.co_consts, code.co_names))
            parts = [self.name, text, repr(self.inputs), repr(sorted(self.no_derivative)),
                     self.derivative.digest if self.derivative is not None else ""]
            h = hashlib.sha256("\x1f".join(parts).encode()).hexdigest()[:12]
            self._digest = h
        return h

    @property
    def differentiable(self) -> list:
        """The inputs whose derivatives the derivative function takes, in order."""
        return [n for n in self.inputs if n not in self.no_derivative]

    def __repr__(self):
        return f"<ac.function {self.name}({', '.join(self.inputs)})>"

    def __call__(self, *args):
        if len(args) != len(self.inputs):
            raise _invalid(f"{self.name}() takes {len(self.inputs)} arguments "
                           f"({', '.join(self.inputs)}), got {len(args)}")
        if not _symbolic(args):
            return self.body(*args)
        from .operators import sympify_value     # sympy: a call with symbols only
        layout = tuple(_layout(a) for a in args)
        flat = [sympify_value(v) for a, s in zip(args, layout) for v in _flat(a, s)]
        return self._node(layout)(*flat)

    def _node(self, layout):
        """The sympy function class of this function for arguments of these shapes."""
        node = self._nodes.get(layout)
        if node is None:
            # the class's name carries a digest of the body and its derivatives: the
            # compile cache knows an equation by its node classes' names, and a changed
            # body must not find the model compiled with the old one
            node = type(f"{self.name}_{self.digest}", (_applied(),),
                        {"function": self, "layout": layout,
                         "nargs": sum(_size(s) for s in layout)})
            self._nodes[layout] = node
        return node


def _size(shape) -> int:
    return 1 if shape is None else int(np.prod(shape))


def _unflatten(flat, layout) -> list:
    out, k = [], 0
    for s in layout:
        n = _size(s)
        out.append(_build(list(flat[k:k + n]), s))
        k += n
    return out


def _applied_base():
    sp = _sympy()

    class _AppliedBase(sp.Function):
        """A call of a user-defined function in an equation (module docstring)."""

        function: Function = None
        layout: tuple = ()

        @classmethod
        def eval(cls, *args):
            return None                  # stays a call until it is inlined

        def inline(self):
            """The body, on the call's arguments."""
            f = type(self).function
            return _sympy().sympify(f.body(*_unflatten(self.args, type(self).layout)))

        def fdiff(self, argindex=1):
            """d f / d x_k, from the body (the Jacobian's entry; the time derivative
            is the derivative function's, :func:`time_derivative`)."""
            sp = _sympy()
            k = argindex - 1
            d = sp.Dummy("x")
            args = list(self.args)
            args[k] = d
            body = type(self).function.body(*_unflatten(args, type(self).layout))
            return sp.diff(sp.sympify(body), d).xreplace({d: self.args[k]})

        def _eval_evalf(self, prec):
            return self.inline()._eval_evalf(prec)

        def _sympystr(self, printer):
            return f"{type(self).function.name}({', '.join(printer.doprint(a) for a in self.args)})"

    return _AppliedBase


class _LazyApplied:
    """The sympy base class of the calls, made when sympy is first needed (defining
    components does not load sympy)."""
    cls = None


def _applied():
    if _LazyApplied.cls is None:
        _LazyApplied.cls = _applied_base()
    return _LazyApplied.cls


def function(body=None, *, derivative=None, no_derivative=(), name=None):
    """``@ac.function`` or ``@ac.function(derivative=f_der, no_derivative=("u",))``: a
    user-defined function of a model's values whose time derivative is ``derivative``
    (Modelica's derivative annotation; the module docstring says how)."""
    if body is None:
        return lambda b: Function(b, derivative, no_derivative, name)
    return Function(body, derivative, no_derivative, name)


def inline_functions(expr):
    """``expr`` with every call of a user-defined function replaced by its body."""
    sp = _sympy()
    if not isinstance(expr, sp.Basic):
        return expr
    base = _LazyApplied.cls
    if base is None:
        return expr
    while expr.has(base):
        expr = expr.replace(lambda e: isinstance(e, base), lambda e: e.inline())
    return expr


def has_calls(expr) -> bool:
    """True if ``expr`` calls a user-defined function."""
    base = _LazyApplied.cls
    return base is not None and isinstance(expr, _sympy().Basic) and expr.has(base)


def calls_outside(expr) -> tuple:
    """(``{stand-in: call}``, ``expr`` with each outermost call of a user-defined
    function replaced by a stand-in symbol)."""
    if not has_calls(expr):
        return {}, expr
    sp = _sympy()
    stand = {c: sp.Dummy(type(c).function.name) for c in _outer_calls(expr)}
    return {d: c for c, d in stand.items()}, expr.xreplace(stand)


def _outer_calls(expr) -> list:
    """The calls in ``expr`` that are not inside another call's arguments."""
    sp = _sympy()
    base = _LazyApplied.cls
    out, stack = [], [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, base):
            if e not in out:
                out.append(e)
        elif isinstance(e, sp.Basic):
            stack.extend(e.args)
    return out


def structural_symbols(expr, symbols_of) -> set:
    """The symbols of ``expr`` that the structural passes see (index reduction, the
    signature matrix): those of its inputs not in no_derivative, whose derivatives the
    call's derivative reads; an input in no_derivative is a value the call reads, never
    differentiated, so it is no incidence of the equation until the call is inlined
    (Modelica's InlineAfterIndexReduction, :func:`inline_functions`).  ``symbols_of``:
    the symbols of an expression without calls."""
    kept, reduced = calls_outside(expr)
    out = set(symbols_of(reduced)) - set(kept)
    for call in kept.values():
        cls = type(call)
        f = cls.function
        for name, value, shape in zip(f.inputs, _unflatten(call.args, cls.layout),
                                      cls.layout):
            if name not in f.no_derivative:
                for v in _flat(value, shape):
                    out |= structural_symbols(_sympy().sympify(v), symbols_of)
    return out


def time_derivative(expr, plain):
    """d/dt ``expr`` where each call of a user-defined function is differentiated by its
    derivative function (module docstring), and the rest by ``plain`` (the compiler's
    d/dt of an expression without calls: the chain rule over its variables and time).

        d/dt g(v, f(x)) = plain d/dt of g(v, c) + dg/dc f_der(x, d/dt x_diff)

    with c standing for the call and x_diff its inputs not in no_derivative."""
    sp = _sympy()
    kept, reduced = calls_outside(expr)
    out = plain(reduced)
    for d, c in kept.items():
        out += sp.diff(reduced, d) * _call_derivative(c, plain)
    return out.xreplace(kept)


def _call_derivative(call, plain):
    """d/dt of one call: the derivative function at its inputs and the time derivatives
    of those not in no_derivative."""
    sp = _sympy()
    cls = type(call)
    f = cls.function
    args = _unflatten(call.args, cls.layout)
    ders = []
    for name, value, shape in zip(f.inputs, args, cls.layout):
        if name in f.no_derivative:
            continue
        flat = _flat(value, shape)
        ders.append(_build([time_derivative(sp.sympify(v), plain) for v in flat], shape))
    if f.derivative is None:
        if all(sp.sympify(v) == 0 for d in ders for v in _flat(d, _layout(d))):
            return sp.S.Zero
        raise ModelError(
            f"{f.name}({', '.join(map(str, call.args))}) must be differentiated (index "
            "reduction differentiates its equation), but ac.function "
            f"{f.name} has no derivative: give it one, ac.function(derivative=...), or "
            "list in no_derivative the inputs whose derivative it does not need")
    return sp.sympify(f.derivative(*args, *ders))
