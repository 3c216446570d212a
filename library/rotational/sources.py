"""Torque, speed and angle sources (Modelica.Mechanics.Rotational.Sources).

A torque source drives its flange with ``flange.tau = -tau`` (the cut torque into the
source is minus the torque it exerts).  Speed and angle sources impose the motion of
their flange and take whatever torque that needs.  Every source acts against its
housing: ``useSupport=True`` gives it a ``support`` flange that takes the reaction
(support.tau = -flange.tau; a motor on a moving frame), and its speed and angle are
then relative to the support.  Without it the housing is fixed.
"""
import acausal as ac
from acausal.ports import RealInput

from ..blocks import signals
from ..friction.regularization import check_regularization, regularized_sign
from .interfaces import PartialElementaryOneFlangeAndSupport, PartialTwoFlanges

__all__ = ["ConstantTorque", "TorqueStep", "Torque", "Torque2", "LinearSpeedDependentTorque",
           "QuadraticSpeedDependentTorque", "SignTorque", "EddyCurrentTorque",
           "ConstantSpeed", "Speed", "Accelerate", "Position"]


class ConstantTorque(PartialElementaryOneFlangeAndSupport):
    """Constant torque driving the flange:  flange.tau = -tau_constant.

    (A positive torque accelerates the flange in the positive direction; the cut torque
    into the source is its negative.)
    """

    tau_constant = ac.Parameter(1.0, unit="N.m", description="driving torque")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.tau, -self.tau_constant)]


class TorqueStep(PartialElementaryOneFlangeAndSupport):
    """Torque step:  flange.tau = -(offsetTorque + (stepTorque if time >= startTime))."""

    stepTorque = ac.Parameter(1.0, unit="N.m", description="height of the step")
    offsetTorque = ac.Parameter(0.0, unit="N.m", description="torque before the step")
    startTime = ac.Parameter(0.0, unit="s", description="time of the step")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        tau = self.offsetTorque + signals.step(self.stepTorque, self.startTime)
        return [ac.Eq(self.flange.tau, -tau)]


class Torque(PartialElementaryOneFlangeAndSupport):
    """Torque set by a signal:  flange.tau = -tau."""

    tau = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.tau, -self.tau)]


class Torque2(PartialTwoFlanges):
    """A signal torque acting between two flanges (MSL Sources.Torque2), pushing
    flange_b forward and flange_a back:

        flange_a.tau = tau,   flange_b.tau = -tau
    """

    tau = RealInput()

    energy_role = "source"  # drives the flanges from outside the model

    def equations(self):
        return [ac.Eq(self.flange_a.tau, self.tau), ac.Eq(self.flange_b.tau, -self.tau)]


class _SpeedDependentTorque(PartialElementaryOneFlangeAndSupport):
    """tau = -flange.tau, a function of the speed w = der(flange.phi - phi_support);
    ``TorqueDirection=True`` (the MSL's default): the same direction of torque in both
    directions of rotation, else the torque changes sign with w."""

    tau_nominal = ac.Parameter(1.0, unit="N.m",
                               description="torque at w_nominal (negative: a load)")
    w_nominal = ac.Parameter(1.0, unit="rad/s", min=0, description="nominal speed")
    w = ac.Variable(unit="rad/s", description="speed of the flange (to support)")
    tau = ac.Variable(unit="N.m", description="accelerating torque at the flange")

    energy_role = "source"  # drives (or brakes) the flange from outside the model

    def __init__(self, *, TorqueDirection=True, **modifications):
        super().__init__(**modifications)
        if not isinstance(TorqueDirection, bool):
            raise ac.ModelError(f"{type(self).__name__}: TorqueDirection must be True or "
                                f"False, not {TorqueDirection!r}")
        object.__setattr__(self, "TorqueDirection", TorqueDirection)

    def law(self, x):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.w, ac.der(self.flange.phi - self.phi_support())),
                ac.Eq(self.tau, -self.flange.tau),
                ac.Eq(self.tau, self.tau_nominal * self.law(self.w / self.w_nominal))]


class LinearSpeedDependentTorque(_SpeedDependentTorque):
    """Torque linear in speed (MSL Sources.LinearSpeedDependentTorque):

        tau = tau_nominal |w / w_nominal|   (TorqueDirection=True)
        tau = tau_nominal w / w_nominal     (TorqueDirection=False)
    """

    def law(self, x):
        return ac.abs(x) if self.TorqueDirection else x


class QuadraticSpeedDependentTorque(_SpeedDependentTorque):
    """Torque quadratic in speed (MSL Sources.QuadraticSpeedDependentTorque), e.g. a fan
    or a pump as a load (tau_nominal < 0, TorqueDirection=False):

        tau = tau_nominal (w / w_nominal)^2             (TorqueDirection=True)
        tau = tau_nominal (w / w_nominal) |w / w_nominal|   (TorqueDirection=False)
    """

    def law(self, x):
        return x**2 if self.TorqueDirection else x * ac.abs(x)


class _PartialTorque(PartialElementaryOneFlangeAndSupport):
    """A torque acting at the flange against the support (MSL Interfaces.PartialTorque):

        phi = flange.phi - phi_support,   w = der(phi)
    """

    phi = ac.Variable(start=0.0, unit="rad", description="angle of the flange to the support")
    w = ac.Variable(start=0.0, unit="rad/s", description="speed of the flange to the support")

    def equations(self):
        return [ac.Eq(self.phi, self.flange.phi - self.phi_support()),
                ac.Eq(self.w, ac.der(self.phi))]


class SignTorque(_PartialTorque):
    """Constant torque changing sign with speed (MSL Sources.SignTorque), regularized
    below w0 (``reg``: "Exp" (the MSL's default), "Sine", "Linear" or "CoSine", see
    ``friction.regularization``):

        tau = -flange.tau = tau_nominal sgn_reg(w / w0)

    A negative tau_nominal is a load (Coulomb-like friction).
    """

    tau_nominal = ac.Parameter(1.0, unit="N.m",
                               description="nominal torque (negative: acting as a load)")
    w0 = ac.Parameter(0.1, unit="rad/s", min=0, description="regularization below w0 (> 0)")
    tau = ac.Variable(unit="N.m", description="accelerating torque at the flange")

    energy_role = "source"  # drives (or brakes) the flange from outside the model

    def __init__(self, *, reg="Exp", **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "reg", check_regularization(reg, type(self).__name__))

    def equations(self):
        return [ac.Eq(self.tau, -self.flange.tau),
                ac.Eq(self.tau, self.tau_nominal * regularized_sign(self.w, self.w0, self.reg))]


class EddyCurrentTorque(_PartialTorque):
    """Eddy current brake (MSL Sources.EddyCurrentTorque), always braking, its speed for
    the maximum torque rising with the temperature of its material:

        tau = flange.tau = 2 tau_nominal w_n / (1 + w_n^2),
        w_n = w / (w_nominal (1 + alpha (T - TRef))),
        alpha = alpha20 / (1 + alpha20 (TRef - 293.15 K))
        lossPower = tau w

    The temperature is the parameter ``T`` (the MSL's with useHeatPort = false; the
    heat port waits for conditional connectors in the language).
    """

    tau_nominal = ac.Parameter(1.0, unit="N.m", description="maximum torque (always braking)")
    w_nominal = ac.Parameter(1.0, unit="rad/s", min=0,
                             description="nominal speed (of the maximum torque) at TRef")
    TRef = ac.Parameter(293.15, unit="K", description="reference temperature")
    alpha20 = ac.Parameter(0.0, unit="1/K", description="temperature coefficient at 20 degC")
    T = ac.Parameter(293.15, unit="K", description="temperature of the brake")
    tau = ac.Variable(unit="N.m", description="braking torque, flange.tau")
    w_normalized = ac.Variable(description="relative speed w / w_nominal(T)")
    lossPower = ac.Variable(unit="W", description="power dissipated, tau w")

    def loss_power(self):
        return self.lossPower

    def equations(self):
        alpha = self.alpha20 / (1 + self.alpha20 * (self.TRef - 293.15))
        w_n = self.w_normalized
        return [ac.Eq(self.tau, self.flange.tau),
                ac.Eq(w_n, self.w / (self.w_nominal * (1 + alpha * (self.T - self.TRef)))),
                ac.Eq(self.tau, 2 * self.tau_nominal * w_n / (1 + w_n * w_n)),
                ac.Eq(self.lossPower, self.tau * self.w)]


class _SpeedSource(PartialElementaryOneFlangeAndSupport):
    """The flange's angle phi relative to the support (a state) and its speed
    w = der(phi)."""

    phi = ac.Variable(start=0.0, unit="rad", description="angle of the flange (to support)")
    w = ac.Variable(unit="rad/s", description="speed of the flange (to support)")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.phi, self.flange.phi - self.phi_support()),
                ac.Eq(self.w, ac.der(self.phi))]


class ConstantSpeed(_SpeedSource):
    """Flange turning at constant speed:  der(flange.phi - phi_support) = w_fixed."""

    w_fixed = ac.Parameter(1.0, unit="rad/s", description="imposed speed")

    def equations(self):
        return [ac.Eq(self.w, self.w_fixed)]


class Speed(_SpeedSource):
    """Flange speed set by a signal:  der(flange.phi - phi_support) = w_ref."""

    w_ref = RealInput()

    def equations(self):
        return [ac.Eq(self.w, self.w_ref)]


class Accelerate(_SpeedSource):
    """Flange acceleration set by a signal (MSL Sources.Accelerate), from the start
    values of phi and w (relative to the support):

        a = der(w) = a_ref
    """

    a_ref = RealInput()
    a = ac.Variable(unit="rad/s2", description="acceleration of the flange (to support)")

    def equations(self):
        return [ac.Eq(self.a, ac.der(self.w)),
                ac.Eq(self.a, self.a_ref)]


class Position(PartialElementaryOneFlangeAndSupport):
    """Flange angle set by a signal:  flange.phi - phi_support = phi_ref.

    Driving an inertia, this differentiates phi_ref twice (index reduction), so the
    signal must be twice differentiable in the model (a Sine, or a filtered reference);
    a step makes the torque impulsive.
    """

    phi_ref = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.phi - self.phi_support(), self.phi_ref)]
