"""Force, speed and position sources (Modelica.Mechanics.Translational.Sources).

A force source pushes its flange in +s with ``flange.f = -f``; speed and position
sources impose the motion of their flange and take whatever force that needs.  Every
source acts against its housing: ``useSupport=True`` gives it a ``support`` flange that
takes the reaction (support.f = -flange.f), and its position and speed are then
relative to the support.  Without it the housing is fixed.
"""
import acausal as ac
from acausal.ports import RealInput

from ..blocks import signals
from ..friction.regularization import check_regularization, regularized_sign
from .interfaces import PartialElementaryOneFlangeAndSupport, PartialTwoFlanges

__all__ = ["ConstantForce", "ForceStep", "Force", "Force2", "LinearSpeedDependentForce",
           "QuadraticSpeedDependentForce", "SignForce", "EddyCurrentForce", "ConstantSpeed",
           "Speed", "Accelerate", "Position"]


class ConstantForce(PartialElementaryOneFlangeAndSupport):
    """Constant force pushing the flange in +s:  flange.f = -f_constant."""

    f_constant = ac.Parameter(1.0, unit="N", description="driving force")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.f, -self.f_constant)]


class ForceStep(PartialElementaryOneFlangeAndSupport):
    """Force step:  flange.f = -(offsetForce + (stepForce if time >= startTime else 0))."""

    stepForce = ac.Parameter(1.0, unit="N", description="height of the step")
    offsetForce = ac.Parameter(0.0, unit="N", description="force before the step")
    startTime = ac.Parameter(0.0, unit="s", description="time of the step")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        f = self.offsetForce + signals.step(self.stepForce, self.startTime)
        return [ac.Eq(self.flange.f, -f)]


class Force(PartialElementaryOneFlangeAndSupport):
    """Force set by a signal:  flange.f = -f."""

    f = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.f, -self.f)]


class Force2(PartialTwoFlanges):
    """A signal force acting between two flanges (MSL Sources.Force2), pushing flange_b
    forward and flange_a back:

        flange_a.f = f,   flange_b.f = -f
    """

    f = RealInput()

    energy_role = "source"  # drives the flanges from outside the model

    def equations(self):
        return [ac.Eq(self.flange_a.f, self.f), ac.Eq(self.flange_b.f, -self.f)]


class _SpeedDependentForce(PartialElementaryOneFlangeAndSupport):
    """f = -flange.f, a function of the speed v = der(flange.s - s_support);
    ``ForceDirection=True`` (the MSL's default): the same direction of force in both
    directions of motion, else the force changes sign with v."""

    f_nominal = ac.Parameter(1.0, unit="N", description="force at v_nominal (negative: a load)")
    v_nominal = ac.Parameter(1.0, unit="m/s", min=0, description="nominal speed")
    v = ac.Variable(unit="m/s", description="speed of the flange (to support)")
    f = ac.Variable(unit="N", description="accelerating force at the flange")

    energy_role = "source"  # drives (or brakes) the flange from outside the model

    def __init__(self, *, ForceDirection=True, **modifications):
        super().__init__(**modifications)
        if not isinstance(ForceDirection, bool):
            raise ac.ModelError(f"{type(self).__name__}: ForceDirection must be True or "
                                f"False, not {ForceDirection!r}")
        object.__setattr__(self, "ForceDirection", ForceDirection)

    def law(self, x):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.flange.s - self.s_support())),
                ac.Eq(self.f, -self.flange.f),
                ac.Eq(self.f, self.f_nominal * self.law(self.v / self.v_nominal))]


class LinearSpeedDependentForce(_SpeedDependentForce):
    """Force linear in speed (MSL Sources.LinearSpeedDependentForce):

        f = f_nominal |v / v_nominal|   (ForceDirection=True)
        f = f_nominal v / v_nominal     (ForceDirection=False)
    """

    def law(self, x):
        return ac.abs(x) if self.ForceDirection else x


class QuadraticSpeedDependentForce(_SpeedDependentForce):
    """Force quadratic in speed (MSL Sources.QuadraticSpeedDependentForce), e.g. the
    air drag of a vehicle (f_nominal < 0, ForceDirection=False):

        f = f_nominal (v / v_nominal)^2               (ForceDirection=True)
        f = f_nominal (v / v_nominal) |v / v_nominal|   (ForceDirection=False)
    """

    def law(self, x):
        return x**2 if self.ForceDirection else x * ac.abs(x)


class _PartialForce(PartialElementaryOneFlangeAndSupport):
    """A force acting at the flange against the support (MSL Interfaces.PartialForce,
    whose f = flange.f):

        s = flange.s - s_support,   v = der(s),   f = flange.f
    """

    s = ac.Variable(start=0.0, unit="m", description="position of the flange to the support")
    v = ac.Variable(start=0.0, unit="m/s", description="velocity of the flange to the support")
    f = ac.Variable(unit="N", description="force at the flange, flange.f")

    def equations(self):
        return [ac.Eq(self.s, self.flange.s - self.s_support()),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.f, self.flange.f)]


class SignForce(_PartialForce):
    """Constant force changing sign with speed (MSL Sources.SignForce), regularized below
    v0 (``reg``: "Exp" (the MSL's default), "Sine", "Linear" or "CoSine", see
    ``friction.regularization``); with f = flange.f:

        f = -f_nominal sgn_reg(v / v0)      (pushing the flange with f_nominal sgn(v))

    A negative f_nominal is a load (Coulomb-like friction).
    """

    f_nominal = ac.Parameter(1.0, unit="N",
                             description="nominal force (negative: acting as a load)")
    v0 = ac.Parameter(0.1, unit="m/s", min=0, description="regularization below v0 (> 0)")

    energy_role = "source"  # drives (or brakes) the flange from outside the model

    def __init__(self, *, reg="Exp", **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "reg", check_regularization(reg, type(self).__name__))

    def equations(self):
        return [ac.Eq(self.f, -self.f_nominal * regularized_sign(self.v, self.v0, self.reg))]


class EddyCurrentForce(_PartialForce):
    """Translational eddy current brake (MSL Sources.EddyCurrentForce), always braking,
    its speed for the maximum force rising with the temperature of its material; with
    f = flange.f:

        f = 2 f_nominal v_n / (1 + v_n^2),
        v_n = v / (v_nominal (1 + alpha (T - TRef))),
        alpha = alpha20 / (1 + alpha20 (TRef - 293.15 K))
        lossPower = f v

    The temperature is the parameter ``T`` (the MSL's with useHeatPort = false; the
    heat port waits for conditional connectors in the language).
    """

    f_nominal = ac.Parameter(1.0, unit="N", description="maximum force (always braking)")
    v_nominal = ac.Parameter(1.0, unit="m/s", min=0,
                             description="nominal speed (of the maximum force) at TRef")
    TRef = ac.Parameter(293.15, unit="K", description="reference temperature")
    alpha20 = ac.Parameter(0.0, unit="1/K", description="temperature coefficient at 20 degC")
    T = ac.Parameter(293.15, unit="K", description="temperature of the brake")
    v_normalized = ac.Variable(description="relative speed v / v_nominal(T)")
    lossPower = ac.Variable(unit="W", description="power dissipated, f v")

    def loss_power(self):
        return self.lossPower

    def equations(self):
        alpha = self.alpha20 / (1 + self.alpha20 * (self.TRef - 293.15))
        v_n = self.v_normalized
        return [ac.Eq(v_n, self.v / (self.v_nominal * (1 + alpha * (self.T - self.TRef)))),
                ac.Eq(self.f, 2 * self.f_nominal * v_n / (1 + v_n * v_n)),
                ac.Eq(self.lossPower, self.f * self.v)]


class _SpeedSource(PartialElementaryOneFlangeAndSupport):
    """The flange's position s relative to the support (a state) and its speed
    v = der(s)."""

    s = ac.Variable(start=0.0, unit="m", description="position of the flange (to support)")
    v = ac.Variable(unit="m/s", description="speed of the flange (to support)")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.s, self.flange.s - self.s_support()),
                ac.Eq(self.v, ac.der(self.s))]


class ConstantSpeed(_SpeedSource):
    """Flange moving at constant speed:  der(flange.s - s_support) = v_fixed."""

    v_fixed = ac.Parameter(1.0, unit="m/s", description="imposed speed")

    def equations(self):
        return [ac.Eq(self.v, self.v_fixed)]


class Speed(_SpeedSource):
    """Flange speed set by a signal:  der(flange.s - s_support) = v_ref."""

    v_ref = RealInput()

    def equations(self):
        return [ac.Eq(self.v, self.v_ref)]


class Accelerate(_SpeedSource):
    """Flange acceleration set by a signal (MSL Sources.Accelerate), from the start
    values of s and v (relative to the support):

        a = der(v) = a_ref
    """

    a_ref = RealInput()
    a = ac.Variable(unit="m/s2", description="acceleration of the flange (to support)")

    def equations(self):
        return [ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(self.a, self.a_ref)]


class Position(PartialElementaryOneFlangeAndSupport):
    """Flange position set by a signal:  flange.s - s_support = s_ref.

    Driving a mass, this differentiates s_ref twice (index reduction): the signal must
    be twice differentiable in the model.
    """

    s_ref = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.s - self.s_support(), self.s_ref)]
