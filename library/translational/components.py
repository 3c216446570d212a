"""Translational components (Egeland & Gravdahl 2.1.2: the mass-spring-damper; the MSL's
hard stops)."""
from acausal._sympy import sympy as sp

import acausal as ac

from .interfaces import (PartialCompliant, PartialCompliantWithRelativeStates,
                         PartialElementaryOneFlange, PartialRigid, PartialTwoFlanges)

__all__ = ["Fixed", "Mass", "Rod", "Spring", "Damper", "SpringDamper", "ElastoGap",
           "MassWithStop"]


class Fixed(PartialElementaryOneFlange):
    """Flange fixed in the housing:  flange.s = s0."""

    s0 = ac.Parameter(0.0, unit="m", description="fixed position of the housing")

    energy_role = "lossless"  # the housing does not move

    def equations(self):
        return [ac.Eq(self.flange.s, self.s0)]


class Mass(PartialRigid):
    """Sliding mass with inertia (MSL Translational.Components.Mass), its centre at s and
    its flanges L/2 either side (``PartialRigid``):

        v = der(s),   a = der(v),   m a = flange_a.f + flange_b.f
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass of the sliding mass")
    v = ac.Variable(start=0.0, unit="m/s", description="absolute velocity")
    a = ac.Variable(unit="m/s2", description="absolute acceleration")

    def stored_energy(self):
        """Kinetic energy m v^2 / 2  (Egeland & Gravdahl (2.58))."""
        return self.m * self.v**2 / 2

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(self.m * self.a, self.flange_a.f + self.flange_b.f)]


class Rod(PartialRigid):
    """Rod without inertia (MSL Translational.Components.Rod), its centre at s and its
    flanges L/2 either side (``PartialRigid``):

        0 = flange_a.f + flange_b.f
    """

    energy_role = "lossless"  # rigid and massless

    def equations(self):
        return [ac.Eq(0, self.flange_a.f + self.flange_b.f)]


class Spring(PartialCompliant):
    """Linear spring:  f = c (s_rel - s_rel0)."""

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched length")

    def stored_energy(self):
        """c (s_rel - s_rel0)^2 / 2  (Egeland & Gravdahl (2.58))."""
        return self.c * (self.s_rel - self.s_rel0)**2 / 2

    def equations(self):
        return [ac.Eq(self.f, self.c * (self.s_rel - self.s_rel0))]


class Damper(PartialCompliantWithRelativeStates):
    """Linear damper (Egeland & Gravdahl (2.57); MSL Translational.Components.Damper):

        f = d v_rel,   lossPower = d v_rel^2

    ``Damper(stateSelect="prefer")`` makes s_rel and v_rel preferred states.
    """

    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")
    lossPower = ac.Variable(unit="W", description="power dissipated, d v_rel^2 >= 0")

    def loss_power(self):
        """lossPower = d v_rel^2  (Egeland & Gravdahl (2.60); the audit checks it against
        the port power f v_rel)."""
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.f, self.d * self.v_rel),
                ac.Eq(self.lossPower, self.d * self.v_rel**2)]


class SpringDamper(PartialCompliantWithRelativeStates):
    """Spring and damper in parallel (MSL Translational.Components.SpringDamper):

        f = c (s_rel - s_rel0) + d v_rel,   lossPower = d v_rel^2
    """

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched length")
    lossPower = ac.Variable(unit="W", description="power dissipated, d v_rel^2 >= 0")

    def stored_energy(self):
        """c (s_rel - s_rel0)^2 / 2."""
        return self.c * (self.s_rel - self.s_rel0)**2 / 2

    def loss_power(self):
        """lossPower = d v_rel^2."""
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.f, self.c * (self.s_rel - self.s_rel0) + self.d * self.v_rel),
                ac.Eq(self.lossPower, self.d * self.v_rel**2)]


class ElastoGap(PartialCompliantWithRelativeStates):
    """Spring and damper in parallel that act only when the gap is closed (MSL
    Translational.Components.ElastoGap), contact = s_rel < s_rel0:

        f_c = -c |s_rel - s_rel0|^n in contact, else 0          (spring, only pushes)
        f_d2 = d v_rel in contact, else 0                      (linear damping)
        f_d = f_d2 limited to [f_c, -f_c] in contact, else 0   (|f_d| <= |f_c|)
        f = f_c + f_d,   lossPower = f_d v_rel

    The damping force is limited by the spring force, so the contact force starts from
    zero, is continuous, and never pulls.  Entering and leaving contact are events; the
    limiting inside the contact is evaluated without events (the MSL's noEvent).
    """

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    d = ac.Parameter(1.0, unit="N.s/m", min=0, description="damping constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    n = ac.Parameter(1.0, min=1, description="exponent of the spring force, "
                                             "f_c = -c |s_rel - s_rel0|^n")
    unit_s = ac.Parameter(1.0, unit="m", min=0,
                          description="1 m: the unit of the gap in the power law")
    f_c = ac.Variable(unit="N", description="spring force")
    f_d2 = ac.Variable(unit="N", description="linear damping force")
    f_d = ac.Variable(unit="N", description="damping force limited by the spring force")
    lossPower = ac.Variable(unit="W", description="power dissipated, f_d v_rel >= 0")

    def contact(self):
        """Relation: the gap is closed."""
        return self.s_rel < self.s_rel0

    def stored_energy(self):
        """c |s_rel - s_rel0|^(n + 1) / (n + 1) in contact (in metres), 0 else."""
        # the gap in metres, > 0 in contact (1 elsewhere, where it is not used)
        gap = ac.if_else(self.contact(), (self.s_rel0 - self.s_rel) / self.unit_s, 1)
        return ac.if_else(self.contact(),
                          self.c * self.unit_s**2 * gap**(self.n + 1) / (self.n + 1), 0)

    def loss_power(self):
        return self.lossPower

    def equations(self):
        contact, f_c, f_d2 = self.contact(), self.f_c, self.f_d2
        # |s_rel - s_rel0| in metres, so that c |s_rel - s_rel0|^n is a force for any n
        gap = ac.no_event(ac.abs(self.s_rel - self.s_rel0)) / self.unit_s
        limited = ac.no_event(ac.min(ac.max(f_d2, f_c), -f_c))
        return [ac.Eq(f_c, ac.if_else(contact, -self.c * self.unit_s * gap**self.n, 0)),
                ac.Eq(f_d2, ac.if_else(contact, self.d * self.v_rel, 0)),
                ac.Eq(self.f_d, ac.if_else(contact, limited, 0)),
                ac.Eq(self.f, f_c + self.f_d),
                ac.Eq(self.lossPower, self.f_d * self.v_rel)]


class MassWithStop(PartialTwoFlanges):
    """Sliding mass between hard stops at s_min and s_max (the stops of the MSL's
    ``MassWithStopAndFriction``, without friction):

        s = flange_a.s = flange_b.s,   v = der(s),   m der(v) = f_app + f_stop
        f_app = flange_a.f + flange_b.f              (the force of the rest of the model)
        f_stop = -max(f_app, 0) at s_max,  -min(f_app, 0) at s_min,  0 in between

    Parameters
    ----------
    m : float
        Mass [kg].
    s_min, s_max : float
        Positions of the stops [m], s_min < s_max.
    e : float
        Coefficient of restitution (Newton's law of impact): a hit sets v to -e v.
        0 (the default) is a plastic impact: the mass comes to rest at the stop (and,
        being 0, a structural zero: give e at instantiation to use it).
    v_rest : float
        Rebound speed [m/s] below which a hit is plastic instead (see Notes).
    eps : float
        Width of the contact band inside each stop [m], see Notes.

    Notes
    -----
    At a stop the mass rests with v = 0 and der(v) = 0 exactly while the applied
    force pushes into the stop (the stop force is its reaction); it leaves, on the
    free motion, at the event where f_app changes sign.  The stops are rigid:
    reaching one is an event that reinitializes v, v+ = -e v- (Newton's impact law,
    e.g. Brogliato, *Nonsmooth Mechanics*, 1999; the MSL's ``MassWithStopAndFriction``
    stops the mass, e = 0).  Everything rigidly attached to the mass (masses,
    ideal gears) takes part in the impact with it, as the stop is fixed.

    With e > 0 and a force that keeps pushing, the rebounds shrink geometrically and
    accumulate in finite time (Zeno), which the simulator stops on; so a rebound
    slower than v_rest ends the bouncing: the mass is then put at rest on the stop.

    Contact is a band of width eps inside each stop: entering it is the impact, which
    also sets s to the stop exactly (a shift of at most eps); after a rebound s is
    put 2 eps inside the free range.  The band's relation is
    atan((s - s_max)/eps + 1) > 0 (mirrored at s_min), +-pi/4 at s = s_max and
    s_max - 2 eps, clearly non-zero for the event logic whatever eps (eps must be
    small against the stroke and above the round-off of s).
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    s_min = ac.Parameter(-1.0, unit="m", description="position of the lower stop")
    s_max = ac.Parameter(1.0, unit="m", description="position of the upper stop")
    e = ac.Parameter(0.0, min=0, max=1, description="coefficient of restitution")
    v_rest = ac.Parameter(1e-3, unit="m/s", min=0,
                          description="slowest rebound; slower hits are plastic")
    eps = ac.Parameter(1e-10, unit="m", min=0, description="width of the contact band")
    # states, because the impacts reinitialize them
    s = ac.Variable(start=0.0, unit="m", state_select="prefer", description="absolute position")
    v = ac.Variable(start=0.0, unit="m/s", state_select="prefer", description="absolute velocity")
    a = ac.Variable(unit="m/s2", description="absolute acceleration")
    f_app = ac.Variable(unit="N", description="force applied by the rest of the model")
    f_stop = ac.Variable(unit="N", description="force of the stops on the mass")

    def stored_energy(self):
        """m v^2 / 2; the rigid stops do no work (v = 0 in contact), impacts lose
        energy at events."""
        return self.m * self.v**2 / 2

    def at_max(self):
        """Relation: in the contact band at s_max."""
        return sp.atan((self.s - self.s_max) / self.eps + 1) > 0

    def at_min(self):
        """Relation: in the contact band at s_min."""
        return sp.atan((self.s_min - self.s) / self.eps + 1) > 0

    def equations(self):
        f, at_max, at_min = self.f_app, self.at_max(), self.at_min()
        stop = ac.if_else(at_max, ac.if_else(f > 0, -f, 0),
                          ac.if_else(at_min, ac.if_else(f < 0, -f, 0), 0))
        # 1 for a rebound, 0 for rest (a rebound slower than v_rest), on the speed just
        # before the hit: the step max(0, x)/max(|x|, tiny), because no_event() keeps
        # max and abs out of the zero crossings but not an if_else relation (that would
        # add an event at every v = +-v_rest/e), and sign() or Heaviside() have no
        # printable derivative for the generated Jacobian
        up = _step(self.e * ac.pre(self.v) - self.v_rest)
        down = _step(-self.e * ac.pre(self.v) - self.v_rest)
        return [ac.Eq(self.s, self.flange_a.s),
                ac.Eq(self.s, self.flange_b.s),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(self.f_app, self.flange_a.f + self.flange_b.f),
                ac.Eq(self.f_stop, stop),
                ac.Eq(self.m * self.a, self.f_app + self.f_stop),
                ac.when(at_max, ac.reinit(self.s, self.s_max - up * 2 * self.eps),
                        ac.reinit(self.v, -up * self.e * ac.pre(self.v))),
                ac.when(at_min, ac.reinit(self.s, self.s_min + down * 2 * self.eps),
                        ac.reinit(self.v, -down * self.e * ac.pre(self.v)))]


def _step(x):
    """1 for x > 0, else 0, evaluated directly (no event)."""
    return ac.no_event(sp.Max(0, x) / sp.Max(sp.Abs(x), 1e-300))
