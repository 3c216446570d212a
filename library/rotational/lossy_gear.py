"""A gear with mesh efficiency and bearing friction that can lock
(Modelica.Mechanics.Rotational.Components.LossyGear; Pelchen, Schweiger & Otter,
*Modeling and simulating the efficiency of gearboxes and of planetary gearboxes*,
2nd International Modelica Conference, 2002, with the fix of Bertsch, 2009).
"""
from __future__ import annotations

import numpy as np

import acausal as ac
from acausal.library.thermal.conditional import PartialElementaryConditionalHeatPortWithoutT

from ..friction.modes import FrictionModes, check_speed_column, table_at_zero, table_value
from .friction_modes import PartialFriction
from .interfaces import PartialElementaryTwoFlangesAndSupport

__all__ = ["LossyGear"]

_EPS = 2.220446049250313e-16          # Modelica.Constants.eps
_IDEAL = np.array([[0.0, 1.0, 1.0, 0.0, 0.0]])


def loss_table(table, owner: str) -> np.ndarray:
    """``lossTable`` as a checked (n x 5) array: rows [|w_a|, eta_mf1, eta_mf2, |tau_bf1|,
    |tau_bf2|], |w_a| >= 0 increasing, efficiencies > 0."""
    try:
        data = np.array(table, dtype=float)
    except (TypeError, ValueError):
        raise ac.InvalidValue(f"{owner}: lossTable must be rows [w_a, eta_mf1, eta_mf2, "
                              f"tau_bf1, tau_bf2] of numbers, got {table!r}") from None
    if data.ndim == 1 and data.size == 5:
        data = data.reshape(1, 5)
    if data.ndim != 2 or data.shape[1] != 5 or data.shape[0] < 1:
        raise ac.InvalidValue(f"{owner}: lossTable must be rows [w_a, eta_mf1, eta_mf2, "
                              f"tau_bf1, tau_bf2] (n x 5), got shape {data.shape}")
    check_speed_column(data, owner, "lossTable", "|w_a|")
    eta = data[:, 1:3]
    if (eta <= 0).any():
        k = int(np.argmax((eta <= 0).any(axis=1)))
        raise ac.InvalidValue(f"{owner}: lossTable row {k + 1}: a mesh efficiency "
                              f"{eta[k].min()} <= 0 (eta_mf1 and eta_mf2 must be > 0)")
    return data


class LossyGear(PartialFriction, PartialElementaryTwoFlangesAndSupport,
                PartialElementaryConditionalHeatPortWithoutT):
    """Gear with mesh efficiency and bearing friction, stuck or rolling (MSL
    Rotational.Components.LossyGear), the angles taken from its housing:

        phi_a = flange_a.phi - phi_support,   phi_b = flange_b.phi - phi_support
        phi_a = ratio phi_b,   w_a = der(phi_a),   a_a = der(w_a)
        0 = flange_b.tau + ratio (flange_a.tau - tauLoss),   lossPower = tauLoss w_a

    The losses, from ``lossTable`` rows [|w_a|, eta_mf1, eta_mf2, |tau_bf1|, |tau_bf2|]
    (interpolated linearly in |w_a|; eta_mf1 the mesh efficiency when flange_a drives,
    eta_mf2 when flange_b drives, tau_bf1/2 the resultant bearing friction on the
    flange_a side in those cases), in the four quadrants of (w_a, tau_eta):

        quadrant1 = (1 - eta_mf1) flange_a.tau + tau_bf1     w_a > 0, tau_eta >= 0
        quadrant2 = (1 - 1/eta_mf2) flange_a.tau + tau_bf2   w_a > 0, tau_eta < 0
        quadrant4 = (1 - 1/eta_mf2) flange_a.tau - tau_bf2   w_a < 0, tau_eta >= 0
        quadrant3 = (1 - eta_mf1) flange_a.tau - tau_bf1     w_a < 0, tau_eta < 0

    tau_eta = flange_a.tau -+ tau_bf_a decides which side drives (tau_bf_a the bearing
    friction of the flange_a side, (tau_bf1 - tau_bf2)/(eta_mf1 - 1/eta_mf2), or
    tau_bf1/2 where both efficiencies are 1).  The gear is a friction element of the
    speed w_a (``friction.modes``): rolling forward tauLoss = quadrant1 or 2, backward
    quadrant4 or 3; locked (a_a = 0) tauLoss is what the torque balance needs, and it
    starts to roll forward when that exceeds tauLossMax_p (the forward loss at w_a = 0+
    with the table's values at 0), backward below tauLossMin_m.  So a gear of low
    efficiency that the load drives backwards stays stuck (self-locking).

    ``lossTable`` is given where the gear is made (a table, as the MSL's parameter
    array); the ideal table [0, 1, 1, 0, 0] (the default) has no losses and no modes.
    ``useHeatPort=True``: lossPower leaves through ``heatPort``.
    """

    ratio = ac.Parameter(1.0, description="transmission ratio flange_a.phi / flange_b.phi")
    phi_a = ac.Variable(start=0.0, unit="rad", description="angle of flange_a to the support")
    phi_b = ac.Variable(start=0.0, unit="rad", description="angle of flange_b to the support")
    w_a = ac.Variable(start=0.0, unit="rad/s",
                      description="speed of flange_a to the support")
    a_a = ac.Variable(unit="rad/s2", description="acceleration of flange_a to the support")
    tauLoss = ac.Variable(unit="N.m", description="torque loss of the teeth and bearings")
    lossPower = ac.Variable(unit="W", description="power dissipated, tauLoss w_a")

    def __init__(self, lossTable=((0.0, 1.0, 1.0, 0.0, 0.0),), *, useSupport=False, **mods):
        super().__init__(useSupport=useSupport, **mods)
        data = loss_table(lossTable, type(self).__name__)
        object.__setattr__(self, "lossTable", data)
        object.__setattr__(self, "ideal", data.shape == _IDEAL.shape
                           and bool(np.all(np.abs(data - _IDEAL) <= _EPS)))

    # -- the friction element of the speed w_a ------------------------------------------
    @property
    def w_relfric(self):
        return self.w_a

    @property
    def a_relfric(self):
        return self.a_a

    @property
    def tau(self):
        return self.tauLoss

    def _at_rest(self):
        """eta_mf1, eta_mf2, |tau_bf1|, |tau_bf2| and tau_bf_a at w_a = 0 (numbers)."""
        eta1, eta2 = (table_at_zero(self.lossTable, k) for k in (1, 2))
        bf1, bf2 = (abs(table_at_zero(self.lossTable, k)) for k in (3, 4))
        if abs(eta1 - 1.0) <= _EPS and abs(eta2 - 1.0) <= _EPS:
            bf_a = bf1 / 2
        else:
            bf_a = (bf1 - bf2) / (eta1 - 1.0 / eta2)
        return eta1, eta2, bf1, bf2, bf_a

    def _losses(self, speed):
        """eta_mf1, eta_mf2, |tau_bf1|, |tau_bf2| and tau_bf_a at |w_a| = ``speed`` (w_a
        rolling forward, -w_a backward), the table interpolated linearly."""
        eta1, eta2, bf1, bf2 = (table_value(self.lossTable, speed / self.unit_w, k)
                                for k in (1, 2, 3, 4))
        bf1, bf2 = ac.abs(bf1) * self.unit_tau, ac.abs(bf2) * self.unit_tau
        split = (bf1 - bf2) / (eta1 - 1 / eta2)
        rows_one = [abs(r[1] - 1.0) <= _EPS and abs(r[2] - 1.0) <= _EPS for r in self.lossTable]
        if all(rows_one):
            bf_a = bf1 / 2
        elif not any(rows_one):
            bf_a = split
        else:                                # both efficiencies 1 at some speeds only
            both_one = (eta1 - 1)**2 + (eta2 - 1)**2 <= 2 * _EPS**2
            bf_a = ac.if_else(both_one, bf1 / 2, split)
        return eta1, eta2, bf1, bf2, bf_a

    def break_away(self) -> tuple:
        """(tauLossMax_p, tauLossMin_m): the losses at w_a = 0+ and 0- (the table at 0),
        on the side tau_eta_p = flange_a.tau - tau_bf_a_0 (tau_eta_m = ... + tau_bf_a_0)
        gives.  (The MSL chooses the side without an event; here its sign is a relation
        of its own, which changes nothing but adds an event where it switches.)"""
        eta1, eta2, bf1, bf2, bf_a = self._at_rest()
        bf1, bf2, bf_a = (x * self.unit_tau for x in (bf1, bf2, bf_a))
        tau_a = self.flange_a.tau
        quadrant1_p = (1 - eta1) * tau_a + bf1
        quadrant2_p = (1 - 1 / eta2) * tau_a + bf2
        quadrant4_m = (1 - 1 / eta2) * tau_a - bf2
        quadrant3_m = (1 - eta1) * tau_a - bf1
        return (ac.if_else(tau_a - bf_a > 0, quadrant1_p, quadrant2_p),
                ac.if_else(tau_a + bf_a > 0, quadrant4_m, quadrant3_m))

    def sliding_laws(self) -> tuple:
        """(tauLossMax, tauLossMin): rolling forward, tau_eta = flange_a.tau - tau_bf_a,
        quadrant1 where tau_eta >= 0 else quadrant2; backward, tau_eta = flange_a.tau +
        tau_bf_a, quadrant4 or quadrant3.  The sign of tau_eta is an event."""
        tau_a = self.flange_a.tau
        eta1, eta2, bf1, bf2, bf_a = self._losses(self.w_a)
        quadrant1 = (1 - eta1) * tau_a + bf1
        quadrant2 = (1 - 1 / eta2) * tau_a + bf2
        forward = ac.if_else(tau_a - bf_a >= 0, quadrant1, quadrant2)
        eta1, eta2, bf1, bf2, bf_a = self._losses(-self.w_a)
        quadrant4 = (1 - 1 / eta2) * tau_a - bf2
        quadrant3 = (1 - eta1) * tau_a - bf1
        return forward, ac.if_else(tau_a + bf_a >= 0, quadrant4, quadrant3)

    def loss_power(self):
        return self.lossPower

    @ac.replaces(FrictionModes)
    def equations(self):
        phi_s = self.phi_support()
        eqs = [ac.Eq(self.phi_a, self.flange_a.phi - phi_s),
               ac.Eq(self.phi_b, self.flange_b.phi - phi_s),
               ac.Eq(self.phi_a, self.ratio * self.phi_b),
               ac.Eq(0, self.flange_b.tau + self.ratio * (self.flange_a.tau - self.tauLoss)),
               ac.Eq(self.w_a, ac.der(self.phi_a)),
               ac.Eq(self.a_a, ac.der(self.w_a)),
               ac.Eq(self.lossPower, self.tauLoss * self.w_a)]
        if self.ideal:                       # no losses, no modes (sa is not used)
            w = self.w_a                     # the mode signals as the speed's sign says
            return eqs + [ac.Eq(self.tauLoss, 0), ac.Eq(self.sa, 0),
                          ac.Eq(self.free, False), ac.Eq(self.startForward, False),
                          ac.Eq(self.startBackward, False),
                          ac.Eq(self.locked, ~((w > 0) | (w < 0))),
                          ac.Eq(self.mode, ac.if_else(w > 0, self.Forward,
                                                      ac.if_else(w < 0, self.Backward,
                                                                 self.Stuck)))]
        return eqs + self.mode_system()

    def mode_structure(self) -> list:
        return [] if self.ideal else super().mode_structure()
