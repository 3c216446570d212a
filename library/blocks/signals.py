"""Time signals as expressions, shared by signal sources of every domain.

Each function returns a symbolic expression of ``time``; its relations become zero
crossings (events), so steps and pulse edges are located exactly.  The pulse uses a
smooth crossing function, ``cos(theta - pi w) - cos(pi w)`` with theta the phase, which
changes sign at both edges of every period without any ``mod``.
"""
import sympy as sp

import acausal as ac

__all__ = ["step", "ramp", "sine", "pulse"]


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
    ``period`` after ``start``, 0 otherwise (0 < width < 1)."""
    theta = 2 * sp.pi * (ac.time - start) / period
    high = sp.cos(theta - sp.pi * width) >= sp.cos(sp.pi * width)
    return ac.if_else(ac.time >= start, ac.if_else(high, amplitude, 0), 0)
