"""Top-level inputs: the inputs of the model's own ports that nothing in it drives.

A ``RealInput`` (``BooleanInput``, ``IntegerInput``) declared on the model itself, whose
connection set holds no port that drives it (an output, or a port of another kind) and
that no equation of the model gives a value (``ac.Eq(self.u, ...)``), is an *input of
the model*: its value comes from outside, as in a Modelica tool or an FMU.  Flattening
adds ``u.signal = input(u)``: the symbol ``input(u)`` is, for the generated code, a value
read from the parameter vector after the tunable parameters and the delays
(``p[n_params + n_delays + j]``), which the runtime writes from what ``simulate(...,
inputs={"u": ...})`` gives (a number, a function of time, a table:
:mod:`acausal.runtime.inputs`).  An input is no constant for the structural passes (its
value varies), and an equation with an input that index reduction would have to
differentiate is refused, since the runtime gives the input's value, not its derivative.
"""
from __future__ import annotations

import sympy as sp

from .flatten import FlatEquation

__all__ = ["InputValue", "find_inputs"]

_INPUT_PORTS = ("RealInput", "BooleanInput", "IntegerInput")


class InputValue:
    """One top-level input: ``name`` (the port's, ``u``), ``symbol`` its value in the
    equations, ``type`` (Real, Boolean, Integer), ``start`` (the signal's start value, the
    value of an input that is not given), ``where`` the model."""

    __slots__ = ("name", "symbol", "type", "start", "text", "where")

    def __init__(self, name, symbol, typ, start, where):
        self.name, self.symbol, self.type, self.start = name, symbol, typ, start
        self.text, self.where = f"input {name}", where

    def __repr__(self):
        return f"InputValue({self.name})"

    def not_differentiable(self) -> str:
        """Why an equation that index reduction differentiates may not hold the input."""
        return (f"the model's input '{self.name}' appears in an equation that index "
                "reduction must differentiate (the model needs der("
                f"{self.name}), which an input given as a value does not provide): give "
                "the derivative as another input, or filter the input inside the model "
                "(a first-order block before it)")


def _drives(port, inputs) -> bool:
    """Whether ``port`` can give a connection set its value: anything but an input."""
    return type(port).__name__ not in _INPUT_PORTS and port not in inputs


def find_inputs(flat, model, connections) -> list:
    """The top-level inputs of ``model`` (module docstring): the equations
    ``u.signal = input(u)`` are appended to ``flat.equations``; returns the
    :class:`InputValue` list in declaration order."""
    from ...components.declarations import TYPE_NAMES
    ports = {name: child for name, child in model.children().items()
             if type(child).__name__ in _INPUT_PORTS}
    if not ports:
        return []
    candidates = set(ports.values())
    driven = set()
    parent = {}

    def find(p):
        parent.setdefault(p, p)
        while parent[p] is not p:
            parent[p] = parent[parent[p]]
            p = parent[p]
        return p

    for conn in connections:
        for p in conn.ports[1:]:
            a, b = find(conn.ports[0]), find(p)
            if a is not b:
                parent[a] = b
    drivers = {find(p) for conn in connections for p in conn.ports
               if _drives(p, candidates)}
    for port in candidates:
        if port in parent and find(port) in drivers:
            driven.add(port)
    defined = {eq.defines for eq in flat.equations if eq.kind == "equation"}
    out = []
    for name, port in ports.items():
        sym = port.signal
        if port in driven or sym in defined:
            continue
        decl = port.declarations()["signal"]
        attrs = port.variable_attributes("signal")
        typ = TYPE_NAMES[getattr(decl, "type", float)]
        start = float(attrs.start) if attrs.start is not None else 0.0
        value = sp.Symbol(f"input({name})", real=True)
        out.append(InputValue(name, value, typ, start, f"the model ({flat.name})"))
        flat.equations.append(FlatEquation(sym - value, f"{sym.name} = input({name})",
                                           port.path, type(port).__name__, "input"))
    return out
