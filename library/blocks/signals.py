"""Time signals as expressions, shared by signal sources of every domain.

Each function returns a symbolic expression of ``time``.  Its relations are linear in
time between events, so the runtime knows every edge before the integrator reaches it
(exact time events, :mod:`acausal.runtime.modes`): a step, the corners of a ramp, and
both edges of every pulse, however short the pulse and however long the run.  The pulse
reads its phase through ``mod`` (a frozen floor value, Modelica semantics), which
switches at the start of every period.
"""
from acausal._sympy import sympy as sp

import acausal as ac

__all__ = ["step", "ramp", "sine", "pulse", "trapezoid"]


def step(height, start):
    """``height`` from ``start`` on, 0 before."""
    return ac.if_else(ac.time >= start, height, 0)


def ramp(height, duration, start):
    """0 before ``start``, rising linearly to ``height`` over ``duration``, then constant."""
    rising = height * (ac.time - start) / duration
    return ac.if_else(ac.time < start, 0, ac.if_else(ac.time < start + duration, rising, height))


def sine(amplitude, f, phase, start):
    """``amplitude sin(2 pi f (time - start) + phase)`` from ``start`` on, 0 before."""
    wave = amplitude * sp.sin(2 * sp.pi * f * (ac.time - start) + phase)
    return ac.if_else(ac.time >= start, wave, 0)


def pulse(amplitude, width, period, start):
    """Rectangular pulses: ``amplitude`` during the first fraction ``width`` of every
    ``period`` after ``start``, 0 otherwise (0 < width < 1)::

        phase = mod(time - start, period),   high while phase < width * period
    """
    phase = sp.Mod(ac.time - start, period)
    return ac.if_else(ac.time >= start, ac.if_else(phase < width * period, amplitude, 0), 0)


def trapezoid(amplitude, rising, width, falling, period, start):
    """Periodic trapezoid after ``start`` (the MSL's Trapezoid, endless): in every
    ``period`` a rise over ``rising`` to ``amplitude``, ``width`` at it, a fall over
    ``falling`` to 0, then 0 for the rest of the period::

        phase = mod(time - start, period)

    (rising + width + falling <= period; every corner is an exact time event.)
    """
    phase = sp.Mod(ac.time - start, period)
    top, down = rising + width, rising + width + falling
    shape = ac.if_else(phase < rising, amplitude * phase / rising,
                       ac.if_else(phase < top, amplitude,
                                  ac.if_else(phase < down,
                                             amplitude * (down - phase) / falling, 0)))
    return ac.if_else(ac.time >= start, shape, 0)
