"""Friction that sticks: the mode logic of clutches and brakes, written once
(Modelica.Mechanics.Rotational.Interfaces.PartialFriction; Otter, Elmqvist & Mattsson,
*Hybrid modeling in Modelica based on the synchronous data flow principle*, CACSD 1999).

A friction element between two surfaces with relative speed w and relative acceleration
a = der(w) is in one of six modes:

    free            the surfaces are not pressed together        tau = 0
    forward         w > 0, sliding                              tau =  tau_slide(w)
    backward        w < 0, sliding                              tau = -tau_slide(-w)
    start forward   w = 0, breaking away forwards  (a > 0)      tau =  tau_slide(0)
    start backward  w = 0, breaking away backwards (a < 0)      tau = -tau_slide(0)
    locked          w = 0 and stays so             (a = 0)      tau from the torque balance

The locked mode is an acceleration constraint, a = 0, whose unknown is the friction
torque: the torque the rest of the system needs to keep the surfaces together, whatever
is connected (the element never needs another component's parameters).  Both are
written with one unknown, the path parameter sa [N.m] of the MSL, and two equations
whose branches are the modes:

    0 = a                       locked      (sa: the torque the lock must carry)
    0 = a - (sa - tau0_max)     start forward,   0 = a - (sa + tau0_max)  start backward
                                (sa in N.m read as rad/s2: unit_a/unit_tau = 1)
    0 = sa                      free, forward, backward (sa is not needed)
    tau = sa  locked,  else the sliding law of the mode

The modes are decided by four relations, frozen between events like every relation
(Modelica's pre() of the mode is the frozen value):

    w > 0,   w < 0,   sa > tau0_max,   sa < -tau0_max       (tau0_max = peak tau0)

A sliding element whose speed reaches zero leaves its sliding mode at that event:
neither w > 0 nor w < 0 keeps its rate once the friction torque of that side acts (the
runtime judges a relation at zero by its rate in the mode it leads to,
:mod:`acausal.runtime.events`).  Since sa = 0 while it slides, both break-away relations
are false then, so it enters the locked mode, whose sa is the torque needed to hold it.
If that exceeds tau0_max the relation ``sa > tau0_max`` (or its mirror) is contradicted
and switches: the element starts to slide, a = sa - tau0_max > 0 with tau = tau_slide(0)
= tau0 <= tau0_max (it moves in the direction of the torque it could not hold), and once
w leaves zero the sliding mode takes over.  A locked element breaks away at the event
where |sa| reaches tau0_max, in the direction its rate gives.  So the event iteration
settles the modes in a few rounds and cannot cycle, by construction: sliding -> locked
-> starting -> sliding, never back; this is the MSL's startForward/startBackward logic,
with the frozen relation values in place of pre(mode).

While locked w keeps the value it had at the lock-up (zero within the event tolerance):
a = 0 holds it, so w is not an independent degree of freedom there, and the flanges
move as one body.  The lock-up itself is continuous (w reaches zero under a finite
friction torque), so no impulse acts and the angular momentum of the locked group is
that of its parts.

:class:`PartialFriction` carries the modes; an element (``Clutch``, ``Brake``,
``OneWayClutch`` in :mod:`acausal.library.rotational.clutches`) says which speed and
acceleration rub (``w_relfric``, ``a_relfric``), what torque acts (``tau``), its normal
force (``fn``) and its sliding law.
"""
from __future__ import annotations

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac

from ..blocks.tables import _Pieces, _search_tree

__all__ = ["PartialFriction", "friction_table", "MODES"]

MODES = ("free", "forward", "backward", "start forward", "start backward", "locked")


def friction_table(table, owner: str, name: str = "mu_pos", value: str = "mu") -> np.ndarray:
    """The table ``name`` (rows [w, value], w >= 0, value >= 0) as a checked (n x 2)
    float array.

    One row is a constant; more rows are interpolated linearly and extrapolated with the
    two end points (as the MSL's ``Extrapolation.LastTwoPoints``).
    """
    try:
        data = np.array(table, dtype=float)
    except (TypeError, ValueError):
        raise ac.InvalidValue(f"{owner}: {name} must be rows [w_rel, {value}] of numbers, "
                              f"got {table!r}") from None
    if data.ndim == 1 and data.size == 2:
        data = data.reshape(1, 2)
    if data.ndim != 2 or data.shape[1] != 2 or data.shape[0] < 1:
        raise ac.InvalidValue(f"{owner}: {name} must be rows [w_rel, {value}] (n x 2), got "
                              f"shape {data.shape}")
    if not np.isfinite(data).all():
        raise ac.InvalidValue(f"{owner}: {name} holds a value that is not a finite number")
    w, mu = data[:, 0], data[:, 1]
    if (w < 0).any():
        raise ac.InvalidValue(f"{owner}: {name} row {int(np.argmax(w < 0)) + 1}: w_rel = "
                              f"{w[w < 0][0]} < 0 (the table is the positive branch, "
                              "w_rel >= 0)")
    steps = np.diff(w)
    if (steps <= 0).any():
        k = int(np.argmax(steps <= 0)) + 1
        raise ac.InvalidValue(f"{owner}: {name} row {k + 1}: w_rel = {w[k]} does not "
                              f"increase (previous row {w[k - 1]}); the first column must "
                              "be strictly increasing")
    if (mu < 0).any():
        raise ac.InvalidValue(f"{owner}: {name} row {int(np.argmax(mu < 0)) + 1}: {value} = "
                              f"{mu[mu < 0][0]} < 0 (friction opposes the motion)")
    return data


def _table_value(data: np.ndarray, x):
    """mu(x) of a checked table: linear pieces, the end segments extended linearly.

    Only the inner breakpoints are relations (events): the outer ones, w = 0 among them,
    are where a stuck element sits, and a relation there would sit at zero for as long
    as it is stuck."""
    if data.shape[0] == 1:
        return sp.Float(float(data[0, 1]))
    pieces = _Pieces(data[:, 0], data[:, 1], "linear")
    leaves = [pieces.leaf(k, x) for k in range(len(pieces.seg))]
    return _search_tree(x, pieces.knots[1:-1], leaves)


def _table_at_zero(data: np.ndarray) -> float:
    """mu0 = mu(0), by the same pieces as :func:`_table_value`."""
    if data.shape[0] == 1:
        return float(data[0, 1])
    (w0, w1), (m0, m1) = data[:2, 0], data[:2, 1]
    return float(m0 + (m1 - m0) / (w1 - w0) * (0.0 - w0))


class PartialFriction(ac.Component):
    """The modes of an element with Coulomb friction that sticks (module docstring;
    Modelica.Mechanics.Rotational.Interfaces.PartialFriction).

    A subclass declares the variables ``w_relfric`` (relative speed of the rubbing
    surfaces), ``a_relfric`` = der(w_relfric) and ``tau`` (friction torque, positive
    against w_relfric > 0), and the methods

    * ``free()``: the relation under which the surfaces do not touch (fn <= 0), or
      None where there is no free mode;
    * ``tau0()``, ``tau0_max()``: friction torque at w = 0 sliding, and the most the
      element holds at w = 0 (``peak`` tau0);
    * ``sliding_torque(w)``: the friction torque while sliding forwards at w >= 0.

    ``backward = False`` (a one-way clutch) drops the backward modes: w <= 0 is held
    by the freewheel, whatever torque that needs.
    """

    backward = True
    sa = ac.Variable(start=0.0, unit="N.m",
                     description="path parameter: torque held while locked, else 0 "
                                 "or the acceleration past break-away")
    # sa is a torque; past break-away it also measures an acceleration, 1 N.m for
    # 1 rad/s2 (the MSL's unitTorque and unitAngularAcceleration)
    unit_a = ac.Parameter(1.0, unit="rad/s2", min=0,
                          description="1 rad/s2: the unit of sa as an acceleration")
    unit_tau = ac.Parameter(1.0, unit="N.m", min=0, description="1 N.m: the unit of sa")

    def mode_relations(self) -> dict:
        """The relations that decide the mode (module docstring), by name."""
        w, sa, tau0_max = self.w_relfric, self.sa, self.tau0_max()
        rel = {"forward": w > 0, "start forward": sa > tau0_max}
        if self.free() is not None:
            rel["free"] = self.free()
        if self.backward:
            rel.update({"backward": w < 0, "start backward": sa < -tau0_max})
        return rel

    def mode_equations(self) -> dict:
        """Per mode, its (acceleration equation, friction torque) as expressions
        ``0 = first`` and ``tau = second``: the structure of each mode."""
        a, sa, tau0_max = self.a_relfric, self.sa, self.tau0_max()
        forward = self.sliding_torque(self.w_relfric)
        backward = -self.sliding_torque(-self.w_relfric)
        per = self.unit_a / self.unit_tau
        modes = {"forward": (per * sa, forward),
                 "start forward": (a - per * (sa - tau0_max), forward), "locked": (a, sa)}
        if self.free() is not None:
            modes["free"] = (per * sa, sp.Integer(0))
        if self.backward:
            modes.update({"backward": (per * sa, backward),
                          "start backward": (a - per * (sa + tau0_max), backward)})
        return modes

    def mode_structure(self) -> list:
        """Per mode: its name, the relations that select it, and what determines the
        acceleration and the friction torque there (for the index report)."""
        rel, eqs = self.mode_relations(), self.mode_equations()
        a, sa, w, tau = self.a_relfric, self.sa, self.w_relfric, self.tau
        out = []
        for mode in [m for m in MODES if m in eqs]:
            accel, torque = eqs[mode]
            if sa not in accel.free_symbols:
                motion = (f"0 = {accel}: {w} is held (der({w}) = 0, not an independent "
                          f"state); {tau} = {sa} from the torque balance of the system")
            elif a in accel.free_symbols:
                motion = (f"0 = {accel}: {sa} from {a} (the system's dynamics); "
                          f"{tau} = {torque}")
            else:
                motion = f"{sa} = 0 (unused); {tau} = {torque}"
            out.append({"mode": mode, "when": str(rel[mode]) if mode in rel else
                        "none of the above", "structure": motion})
        return out

    def equations(self):
        rel, eqs = self.mode_relations(), self.mode_equations()
        order = [m for m in MODES[:-1] if m in rel]        # the first that holds decides
        accel, torque = eqs["locked"]
        for mode in reversed(order):
            accel = ac.if_else(rel[mode], eqs[mode][0], accel)
            torque = ac.if_else(rel[mode], eqs[mode][1], torque)
        return [ac.Eq(0, accel), ac.Eq(self.tau, torque)]

    def loss_power(self):
        """tau w_relfric >= 0: sliding friction opposes the motion, a locked element
        does not slide."""
        return self.tau * self.w_relfric
