"""The values of a model's top-level inputs during a run (:mod:`acausal.compiler.frontend.inputs`).

An input is driven by what ``simulate(..., inputs={"u": ...})`` gives:

* a number (a bool for a Boolean input, a whole number for an Integer one): a constant,
  written into ``p`` once, so the compiled step loop runs as for any model;
* a function of time, ``f(t) -> number``: evaluated before every call of the generated
  code (the Python step loop);
* a table ``(times, values)`` (two sequences of one length, times non-decreasing; a
  repeated time is a jump) or a ``CombiTimeTable`` (its first selected column, with its
  smoothness and extrapolation): interpolated linearly (a Boolean or Integer input, and
  ``smoothness="constant"``: held), held before the first and after the last time; its
  times are exact time events, so the integrator lands on every kink and jump.

A Boolean or Integer input changes only at events: given as a function, its value is
sampled at the events and output points only (a table says when it changes).
"""
from __future__ import annotations

import math
import numbers

import numpy as np
from ..errors import InvalidValue, MissingInput, NotInModel, SimulationError

__all__ = ["InputDrivers"]


class _Constant:
    varying = False

    def __init__(self, value):
        self.value = float(value)

    def __call__(self, t):
        return self.value

    def breaks(self):
        return ()


class _Function:
    varying = True

    def __init__(self, f, name):
        self.f, self.name = f, name

    def __call__(self, t):
        try:
            x = float(self.f(t))
        except Exception as err:        # the user's function: say which input
            raise SimulationError(f"the function given for input '{self.name}' raised "
                                  f"{type(err).__name__} at t = {t:.6g}: {err}", t) from err
        if not math.isfinite(x):
            raise SimulationError(f"the function given for input '{self.name}' returned "
                                  f"{x} at t = {t:.6g}", t)
        return x

    def breaks(self):
        return ()


class _Table:
    varying = True

    def __init__(self, times, values, held: bool, name: str):
        t = np.asarray(times, dtype=float).ravel()
        v = np.asarray(values, dtype=float).ravel()
        if t.size == 0 or t.shape != v.shape:
            raise InvalidValue(f"input '{name}': a table is (times, values) of one length "
                               f"(got {t.size} times and {v.size} values)")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))):
            raise InvalidValue(f"input '{name}': the table holds values that are not finite")
        if np.any(np.diff(t) < 0):
            k = int(np.argmax(np.diff(t) < 0))
            raise InvalidValue(f"input '{name}': the table's times decrease at row {k + 1} "
                               f"({t[k]:g} then {t[k + 1]:g})")
        self.t, self.v, self.held = t, v, held
        self.left = {}

    def __call__(self, t):
        """The value at t; at a repeated time (a jump) the value after it."""
        t_, v = self.t, self.v
        k = int(np.searchsorted(t_, t, side="right"))      # rows with time <= t
        if k == 0:
            return float(v[0])
        if k == len(t_) or self.held:
            return float(v[k - 1])
        t0, t1 = t_[k - 1], t_[k]
        return float(v[k - 1] + (v[k] - v[k - 1]) * (t - t0) / (t1 - t0))

    def breaks(self):
        return self.t


def _driver(spec, name, typ):
    """The driver of input ``name`` for what the user gave (module docstring)."""
    from ..components.declarations import typed_value
    if isinstance(spec, (numbers.Number, np.number, np.bool_)):
        kind = {"Boolean": bool, "Integer": int}.get(typ, float)
        try:
            return _Constant(typed_value(spec, kind, f"input '{name}'"))
        except ValueError as err:
            raise InvalidValue(str(err)) from None
    table = _table_of(spec)
    if table is not None:
        times, values, held = table
        return _Table(times, values, held or typ != "Real", name)
    if callable(spec):
        return _Function(spec, name)
    raise InvalidValue(f"input '{name}': give a number, a function of time, a table "
                       f"(times, values) or a CombiTimeTable, not {spec!r}")


def _table_of(spec):
    """(times, values, held) of a (times, values) pair or a CombiTimeTable, else None."""
    if isinstance(spec, tuple) and len(spec) == 2 and not callable(spec[0]):
        return spec[0], spec[1], False
    data = getattr(spec, "data", None)
    columns = getattr(spec, "columns", None)
    if data is not None and columns is not None:
        data = np.asarray(data, dtype=float)
        return data[:, 0], data[:, columns[0] - 1], spec.smoothness == "constant"
    return None


class InputDrivers:
    """The drivers of a model's inputs (``ic``: its :class:`InputCode`), written into
    ``p[slots]``; ``varying`` while one of them is a function or a table."""

    def __init__(self, ic, first_slot: int):
        self.names = list(ic.names)
        self.types = list(ic.types)
        self.starts = [float(x) for x in ic.starts]
        self.slots = first_slot + np.arange(len(self.names))
        self.drivers = [_Constant(x) for x in self.starts]
        self.given = False

    @property
    def varying(self) -> bool:
        return any(d.varying for d in self.drivers)

    def set(self, specs: dict | None, p) -> None:
        """Drive the inputs by ``specs`` ({name: number, function, table}); every input
        must be given (a missing or unknown name is a typed error naming it)."""
        specs = dict(specs or {})
        unknown = [n for n in specs if n not in self.names]
        if unknown:
            from ..words import suggestion
            raise NotInModel(f"simulate(inputs=...): the model has no input '{unknown[0]}'"
                             f"{suggestion(unknown[0], self.names)} (its inputs: "
                             f"{', '.join(self.names)})")
        missing = [n for n in self.names if n not in specs]
        if missing:
            raise MissingInput(
                f"the model's input{'s' if len(missing) > 1 else ''} "
                f"{', '.join(repr(n) for n in missing)} "
                f"{'are' if len(missing) > 1 else 'is'} not driven: give "
                + ", ".join(f"inputs={{'{n}': ...}}" for n in missing[:1])
                + " (a number, a function of time, a table (times, values) or a "
                "CombiTimeTable) to simulate")
        try:
            self.drivers = [_driver(specs[n], n, typ) for n, typ in zip(self.names, self.types)]
        except InvalidValue:
            raise
        self.given = True
        self.write(0.0, p, constants=True)

    def constants(self, values: dict, p) -> None:
        """Set inputs to constant values (linearize, steady state, sweeps)."""
        for n, x in values.items():
            j = self.names.index(n)
            self.drivers[j] = _driver(x, n, self.types[j])
            p[self.slots[j]] = self.drivers[j](0.0)

    def reset(self, p) -> None:
        """Back to the start values (after a run)."""
        self.drivers = [_Constant(x) for x in self.starts]
        self.given = False
        p[self.slots] = self.starts

    def write(self, t, p, constants: bool = False) -> None:
        """The inputs' values at time t into p (the varying ones; all with ``constants``)."""
        for j, d in enumerate(self.drivers):
            if constants or d.varying:
                p[self.slots[j]] = d(t)

    def values_at(self, t) -> np.ndarray:
        return np.array([d(t) for d in self.drivers])

    def next_break(self, t_min) -> float | None:
        """The first table time after t_min (a time event)."""
        best = None
        for d in self.drivers:
            b = np.asarray(d.breaks(), dtype=float)
            b = b[b > t_min]
            if b.size and (best is None or b[0] < best):
                best = float(b[0])
        return best
