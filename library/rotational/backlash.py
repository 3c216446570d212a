"""Gears and shafts with backlash (Modelica.Mechanics.Rotational.Components.ElastoBacklash,
ElastoBacklash2; Egeland & Gravdahl 3.6.2-3.6.3).

The elastic ones put the backlash in series with a spring and damper: the
MSL's ``ElastoBacklash`` (the damping torque limited by the spring torque, so the contact
torque starts from zero) and ``ElastoBacklash2`` (the torque may jump at the start of
contact), and the book's undamped ``ElasticGearWithDeadzone``.  ``GearWithBacklash`` is
the rigid gear whose flanks meet in plastic impacts.
"""
from acausal._sympy import sympy as sp

import acausal as ac

from .interfaces import PartialCompliantWithRelativeStates, PartialTwoFlanges

__all__ = ["ElastoBacklash", "ElastoBacklash2", "ElasticGearWithDeadzone",
           "GearWithBacklash"]

B_EPS = 1e-10
"""The smallest backlash [rad] (the MSL's bEps): below it the element is a spring-damper."""


class _PartialElastoBacklash(PartialCompliantWithRelativeStates):
    """The spring and damper of an elastic backlash, with phi_diff = phi_rel - phi_rel0
    and the backlash between bMin = -b/2 and bMax = b/2:

        tau_c = c phi_diff                 (b <= bEps: no backlash)
              = c (phi_diff - b/2)         phi_diff > b/2
              = c (phi_diff + b/2)         phi_diff < -b/2
              = 0                          in the backlash
        tau_d = d w_rel

    A subclass gives the flange torque ``tau`` and ``lossPower`` in contact
    (``contact_torque``, ``contact_loss``; each element returns its two sides).
    """

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant (c > 0)")
    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")
    b = ac.Parameter(0.0, unit="rad", min=0, description="total backlash")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")
    tau_c = ac.Variable(unit="N.m", description="spring torque")
    tau_d = ac.Variable(unit="N.m", description="damper torque d w_rel")
    lossPower = ac.Variable(unit="W", description="power dissipated, >= 0")

    def _branches(self, law_above, law_below, no_backlash, inside=0):
        """if b <= bEps: no_backlash, elif phi_diff > b/2: law_above, elif phi_diff <
        -b/2: law_below, else inside."""
        phi, half = self.phi_rel - self.phi_rel0, self.b / 2
        return ac.if_else(ac.abs(self.b) <= B_EPS, no_backlash,
                          ac.if_else(phi > half, law_above,
                                     ac.if_else(phi < -half, law_below, inside)))

    def stored_energy(self):
        """c (|phi_diff| - b/2)^2 / 2 in contact, 0 in the backlash."""
        phi, half = self.phi_rel - self.phi_rel0, self.b / 2
        return self._branches(self.c * (phi - half)**2 / 2, self.c * (phi + half)**2 / 2,
                              self.c * phi**2 / 2)

    def loss_power(self):
        return self.lossPower

    def equations(self):
        phi, half = self.phi_rel - self.phi_rel0, self.b / 2
        tau_c, tau_d = self.tau_c, self.tau_d
        (tau_above, tau_below), (loss_above, loss_below) = self.contact_laws()
        return [ac.Eq(tau_c, self._branches(self.c * (phi - half), self.c * (phi + half),
                                            self.c * phi)),
                ac.Eq(tau_d, self.d * self.w_rel),
                ac.Eq(self.tau, self._branches(tau_above, tau_below, tau_c + tau_d)),
                ac.Eq(self.lossPower, self._branches(loss_above, loss_below,
                                                     tau_d * self.w_rel))]


class ElastoBacklash(_PartialElastoBacklash):
    """Backlash in series with a spring and damper in parallel (MSL
    Rotational.Components.ElastoBacklash), with phi_diff = phi_rel - phi_rel0, tau_c
    and tau_d as in the base (the spring torque beyond the backlash b, d w_rel):

        tau = 0 in the backlash (|phi_diff| <= b/2); in contact above b/2
        tau = 0 if tau_c + tau_d <= 0 (it would pull: the teeth separate),
              else tau_c + min(tau_c, tau_d)          (mirrored below -b/2)
        lossPower = (tau - tau_c) w_rel

    The damping torque is limited by the spring torque, so the contact torque starts
    from 0 and never pulls.  lossPower is what the stored energy c (|phi_diff| - b/2)^2/2
    does not account for: the limited damping and, while the teeth separate with the
    spring still deflected, the spring energy that is released (the MSL books 0 there).
    Entering and leaving the backlash are events; the limiting inside the contact is
    evaluated without events (as the MSL's noEvent).  A backlash b <= 1e-10 rad is a
    spring-damper (as in the MSL).  The MSL's smoothed characteristic during
    initialization is not reproduced: give start values that fix the initial contact
    state.
    """

    def contact_laws(self):
        tau_c, tau_d, w = self.tau_c, self.tau_d, self.w_rel
        pushing = ac.no_event(ac.if_else(tau_c + tau_d <= 0, 0, tau_c + ac.min(tau_c, tau_d)))
        pulling = ac.no_event(ac.if_else(tau_c + tau_d >= 0, 0, tau_c + ac.max(tau_c, tau_d)))
        return (pushing, pulling), ((pushing - tau_c) * w, (pulling - tau_c) * w)


class ElastoBacklash2(_PartialElastoBacklash):
    """Backlash in series with a spring and damper in parallel, whose torque may jump
    at the start of contact (MSL Rotational.Components.ElastoBacklash2), with
    phi_diff = phi_rel - phi_rel0, tau_c and tau_d as in the base:

        tau = 0 in the backlash (|phi_diff| <= b/2); in contact above b/2
        tau = 0 if tau_c + tau_d <= 0 (the teeth separate), else tau_c + tau_d
        (mirrored below -b/2)
        lossPower = tau_d w_rel where tau = tau_c + tau_d, else -tau_c w_rel

    Unlike ``ElastoBacklash`` the damping torque is not limited: hitting the flank with
    a speed w_rel gives a torque d w_rel at once.  The sign of tau_c + tau_d is an event
    (the MSL writes it without noEvent).  lossPower counts, besides the damping, the
    spring energy released while the teeth separate with the spring still deflected
    (the MSL books 0 there); the audit's balance needs it.  A backlash b <= 1e-10 rad
    is a spring-damper.  The MSL's smoothed characteristic during initialization is not
    reproduced: give start values that fix the initial contact state.
    """

    def contact_laws(self):
        tau_c, tau_d, w = self.tau_c, self.tau_d, self.w_rel
        total = tau_c + tau_d
        pushing = ac.if_else(total <= 0, 0, total)
        pulling = ac.if_else(total >= 0, 0, total)
        return (pushing, pulling), ((pushing - tau_c) * w, (pulling - tau_c) * w)


class ElasticGearWithDeadzone(PartialTwoFlanges):
    """Elastic gear with backlash (dead zone) delta (Egeland & Gravdahl 3.6.2,
    (3.118)-(3.119)), motor on flange_a, load on flange_b:

        phi = flange_a.phi - n flange_b.phi
        tau = K (phi + delta)  if phi < -delta,   K (phi - delta)  if phi > delta,   else 0
        flange_a.tau = tau,   flange_b.tau = -n tau

    Here n = flange_a.phi / flange_b.phi as IdealGear's ratio; the book's ratio is 1/n
    (its phi = theta_m - theta_L/n_book, T_gL = T_gm/n_book).  The corners of the
    dead zone are events.
    """

    n = ac.Parameter(1.0, description="gear ratio flange_a.phi / flange_b.phi in contact")
    K = ac.Parameter(1.0e4, unit="N.m/rad", min=0, description="gear stiffness (motor side)")
    delta = ac.Parameter(0.01, unit="rad", min=0, description="half width of the dead zone")
    phi = ac.Variable(unit="rad", description="gear deflection, motor side")
    tau = ac.Variable(unit="N.m", description="gear torque on the motor side T_gm")

    def stored_energy(self):
        """K (|phi| - delta)^2 / 2 outside the dead zone, 0 inside."""
        phi, d = self.phi, self.delta
        return ac.if_else(phi > d, self.K * (phi - d)**2 / 2,
                          ac.if_else(phi < -d, self.K * (phi + d)**2 / 2, 0))

    def equations(self):
        phi, d = self.phi, self.delta
        law = ac.if_else(phi < -d, self.K * (phi + d),
                         ac.if_else(phi > d, self.K * (phi - d), 0))
        return [ac.Eq(phi, self.flange_a.phi - self.n * self.flange_b.phi),
                ac.Eq(self.tau, law),
                ac.Eq(self.flange_a.tau, self.tau),
                ac.Eq(self.flange_b.tau, -self.n * self.tau)]


class GearWithBacklash(PartialTwoFlanges):
    """Rigid ideal gear with backlash (a dead zone of total width 2 delta on the output
    side), motor on flange_a, load on flange_b (Egeland & Gravdahl 3.6.3,
    (3.120)-(3.124)).

    Parameters
    ----------
    n : float
        Gear ratio flange_a.phi / flange_b.phi in contact, as ``IdealGear.ratio``; the
        book's ratio is n_b = 1/n.
    delta : float
        Half width of the dead zone, measured on the output (flange_b) side [rad].
        The book measures it on the motor side: delta_book = n delta.
    J_a, J_b : float
        The inertias rigidly attached to flange_a and flange_b [kg m2] (through rigid
        couplings and ideal gears, reflected to the flange).  They enter only the
        impact law and the coordinates below, and must be those of the model (with
        other values the free and contact motions stay right, but impacts do not
        conserve the angular momentum).
    eps : float
        Width of the contact band [rad], see Notes.

    Notes
    -----
    With the relative angle on the output side and the torque tau that the gear
    exerts on the load::

        phi_rel = flange_b.phi - flange_a.phi / n,     -delta <= phi_rel <= delta
        flange_b.tau = -tau,   flange_a.tau = tau / n      (ideal gear, no losses)

    Free (|phi_rel| < delta, (3.120), (3.124)): tau = 0, each side moves on its own.
    Contact (phi_rel = -delta: the motor drives the load, tau >= 0; phi_rel = +delta:
    the load drives the motor or is braked by it, tau <= 0): the gear is rigid, (3.121),
    and motor and load move as one body with the inertia J_b + n^2 J_a on the load
    side (the book's J_m + n_b^2 J_L on the motor side, (3.12), (3.122)-(3.123)).
    The book's phi = theta_m - n_b theta_L is -n phi_rel here, so its (3.122) is the
    contact at phi_rel = +delta and (3.123) the one at phi_rel = -delta.

    The contact torque follows from the rest of the system, so it is found by a curve
    parameter sa [N m] (as for the MSL's friction elements):

        J_eff der(w_rel) = tau - sa,    1/J_eff = 1/J_b + 1/(n^2 J_a)
        tau = min(sa, 0) at +delta,   max(sa, 0) at -delta,   0 free

    With the stated inertias sa is the torque the contact would have to carry to keep
    w_rel = der(phi_rel) at zero: in contact tau = sa while it pushes into the
    contact and der(w_rel) = 0; once sa would pull, tau = 0 and the sides separate.
    The sign of sa is an event, so the release is located exactly.

    Impact law (the book gives none): plastic, as for rigid bodies meeting with a
    coefficient of restitution 0 (Newton's law of impact; Pfeiffer & Glocker,
    *Multibody Dynamics with Unilateral Contacts*, 1996; Brogliato, *Nonsmooth
    Mechanics*, 1999).  The impulse acts as +P on the load and -P/n on
    the motor, so the angular momentum on the load side

        L = n J_a w_a + J_b w_b = (n^2 J_a + J_b) w_c

    is conserved and the relative speed w_rel becomes 0; the kinetic energy of the
    relative motion, J_eff w_rel^2 / 2, is lost.  The states are phi_rel, w_rel and
    the inertia-weighted (centre-of-inertia) angle and speed phi_c, w_c, so the impact
    is reinit(w_rel, 0) with w_c unchanged.

    Contact is a band of width eps inside each end of the dead zone: entering it is
    the impact, which also sets phi_rel to +-delta exactly (phi_c unchanged, a shift
    of at most eps); a release leaves it with tau = 0, i.e. on the free motion.  The
    band's relation is atan((phi_rel - delta)/eps + 1) > 0 (at -delta mirrored),
    +-pi/4 at the ends of the band, so that it is clearly non-zero at the stop for
    the event logic whatever eps (requires eps << delta).

    Both flanges must carry inertia (J_a, J_b > 0) that the gear's states can move.
    Starting in contact with a contact torque of exactly zero at t0 (at rest on a
    flank with a motor torque that starts from 0) can fail the first step: give the
    torque a start time or a phase, as for an ideal diode at s = 0.
    """

    n = ac.Parameter(1.0, description="gear ratio flange_a.phi / flange_b.phi in contact")
    delta = ac.Parameter(0.01, unit="rad", min=0,
                         description="half width of the dead zone, output side")
    J_a = ac.Parameter(1.0, unit="kg.m2", min=0, description="inertia rigidly on flange_a")
    J_b = ac.Parameter(1.0, unit="kg.m2", min=0, description="inertia rigidly on flange_b")
    eps = ac.Parameter(1e-10, unit="rad", min=0, description="width of the contact band")
    # the four states: the impacts reinitialize phi_rel and w_rel and keep phi_c, w_c
    phi_rel = ac.Variable(start=0.0, unit="rad", state_select="prefer",
                          description="relative angle, output side")
    w_rel = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                        description="relative speed der(phi_rel)")
    a_rel = ac.Variable(unit="rad/s2", description="relative acceleration")
    phi_c = ac.Variable(start=0.0, unit="rad", state_select="prefer",
                        description="inertia-weighted angle (n J_a phi_a + J_b phi_b)/J_tot")
    w_c = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                      description="inertia-weighted speed, L / (n^2 J_a + J_b)")
    a_c = ac.Variable(unit="rad/s2", description="der(w_c)")
    tau = ac.Variable(unit="N.m", description="torque of the gear on the load (flange_b)")
    sa = ac.Variable(start=0.0, unit="N.m", description="curve parameter (contact torque)")

    energy_role = "lossless"  # rigid: tau w_rel = 0; impacts lose energy at events

    def upper(self):
        """Relation: in the contact band at phi_rel = +delta."""
        return sp.atan((self.phi_rel - self.delta) / self.eps + 1) > 0

    def lower(self):
        """Relation: in the contact band at phi_rel = -delta."""
        return sp.atan((-self.delta - self.phi_rel) / self.eps + 1) > 0

    def equations(self):
        n, sa = self.n, self.sa
        J_tot = n**2 * self.J_a + self.J_b
        J_eff = n**2 * self.J_a * self.J_b / J_tot
        upper, lower = self.upper(), self.lower()
        contact = ac.if_else(upper, ac.if_else(sa < 0, sa, 0),
                             ac.if_else(lower, ac.if_else(sa > 0, sa, 0), 0))
        return [ac.Eq(self.phi_rel, self.flange_b.phi - self.flange_a.phi / n),
                ac.Eq(self.w_rel, ac.der(self.phi_rel)),
                ac.Eq(self.a_rel, ac.der(self.w_rel)),
                ac.Eq(J_tot * self.phi_c,
                      n * self.J_a * self.flange_a.phi + self.J_b * self.flange_b.phi),
                ac.Eq(self.w_c, ac.der(self.phi_c)),
                ac.Eq(self.a_c, ac.der(self.w_c)),
                ac.Eq(J_eff * self.a_rel, self.tau - sa),
                ac.Eq(self.tau, contact),
                ac.Eq(self.flange_b.tau, -self.tau),
                ac.Eq(self.flange_a.tau, self.tau / n),
                # plastic impact: w_rel to 0 at constant momentum (w_c is not touched)
                ac.when(upper, ac.reinit(self.phi_rel, self.delta), ac.reinit(self.w_rel, 0)),
                ac.when(lower, ac.reinit(self.phi_rel, -self.delta), ac.reinit(self.w_rel, 0))]
