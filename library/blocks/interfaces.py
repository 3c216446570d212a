"""Partial blocks (Modelica.Blocks.Interfaces): causal signal blocks with RealInput and
RealOutput ports.

A block writes one equation for each of its outputs; an input is set by whatever output
it is connected to.  Inside an acausal model a block is just a component whose equations
happen to be explicit, so it can drive a source (``SignalVoltage``) or read a sensor.
"""
import acausal as ac
from acausal.ports import RealInput, RealOutput

__all__ = ["SO", "SISO", "SI2SO", "SignalSource", "start_from"]


class SO(ac.Component):
    """Single output y."""

    y = RealOutput()


class SISO(SO):
    """Single input u, single output y."""

    u = RealInput()


class SI2SO(SO):
    """Two inputs u1, u2, single output y."""

    u1 = RealInput()
    u2 = RealInput()


class SignalSource(SO):
    """A source of a time signal:  y = offset + (signal of time - startTime)."""

    offset = ac.Parameter(0.0, description="output before startTime")
    startTime = ac.Parameter(0.0, unit="s", description="time the signal starts")


def start_from(mods: dict, given: str, port: str = "y") -> dict:
    """``mods`` with the start value of output ``port`` taken from the parameter
    ``given`` where it is given as a number (the MSL's ``y(start = y_start)``), unless the
    output itself is modified."""
    value = mods.get(given)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        mods.setdefault(port, {"signal": {"start": float(value)}})
    return mods
