"""Clutch and Brake: friction pressed by a normal force that a signal sets
(Modelica.Mechanics.Rotational.Components.Clutch, Brake), on the stick-slip machinery
of Karnopp's friction model (``acausal.library.friction``).
"""
import acausal as ac
from acausal.ports import RealInput

from ..friction._models import _Karnopp
from ..friction.interfaces import PartialRotationalFriction
from .interfaces import PartialElementaryTwoFlangesAndSupport

__all__ = ["Clutch", "Brake"]


class _PressedFriction(_Karnopp):
    """Karnopp's friction levels proportional to a normal force fn set by the signal
    f_normalized: sliding mu cgeo fn, static peak mu cgeo fn."""

    mu = ac.Parameter(0.5, min=0, description="coefficient of sliding friction")
    peak = ac.Parameter(1.1, min=1, description="static / sliding friction at w = 0")
    cgeo = ac.Parameter(1.0, unit="m", min=0,
                        description="geometry constant: mean radius x number of surfaces")
    fn_max = ac.Parameter(1.0, unit="N", min=0, description="normal force at f_normalized = 1")
    v_s = ac.Parameter(1e-3, unit="rad/s", min=0,
                       description="slip speed over which static friction decays")
    dv = ac.Parameter(1e-6, unit="rad/s", min=0, description="half width of the sticking band")
    f_normalized = RealInput()
    fn = ac.Variable(unit="N", description="normal force")
    a = ac.Variable(unit="rad/s2", description="slip acceleration")
    sa = ac.Variable(start=0.0, description="curve parameter (applied torque when stuck)")

    @property
    def F_c(self):
        return self.mu * self.cgeo * self.fn

    @property
    def F_s(self):
        return self.peak * self.F_c

    F_v = 0

    def loss_power(self):
        """tau w >= 0: friction opposes the slip (stuck: w = 0)."""
        return self.tau * self.w

    def pressed(self):
        return [ac.Eq(self.fn, self.fn_max * ac.max(self.f_normalized.signal, 0)),
                *self.law(self.w, self.tau)]


class Clutch(_PressedFriction, PartialRotationalFriction):
    """Dry-friction clutch between flange_a and flange_b (MSL Clutch, with a constant
    coefficient of friction instead of the MSL's table mu(w)):

        fn = fn_max max(f_normalized, 0)                       (normal force)
        sliding (|w| >= dv):  tau = cgeo fn mu_level(w) sgn(w),
            mu_level(w) = mu + (peak - 1) mu exp(-(w/v_s)^2)
        stuck   (|w| <  dv):  tau = sat(torque applied by the rest, peak mu cgeo fn)

    w = der(phi_rel) is the slip speed; the clutch sticks (w = 0 exactly, an event)
    when the slip speed reaches the band and breaks away when the torque it must carry
    exceeds peak mu cgeo fn (see ``KarnoppFriction``; the sticking event sets the slip
    speed from the band's edge to 0, so it changes a speed by at most dv).  With
    f_normalized = 0 the clutch is open (no torque).
    """

    def equations(self):
        return [*super().equations(), *self.pressed()]


class Brake(_PressedFriction, PartialElementaryTwoFlangesAndSupport):
    """Brake on a shaft (MSL Components.Brake): flange_a and flange_b are one rigid
    shaft, braked against the housing (fixed, or the ``support`` flange with
    ``useSupport=True``) with the law of ``Clutch``:

        flange_a.phi = flange_b.phi,   w = der(flange_a.phi - phi_support)
        tau = flange_a.tau + flange_b.tau       (the friction torque, against w)
    """

    w = ac.Variable(start=0.0, unit="rad/s", description="speed of the shaft to its housing")
    tau = ac.Variable(unit="N.m", description="friction torque taken from the shaft")

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.flange_a.phi, self.flange_b.phi),
                ac.Eq(self.w, ac.der(self.flange_a.phi - self.phi_support())),
                ac.Eq(self.tau, self.flange_a.tau + self.flange_b.tau),
                *self.pressed()]
