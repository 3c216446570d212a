"""Ideal elements (Modelica.Electrical.Analog.Ideal, MSL v4.0.0): the ideal diode, the
ideal thyristors and the triac, the ideal transformer, short and idle branches.  The
ideal switches are in :mod:`.switches`, the ideal operational amplifiers in
:mod:`.opamps`, the AD and DA converters in :mod:`.converters`.

The ideal semiconductors are piecewise linear in a curve parameter s, as in the MSL
(:class:`~.interfaces.IdealSemiconductor`): their Boolean state ``off`` is given by an
equation evaluated at every event, whose relation ``s < 0`` is an event, so the number
of states stays the same.
"""
import acausal as ac
from acausal.ports import BooleanInput, NegativePin, PositivePin

from .basic import Capacitor, Resistor
from .interfaces import IdealSemiconductor, OnePort, TwoPort

__all__ = ["IdealDiode", "IdealThyristor", "IdealGTOThyristor", "IdealTriac",
           "IdealTransformer", "Short", "Idle"]


class IdealDiode(IdealSemiconductor):
    """Ideal diode (Modelica.Electrical.Analog.Ideal.IdealDiode, MSL v4.0.0):

        off = s < 0

    on the characteristic of :class:`~.interfaces.IdealSemiconductor`: conducting
    (s >= 0) a resistance Ron above the knee Vknee, blocking a conductance Goff.  Note: a
    circuit where s is exactly 0 at the start time and rising (a sine source with zero
    phase) does not start; give the source a phase or a start time.
    """

    def equations(self):
        return [ac.Eq(self.off, self.s < 0)]


class IdealThyristor(IdealSemiconductor):
    """Ideal thyristor (Modelica.Electrical.Analog.Ideal.IdealThyristor, MSL v4.0.0): an
    ideal diode that starts to conduct only when fired, and then conducts until its
    current reverses (s < 0), whatever ``fire`` does:

        off = s < 0 or pre(off) and not fire

    Give ``off`` its value before the start (``off={"start": True, "fixed": True}``, the
    MSL's ``off(start=true, fixed=true)``).
    """

    fire = BooleanInput()

    def equations(self):
        return [ac.Eq(self.off, (self.s < 0) | (ac.pre(self.off) & ~self.fire))]


class IdealGTOThyristor(IdealSemiconductor):
    """Ideal gate turn-off thyristor (Modelica.Electrical.Analog.Ideal.IdealGTOThyristor,
    MSL v4.0.0): an ideal diode that conducts only while fired:

        off = s < 0 or not fire
    """

    fire = BooleanInput()

    def equations(self):
        return [ac.Eq(self.off, (self.s < 0) | ~self.fire)]


class IdealTriac(ac.Component):
    """Ideal triac (Modelica.Electrical.Analog.Ideal.IdealTriac, MSL v4.0.0): two
    anti-parallel :class:`IdealThyristor` s fired by one gate ``fire1``, ``idealThyristor``
    from n to p and ``idealThyristor1`` from p to n, with a series R-C across them for the
    elimination of disturbances (``resistor`` Rdis, ``capacitor`` Cdis).  Ron, Goff and
    Vknee are the thyristors'.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed triac resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened triac conductance")
    Vknee = ac.Parameter(0.8, unit="V", min=0,
                         description="threshold voltage for positive and negative phase")
    Rdis = ac.Parameter(100.0, unit="Ohm", description="resistance of disturbance elimination")
    Cdis = ac.Parameter(0.005, unit="F", description="capacity of disturbance elimination")

    idealThyristor = IdealThyristor(Ron=ac.ref("Ron"), Goff=ac.ref("Goff"),
                                    Vknee=ac.ref("Vknee"))
    idealThyristor1 = IdealThyristor(Ron=ac.ref("Ron"), Goff=ac.ref("Goff"),
                                     Vknee=ac.ref("Vknee"))
    resistor = Resistor(R=ac.ref("Rdis"))
    capacitor = Capacitor(C=ac.ref("Cdis"))
    fire1 = BooleanInput()
    n = NegativePin()
    p = PositivePin()

    def equations(self):
        c = ac.connect
        return [c(self.idealThyristor.n, self.capacitor.n),
                c(self.capacitor.n, self.idealThyristor1.p),
                c(self.idealThyristor1.n, self.resistor.p),
                c(self.resistor.p, self.idealThyristor.p),
                c(self.resistor.n, self.capacitor.p),
                c(self.idealThyristor1.fire, self.fire1),
                c(self.idealThyristor.fire, self.fire1),
                c(self.n, self.idealThyristor.p),
                c(self.idealThyristor1.p, self.p)]


class IdealTransformer(TwoPort):
    """Ideal transformer core with or without magnetization (Modelica.Electrical.Analog.
    Ideal.IdealTransformer, MSL v4.0.0), turns ratio n = v1/v2:

        v1 = n v2,   im1 = i1 + i2/n
        im1 = 0                              (considerMagnetization = False: lossless)
        psim1 = Lm1 im1,   v1 = der(psim1)   (considerMagnetization = True)

    ``considerMagnetization`` is structural (it adds a state).
    """

    n = ac.Parameter(1.0, description="turns ratio primary:secondary voltage")
    considerMagnetization = ac.Parameter(False, structural=True,
                                         description="choice of considering magnetization")
    Lm1 = ac.Parameter(1.0, unit="H", description="magnetization inductance w.r.t. primary side")
    im1 = ac.Variable(unit="A", description="magnetization current w.r.t. primary side")

    def stored_energy(self):
        """W = Lm1 im1^2 / 2 (0 without magnetization: lossless)."""
        return self.Lm1 * self.im1**2 / 2 if self.considerMagnetization else 0

    def equations(self):
        if not self.considerMagnetization:
            magnetization = [ac.Eq(self.im1, 0)]
        else:
            magnetization = [ac.Eq(self.v1, self.Lm1 * ac.der(self.im1))]
        return [ac.Eq(self.im1, self.i1 + self.i2 / self.n), *magnetization,
                ac.Eq(self.v1, self.n * self.v2)]


class Short(OnePort):
    """Short cut branch (Modelica.Electrical.Analog.Ideal.Short):  v = 0."""

    energy_role = "lossless"  # v = 0

    def equations(self):
        return [ac.Eq(self.v, 0)]


class Idle(OnePort):
    """Idle branch (Modelica.Electrical.Analog.Ideal.Idle):  i = 0."""

    energy_role = "lossless"  # i = 0

    def equations(self):
        return [ac.Eq(self.i, 0)]
