"""Means, root mean squares and harmonics over a period, and the total harmonic
distortion (Modelica.Blocks.Math: Mean, RootMeanSquare, Harmonic, TotalHarmonicDistortion,
and the blocks they are made of: MultiProduct, RectangularToPolar, Pythagoras).

The averages are integrals over a period 1/f, sampled and restarted at the end of every
period (t0 + k/f, exact time events); their output holds the last period's value.
"""
from __future__ import annotations

import math

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput, RealOutput

from .interfaces import SI2SO, SISO
from .math import Division, Gain, Sqrt
from .nonlinear import Limiter
from .sources import Cosine, Sine

__all__ = ["MultiProduct", "RectangularToPolar", "Pythagoras", "Mean", "RootMeanSquare",
           "Harmonic", "TotalHarmonicDistortion"]


class MultiProduct(ac.Component):
    """y = u[0] u[1] ... u[nu-1] (MSL Blocks.Math.MultiProduct); ``nu`` is given when it
    is made."""

    nu = ac.Parameter(2, structural=True, min=0, description="number of inputs")
    y = RealOutput()

    def build(self):
        self.u = [RealInput() for _ in range(int(self.nu))]

    def equations(self):
        return [ac.Eq(self.y, sp.Mul(*(u.signal for u in self.u)) if self.u else 0)]


class RectangularToPolar(ac.Component):
    """y_abs = sqrt(u_re^2 + u_im^2),   y_arg = atan2(u_im, u_re)   (MSL
    Blocks.Math.RectangularToPolar)."""

    u_re = RealInput()
    u_im = RealInput()
    y_abs = RealOutput()
    y_arg = RealOutput()

    def equations(self):
        re, im = self.u_re.signal, self.u_im.signal
        return [ac.Eq(self.y_abs, ac.sqrt(re * re + im * im)),
                ac.Eq(self.y_arg, sp.atan2(im, re))]


class Pythagoras(SI2SO):
    """The hypotenuse or a leg of a right triangle (MSL Blocks.Math.Pythagoras):

        y = sqrt(u1^2 + u2^2),  or with u1IsHypotenuse = True,
        y = sqrt(u1^2 - u2^2) where u1^2 >= u2^2, else 0

    ``u1IsHypotenuse`` is given when it is made.  The MSL's Boolean output ``valid``
    (u1^2 >= u2^2) waits for Boolean signals.
    """

    def __init__(self, *, u1IsHypotenuse: bool = False, **modifications):
        self.u1IsHypotenuse = bool(u1IsHypotenuse)
        super().__init__(**modifications)

    def equations(self):
        u1, u2 = self.u1.signal, self.u2.signal
        if not self.u1IsHypotenuse:
            return [ac.Eq(self.y, ac.sqrt(u1**2 + u2**2))]
        y2 = u1**2 - u2**2
        return [ac.Eq(self.y, ac.no_event(ac.if_else(y2 >= 0, ac.sqrt(y2), 0)))]


class Mean(SISO):
    """The mean of u over each period 1/f (MSL Blocks.Math.Mean):

        der(x) = u,   x(t0) = x0,
        at t0 + k/f:  y_last := f x (or max(0, f x) if yGreaterOrEqualZero),  x := 0,
        y = y_last

    y_last starts at 0.  The MSL takes t0 from the start of the simulation; here it is a
    parameter (0, where acausal's runs start).  ``yGreaterOrEqualZero`` is given when
    the block is made.  y_last is held by the restart (der(y_last) = 0 between the
    instants), so that both restarts read the values just before the instant.
    """

    f = ac.Parameter(50.0, unit="Hz", description="base frequency")
    x0 = ac.Parameter(0.0, description="start value of the integrator state")
    t0 = ac.Parameter(0.0, unit="s", description="start of the first period")
    x = ac.Variable(start=0.0, description="integrator state")
    y_last = ac.Variable(start=0.0, fixed=True, description="the last period's mean")

    def __init__(self, *, yGreaterOrEqualZero: bool = False, **modifications):
        self.yGreaterOrEqualZero = bool(yGreaterOrEqualZero)
        super().__init__(**modifications)

    def initial_equations(self):
        return [ac.Eq(self.x, self.x0)]

    def equations(self):
        mean = self.f * self.x
        if self.yGreaterOrEqualZero:
            mean = ac.max(0, mean)
        return [ac.Eq(ac.der(self.x), self.u.signal),
                ac.Eq(ac.der(self.y_last), 0),
                ac.when(ac.sample(self.t0 + 1 / self.f, 1 / self.f),
                        ac.reinit(self.y_last, mean), ac.reinit(self.x, 0)),
                ac.Eq(self.y, self.y_last)]


class RootMeanSquare(SISO):
    """The root mean square of u over each period 1/f (MSL Blocks.Math.RootMeanSquare):
    u u through a Mean (y >= 0) and a square root."""

    f = ac.Parameter(50.0, unit="Hz", description="base frequency")
    x0 = ac.Parameter(0.0, description="start value of the integrator state")
    product = MultiProduct(nu=2)
    mean = Mean(f=ac.ref("f"), x0=ac.ref("x0"), yGreaterOrEqualZero=True)
    sqrt1 = Sqrt()

    def equations(self):
        return [ac.connect(self.product.y, self.mean.u),
                ac.connect(self.mean.y, self.sqrt1.u), ac.connect(self.sqrt1.y, self.y),
                ac.connect(self.u, self.product.u[0]), ac.connect(self.u, self.product.u[1])]


class Harmonic(ac.Component):
    """The k-th harmonic of u over each period 1/f, as root mean square and angle (MSL
    Blocks.Math.Harmonic): the means of sqrt(2) cos(2 pi k f t) u and sqrt(2) sin(2 pi k f
    t) u are its real and imaginary parts,

        y_rms = |mean1 + j mean2|,   y_arg = +-arg(mean1 + j mean2)

    (minus with ``useConjugateComplex``, given when it is made)."""

    f = ac.Parameter(50.0, unit="Hz", description="base frequency")
    k = ac.Parameter(1.0, description="order of the harmonic")
    x0Cos = ac.Parameter(0.0, description="start value of the cosine integrator")
    x0Sin = ac.Parameter(0.0, description="start value of the sine integrator")
    f_k = ac.Parameter(lambda c: c.k * c.f, unit="Hz", description="k f")
    amplitude = ac.Parameter(math.sqrt(2), description="sqrt(2)")
    u = RealInput()
    y_rms = RealOutput()
    y_arg = RealOutput()
    sin1 = Cosine(amplitude=ac.ref("amplitude"), f=ac.ref("f_k"), phase=0.0)
    sin2 = Sine(amplitude=ac.ref("amplitude"), f=ac.ref("f_k"), phase=0.0)
    product1 = MultiProduct(nu=2)
    product2 = MultiProduct(nu=2)
    mean1 = Mean(f=ac.ref("f"), x0=ac.ref("x0Cos"))
    mean2 = Mean(f=ac.ref("f"), x0=ac.ref("x0Sin"))
    rectangularToPolar = RectangularToPolar()

    def __init__(self, *, useConjugateComplex: bool = False, **modifications):
        self.useConjugateComplex = bool(useConjugateComplex)
        super().__init__(**modifications)

    def build(self):
        self.gain = Gain(k=-1.0 if self.useConjugateComplex else 1.0)

    def equations(self):
        return [ac.connect(self.product2.y, self.mean2.u),
                ac.connect(self.product1.y, self.mean1.u),
                ac.connect(self.mean1.y, self.rectangularToPolar.u_re),
                ac.connect(self.mean2.y, self.rectangularToPolar.u_im),
                ac.connect(self.rectangularToPolar.y_abs, self.y_rms),
                ac.connect(self.sin1.y, self.product1.u[0]),
                ac.connect(self.u, self.product1.u[1]),
                ac.connect(self.u, self.product2.u[0]),
                ac.connect(self.sin2.y, self.product2.u[1]),
                ac.connect(self.rectangularToPolar.y_arg, self.gain.u),
                ac.connect(self.gain.y, self.y_arg)]


class TotalHarmonicDistortion(SISO):
    """The total harmonic distortion of u over each period 1/f (MSL
    Blocks.Math.TotalHarmonicDistortion): the RMS of u's harmonics other than the first,
    sqrt(RMS^2 - H1^2), over the first harmonic H1 (``useFirstHarmonic``, the default)
    or over the RMS (given when it is made):

        y = sqrt(RMS^2 - H1^2) / max(H1 or RMS, eps)

    The MSL's Boolean output ``valid`` (H1 > 0 and RMS >= H1) waits for Boolean
    signals; the switch between H1 and the RMS is the structural choice it is.
    """

    f = ac.Parameter(1.0, unit="Hz", description="base frequency")
    harmonic = Harmonic(f=ac.ref("f"), k=1.0, x0Cos=0.0, x0Sin=0.0)
    rootMeanSquare = RootMeanSquare(f=ac.ref("f"), x0=0.0)
    division = Division()
    limiter = Limiter(uMin=1e-15, uMax=float("inf"))
    pythagoras = Pythagoras(u1IsHypotenuse=True)

    def __init__(self, *, useFirstHarmonic: bool = True, **modifications):
        self.useFirstHarmonic = bool(useFirstHarmonic)
        super().__init__(**modifications)

    def equations(self):
        reference = self.harmonic.y_rms if self.useFirstHarmonic else self.rootMeanSquare.y
        return [ac.connect(self.u, self.rootMeanSquare.u), ac.connect(self.u, self.harmonic.u),
                ac.connect(self.division.y, self.y),
                ac.connect(self.pythagoras.u1, self.rootMeanSquare.y),
                ac.connect(self.pythagoras.y, self.division.u1),
                ac.connect(self.limiter.y, self.division.u2),
                ac.connect(self.harmonic.y_rms, self.pythagoras.u2),
                ac.connect(reference, self.limiter.u)]
