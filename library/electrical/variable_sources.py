"""Sources driven by signals (Modelica.Electrical.Analog.Sources, MSL v4.0.0): the
signal voltage and current, the sine and cosine sources of variable frequency and
amplitude, and the supply voltage pair.

As in the MSL, ``useConstantAmplitude`` and ``useConstantFrequency`` decide whether the
amplitude and the frequency are parameters or ``RealInput`` s; each is a keyword-only
constructor argument, since it adds or removes a port
(``SineVoltageVariableFrequencyAndAmplitude(useConstantAmplitude=True)`` has the input
``f`` only).
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import NegativePin, PositivePin, RealInput

from .interfaces import OnePort
from .sources import ConstantVoltage

__all__ = ["SignalVoltage", "SignalCurrent", "SineVoltageVariableFrequencyAndAmplitude",
           "CosineVoltageVariableFrequencyAndAmplitude",
           "SineCurrentVariableFrequencyAndAmplitude",
           "CosineCurrentVariableFrequencyAndAmplitude", "SupplyVoltage"]


class SignalVoltage(ac.Component):
    """Voltage set by a signal (MSL SignalVoltage); the input ``v`` is the voltage:

        v = p.v - n.v,   0 = p.i + n.i,   i = p.i
    """

    p = PositivePin()
    n = NegativePin()
    v = RealInput()
    i = ac.Variable(unit="A", description="current flowing from pin p to pin n")

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.v, self.p.v - self.n.v), ac.Eq(0, self.p.i + self.n.i),
                ac.Eq(self.i, self.p.i)]


class SignalCurrent(ac.Component):
    """Current set by a signal (MSL SignalCurrent); the input ``i`` is the current from
    p to n through the source, so it leaves by pin n:

        v = p.v - n.v,   0 = p.i + n.i,   i = p.i
    """

    p = PositivePin()
    n = NegativePin()
    i = RealInput()
    v = ac.Variable(unit="V", description="voltage drop between the two pins (p.v - n.v)")

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.v, self.p.v - self.n.v), ac.Eq(0, self.p.i + self.n.i),
                ac.Eq(self.i, self.p.i)]


class _VariableFrequencyAndAmplitude(OnePort):
    """A sine or cosine whose phase integrates the frequency:

        der(phi) = 2 pi f,   value = offset + amplitude wave(phi)

    (the amplitude and f are inputs, or the parameters constantAmplitude and
    constantFrequency).  ``_amplitude`` names the amplitude input (V or I), ``_unit``
    its unit, ``_quantity`` the one-port variable it sets, ``_wave`` sin or cos.
    """

    _amplitude = _unit = _quantity = None
    _wave = staticmethod(sp.sin)

    constantFrequency = ac.Parameter(1.0, unit="Hz", description="constant frequency")
    phi = ac.Variable(start=0.0, unit="rad", description="phase of the sine wave")

    energy_role = "source"  # delivers -v i

    def __init__(self, *, useConstantAmplitude=False, useConstantFrequency=False,
                 **modifications):
        super().__init__(**modifications)
        for flag, value in (("useConstantAmplitude", useConstantAmplitude),
                            ("useConstantFrequency", useConstantFrequency)):
            if not isinstance(value, bool):
                raise ac.ModelError(f"{type(self).__name__}: {flag} must be True or False, "
                                    f"not {value!r}")
            object.__setattr__(self, flag, value)
        if not useConstantAmplitude:
            setattr(self, self._amplitude, RealInput())
        if not useConstantFrequency:
            self.f = RealInput()

    def equations(self):
        amplitude = (self.constantAmplitude if self.useConstantAmplitude
                     else getattr(self, self._amplitude).signal)
        f = self.constantFrequency if self.useConstantFrequency else self.f.signal
        return [ac.Eq(ac.der(self.phi), 2 * sp.pi * f),
                ac.Eq(getattr(self, self._quantity),
                      self.offset + amplitude * self._wave(self.phi))]


class SineVoltageVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    """Sine voltage of variable frequency and amplitude (MSL
    SineVoltageVariableFrequencyAndAmplitude):

        der(phi) = 2 pi f,   v = offset + V sin(phi)
    """

    _amplitude, _quantity = "V", "v"
    constantAmplitude = ac.Parameter(1.0, unit="V", description="constant amplitude")
    offset = ac.Parameter(0.0, unit="V", description="offset of the sine wave")


class CosineVoltageVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    """Cosine voltage of variable frequency and amplitude (MSL
    CosineVoltageVariableFrequencyAndAmplitude):

        der(phi) = 2 pi f,   v = offset + V cos(phi)
    """

    _amplitude, _quantity = "V", "v"
    _wave = staticmethod(sp.cos)
    constantAmplitude = ac.Parameter(1.0, unit="V", description="constant amplitude")
    offset = ac.Parameter(0.0, unit="V", description="offset of the cosine wave")


class SineCurrentVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    """Sine current of variable frequency and amplitude (MSL
    SineCurrentVariableFrequencyAndAmplitude):

        der(phi) = 2 pi f,   i = offset + I sin(phi)
    """

    _amplitude, _quantity = "I", "i"
    constantAmplitude = ac.Parameter(1.0, unit="A", description="constant amplitude")
    offset = ac.Parameter(0.0, unit="A", description="offset of the sine wave")


class CosineCurrentVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    """Cosine current of variable frequency and amplitude (MSL
    CosineCurrentVariableFrequencyAndAmplitude):

        der(phi) = 2 pi f,   i = offset + I cos(phi)
    """

    _amplitude, _quantity = "I", "i"
    _wave = staticmethod(sp.cos)
    constantAmplitude = ac.Parameter(1.0, unit="A", description="constant amplitude")
    offset = ac.Parameter(0.0, unit="A", description="offset of the cosine wave")


class SupplyVoltage(ac.Component):
    """Positive and negative supply (MSL SupplyVoltage): two constant voltages in series
    about the middle pin ``ground``:

        pin_p.v - ground.v = Vps,   pin_n.v - ground.v = Vns
    """

    Vps = ac.Parameter(15.0, unit="V", description="positive supply")
    Vns = ac.Parameter(-15.0, unit="V", description="negative supply")
    pin_p = PositivePin()
    pin_n = NegativePin()
    ground = NegativePin()
    positiveSupply = ConstantVoltage(V=ac.ref("Vps"))
    negativeSupply = ConstantVoltage(V=ac.ref("Vns"))

    def equations(self):
        # the MSL writes negativeSupply(V = -Vns) from ground to pin_n: the same branch
        return [ac.connect(self.pin_p, self.positiveSupply.p),
                ac.connect(self.negativeSupply.p, self.pin_n),
                ac.connect(self.positiveSupply.n, self.ground),
                ac.connect(self.ground, self.negativeSupply.n)]
