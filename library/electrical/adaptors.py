"""Adaptors between pins and signals (Modelica.Electrical.Analog.Basic.
GeneralCurrentToVoltageAdaptor and GeneralVoltageToCurrentAdaptor, MSL v4.0.0, after
Modelica.Blocks.Interfaces.Adaptors): a one-port whose voltage and current are signals,
so that a circuit can be cut into input/output blocks (an FMU each) and joined again.

``use_pder`` and ``use_fder`` add the derivative outputs and inputs (keyword-only
constructor arguments, since they add ports).  A derivative output is the derivative of
its signal.  A derivative input is connected but does not enter the equations: the MSL
tells the tool through a function's derivative annotation to take it as the
derivative of the input, and here the compiler differentiates the input itself, which
gives the same value when the input and its derivative come from the same source (two
adaptors joined, as in the MSL's examples).
"""
import acausal as ac
from acausal.ports import NegativePin, PositivePin, RealInput, RealOutput

__all__ = ["GeneralCurrentToVoltageAdaptor", "GeneralVoltageToCurrentAdaptor"]


class _GeneralAdaptor(ac.Component):
    """The pins of an adaptor:  v = pin_p.v - pin_n.v,  i = pin_p.i,  pin_p.i + pin_n.i = 0."""

    pin_p = PositivePin()
    pin_n = NegativePin()
    v = ac.Variable(unit="V", description="voltage drop between the two pins (pin_p.v - pin_n.v)")
    i = ac.Variable(unit="A", description="current flowing from pin p to pin n")

    def __init__(self, *, use_pder=True, use_fder=True, **modifications):
        super().__init__(**modifications)
        for flag, value in (("use_pder", use_pder), ("use_fder", use_fder)):
            if not isinstance(value, bool):
                raise ac.ModelError(f"{type(self).__name__}: {flag} must be True or False, "
                                    f"not {value!r}")
            object.__setattr__(self, flag, value)
        self.add_ports()

    def add_ports(self):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.v, self.pin_p.v - self.pin_n.v), ac.Eq(self.i, self.pin_p.i),
                ac.Eq(0, self.pin_p.i + self.pin_n.i)]


class GeneralCurrentToVoltageAdaptor(_GeneralAdaptor):
    """Current in, voltage out (MSL GeneralCurrentToVoltageAdaptor): the pins take the
    current ``f`` and give their voltage as ``p``,

        i = f,   p = v,   pder = der(p)   (use_pder)

    (``fder``, with use_fder, is the derivative of f: see the module docstring.)
    """

    p = RealOutput()
    f = RealInput()

    def add_ports(self):
        if self.use_pder:
            self.pder = RealOutput()
        if self.use_fder:
            self.fder = RealInput()

    def equations(self):
        derivative = [ac.Eq(self.pder, ac.der(self.v))] if self.use_pder else []
        return [ac.Eq(self.p, self.v), ac.Eq(self.i, self.f), *derivative]


class GeneralVoltageToCurrentAdaptor(_GeneralAdaptor):
    """Voltage in, current out (MSL GeneralVoltageToCurrentAdaptor): the pins take the
    voltage ``p`` and give the current out of pin_p as ``f``,

        v = p,   f = -i,   fder = der(f)   (use_fder)

    (``pder``, with use_pder, is the derivative of p: see the module docstring.)
    """

    p = RealInput()
    f = RealOutput()

    def add_ports(self):
        if self.use_pder:
            self.pder = RealInput()
        if self.use_fder:
            self.fder = RealOutput()

    def equations(self):
        derivative = [ac.Eq(self.fder, -ac.der(self.i))] if self.use_fder else []
        return [ac.Eq(self.v, self.p), ac.Eq(self.f, -self.i), *derivative]
