"""Digital signals (Modelica.Electrical.Digital, MSL v4.0.0): the 9-valued logic of
IEEE 1164 (STD_ULOGIC), its connectors, its truth tables and the Pulse source.

A digital signal is the MSL's enumeration ``Logic`` coded by its Integer values (the MSL
documents the coding: 'U' = 1, 'X' = 2, '0' = 3, '1' = 4, 'Z' = 5, 'W' = 6, 'L' = 7,
'H' = 8, '-' = 9), carried by Integer ports: ``Logic["1"]`` is the MSL's ``L.'1'``, and
``DigitalInput``/``DigitalOutput`` are Integer signals holding such a code.  A digital
value changes at events only, as every Integer does.

The tables (Modelica.Electrical.Digital.Tables) are indexed by ``Logic`` codes, as the
MSL's ``AndTable[x1, x2]``: ``AndTable[Logic["1"]][Logic["H"]] == Logic["1"]`` (row and
column 0 are unused, so that a code indexes its row).  They follow IEEE 1164: the
operands of and, or, xor and not are first reduced to 'U', 'X', '0', '1' (a weak '0'
or '1' is the value, 'Z', 'W' and '-' are unknown); the resolution of two drivers keeps
the stronger one (forcing above weak above high impedance), two different values of one
strength give that strength's unknown ('X' or 'W'), and 'U' wins over all.  As the
MSL's X01ZTable, the reduction to 'X', '0', '1', 'Z' takes '-' to 'Z'.
"""
from enum import IntEnum

import sympy as sp

import acausal as ac
from acausal.ports import IntegerInput, IntegerOutput

__all__ = ["Logic", "DigitalInput", "DigitalOutput", "is_one", "AndTable", "OrTable",
           "NotTable", "XorTable", "ResolutionTable", "X01Table", "X01ZTable",
           "UX01Table", "Pulse"]

Logic = IntEnum("Logic", [("U", 1), ("X", 2), ("0", 3), ("1", 4), ("Z", 5), ("W", 6),
                          ("L", 7), ("H", 8), ("-", 9)])
Logic.__doc__ = ("Logic values and their coding according to IEEE 1164 STD_ULOGIC "
                 "(Modelica.Electrical.Digital.Interfaces.Logic): U uninitialized, "
                 "X forcing unknown, 0 forcing 0, 1 forcing 1, Z high impedance, "
                 "W weak unknown, L weak 0, H weak 1, - do not care")


class DigitalInput(IntegerInput):
    """Digital input (Modelica.Electrical.Digital.Interfaces.DigitalInput): a ``Logic``
    code, set by the DigitalOutput it is connected to."""

    hint = "a digital input signal is not connected"


class DigitalOutput(IntegerOutput):
    """Digital output (Modelica.Electrical.Digital.Interfaces.DigitalOutput): a ``Logic``
    code, set by the component that owns it."""


def is_one(signal):
    """The condition ``signal == L.'1' or signal == L.'H'`` (a forced or weak 1)."""
    return sp.Eq(signal, int(Logic["1"])) | sp.Eq(signal, int(Logic["H"]))


# -- Tables (Modelica.Electrical.Digital.Tables), from the rules of IEEE 1164 ------------

_U, _X, _0, _1 = Logic["U"], Logic["X"], Logic["0"], Logic["1"]
# the strength of a driver: forcing 3, weak 2, high impedance 1; its value 0, 1 or None
_STRENGTH = {"0": (3, 0), "1": (3, 1), "X": (3, None), "L": (2, 0), "H": (2, 1),
             "W": (2, None), "Z": (1, None)}


def _ux01(x: Logic) -> Logic:
    """x reduced to U, X, 0, 1 (the MSL's UX01Table)."""
    if x is _U:
        return _U
    return {"0": _0, "L": _0, "1": _1, "H": _1}.get(x.name, _X)


def _and(a: Logic, b: Logic) -> Logic:
    a, b = _ux01(a), _ux01(b)
    if _0 in (a, b):
        return _0
    if _U in (a, b):
        return _U
    return _1 if a is b is _1 else _X


def _or(a: Logic, b: Logic) -> Logic:
    a, b = _ux01(a), _ux01(b)
    if _1 in (a, b):
        return _1
    if _U in (a, b):
        return _U
    return _0 if a is b is _0 else _X


def _xor(a: Logic, b: Logic) -> Logic:
    a, b = _ux01(a), _ux01(b)
    if _U in (a, b):
        return _U
    if _X in (a, b):
        return _X
    return _1 if a is not b else _0


def _not(a: Logic) -> Logic:
    return {_0: _1, _1: _0}.get(_ux01(a), _ux01(a))


def _resolved(a: Logic, b: Logic) -> Logic:
    if _U in (a, b):
        return _U
    if "-" in (a.name, b.name):
        return _X
    (sa, va), (sb, vb) = _STRENGTH[a.name], _STRENGTH[b.name]
    if sa != sb:
        return a if sa > sb else b
    if a is b:
        return a
    return _X if sa == 3 else Logic["W"]   # two values of one strength (Z Z is a is b)


def _table1(rule) -> tuple:
    return (None,) + tuple(rule(a) for a in Logic)


def _table2(rule) -> tuple:
    return (None,) + tuple(_table1(lambda b, a=a: rule(a, b)) for a in Logic)


AndTable = _table2(_and)
OrTable = _table2(_or)
XorTable = _table2(_xor)
NotTable = _table1(_not)
ResolutionTable = _table2(_resolved)
X01Table = _table1(lambda a: _X if _ux01(a) is _U else _ux01(a))
X01ZTable = _table1(lambda a: Logic["Z"] if a.name in "Z-" else X01Table[a])  # '-': the MSL's
UX01Table = _table1(_ux01)


# -- Sources ----------------------------------------------------------------------------

class Pulse(ac.Component):
    """Digital pulse source (Modelica.Electrical.Digital.Sources.Pulse, MSL v4.0.0): the
    value ``pulse`` for ``width`` % of each period from startTime, ``quiet`` otherwise,
    for ``nperiod`` periods (< 0: without end):

        sampling = nperiod <> 0 and (nperiod >= pre(np) or nperiod < 0)
        tick = sample(startTime, period)      (the MSL writes it in the when-condition)
        when sampling and tick:
            T0 = time,   np = if nperiod > 0 then pre(np) + 1 else pre(np)
        y = if sampling then (if time < startTime or time >= T0 + width period/100
                              then quiet else pulse) else quiet
    """

    width = ac.Parameter(50.0, min=0, max=100, description="widths of pulses in % of periods")
    period = ac.Parameter(1.0, unit="s", min=0, description="time for one period")
    startTime = ac.Parameter(0.0, unit="s", description="output = quiet for time < startTime")
    pulse = ac.Parameter(int(Logic["0"]), type=int, description="pulsed value (a Logic code)")
    quiet = ac.Parameter(int(Logic["1"]), type=int, description="quiet value (a Logic code)")
    nperiod = ac.Parameter(-1, type=int, description="number of periods "
                           "(< 0 means infinite number of periods)")
    T0 = ac.Variable(discrete=True, start=0.0, fixed=True, unit="s",
                     description="start time of current period")
    np = ac.Variable(type=int, start=0, fixed=True, description="number of periods begun")
    sampling = ac.Variable(type=bool, description="the pulses go on")
    tick = ac.Variable(type=bool, description="sample(startTime, period): true at a tick")
    y = DigitalOutput()

    def __init__(self, **mods):
        mods.setdefault("T0", {"start": mods.get("startTime", 0.0), "fixed": True})
        super().__init__(**mods)

    def equations(self):
        t = ac.time
        high = (t < self.startTime) | (t >= self.T0 + self.width * self.period / 100)
        # nperiod <> 0, written as two inequalities: a relation of parameters alone is a
        # mode of the compiled model, and modes are inequalities
        return [ac.Eq(self.sampling, ((self.nperiod > 0) | (self.nperiod < 0))
                      & ((self.nperiod >= ac.pre(self.np)) | (self.nperiod < 0))),
                ac.Eq(self.tick, ac.sample(self.startTime, self.period)),
                ac.when(self.sampling & self.tick,
                        ac.assign(self.T0, t),
                        ac.assign(self.np, ac.if_else(self.nperiod > 0, ac.pre(self.np) + 1,
                                                      ac.pre(self.np)))),
                ac.Eq(self.y, ac.if_else(self.sampling,
                                         ac.if_else(high, self.quiet, self.pulse),
                                         self.quiet))]
