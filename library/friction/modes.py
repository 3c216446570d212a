"""Friction that sticks: the mode logic of clutches, brakes, lossy gears and sliding
masses, written once for both mechanical domains
(Modelica.Mechanics.Rotational.Interfaces.PartialFriction and its translational twin;
Otter, Elmqvist & Mattsson, *Hybrid modeling in Modelica based on the synchronous data
flow principle*, CACSD 1999).

A friction element between two surfaces with relative speed w and relative acceleration
a = der(w) is in one of six modes (f the friction force or torque, positive against
w > 0):

    free            the surfaces are not pressed together        f = 0
    forward         w > 0, sliding                              f = f_forward(w)
    backward        w < 0, sliding                              f = f_backward(w)
    start forward   w = 0, breaking away forwards  (a > 0)      f = f_forward(w)
    start backward  w = 0, breaking away backwards (a < 0)      f = f_backward(w)
    locked          w = 0 and stays so             (a = 0)      f from the force balance

(for a Coulomb element f_forward(w) = f_slide(w) and f_backward(w) = -f_slide(-w)).
The locked mode is an acceleration constraint, a = 0, whose unknown is the friction
force: the force the rest of the system needs to keep the surfaces together, whatever
is connected (the element never needs another component's parameters).  Both are
written with one unknown, the path parameter sa of the MSL (a force or torque), and two
equations whose branches are the modes:

    0 = a                        locked      (sa: the force the lock must carry)
    0 = a - (sa - f_max)         start forward,   0 = a - (sa - f_min)  start backward
                                 (sa read as an acceleration: unit_a / unit_force = 1)
    0 = sa                       free, forward, backward (sa is not needed)
    f = sa  locked,  else the sliding law of the mode

f_max > 0 is the most the element holds forwards (peak f0 for a clutch), f_min < 0 the
most it holds backwards (-f_max for a symmetric element; a lossy gear's limits depend
on the torque it transmits).  The modes are decided by four relations, frozen between
events like every relation (Modelica's pre() of the mode is the frozen value):

    w > 0,   w < 0,   sa > f_max,   sa < f_min

A sliding element whose speed reaches zero leaves its sliding mode at that event:
neither w > 0 nor w < 0 keeps its rate once the friction force of that side acts (the
runtime judges a relation at zero by its rate in the mode it leads to,
:mod:`acausal.runtime.events`).  Since sa = 0 while it slides, both break-away relations
are false then, so it enters the locked mode, whose sa is the force needed to hold it.
If that exceeds f_max the relation ``sa > f_max`` (or its mirror) is contradicted and
switches: the element starts to slide, a = sa - f_max > 0 with f = f_forward(0) <= f_max
(it moves in the direction of the force it could not hold), and once w leaves zero the
sliding mode takes over.  A locked element breaks away at the event where sa reaches
f_max (or f_min), in the direction its rate gives.  So the event iteration settles the
modes in a few rounds and cannot cycle, by construction: sliding -> locked -> starting
-> sliding, never back; this is the MSL's startForward/startBackward logic, with the
frozen relation values in place of pre(mode).

While locked w keeps the value it had at the lock-up (zero within the event tolerance):
a = 0 holds it, so w is not an independent degree of freedom there, and the flanges
move as one body.  The lock-up itself is continuous (w reaches zero under a finite
friction force), so no impulse acts and the momentum of the locked group is that of its
parts.

:class:`FrictionModes` carries the modes; the domain bases
(:class:`acausal.library.rotational.friction_modes.PartialFriction`,
:class:`acausal.library.translational.friction.PartialFriction`) name the speed,
acceleration and force and their units, and an element says what rubs, its normal force
and its sliding law.
"""
from __future__ import annotations

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac

from ..blocks.tables import _Pieces, _search_tree

__all__ = ["FrictionModes", "MODES", "friction_table", "table_value", "table_at_zero"]

MODES = ("free", "forward", "backward", "start forward", "start backward", "locked")


def friction_table(table, owner: str, name: str = "mu_pos", value: str = "mu",
                   speed: str = "w_rel") -> np.ndarray:
    """The table ``name`` (rows [speed, value], speed >= 0, value >= 0) as a checked
    (n x 2) float array.

    One row is a constant; more rows are interpolated linearly and extrapolated with the
    two end points (as the MSL's ``Modelica.Math.Vectors.interpolate``).
    """
    try:
        data = np.array(table, dtype=float)
    except (TypeError, ValueError):
        raise ac.InvalidValue(f"{owner}: {name} must be rows [{speed}, {value}] of numbers, "
                              f"got {table!r}") from None
    if data.ndim == 1 and data.size == 2:
        data = data.reshape(1, 2)
    if data.ndim != 2 or data.shape[1] != 2 or data.shape[0] < 1:
        raise ac.InvalidValue(f"{owner}: {name} must be rows [{speed}, {value}] (n x 2), "
                              f"got shape {data.shape}")
    check_speed_column(data, owner, name, speed)
    mu = data[:, 1]
    if (mu < 0).any():
        raise ac.InvalidValue(f"{owner}: {name} row {int(np.argmax(mu < 0)) + 1}: {value} = "
                              f"{mu[mu < 0][0]} < 0 (friction opposes the motion)")
    return data


def check_speed_column(data: np.ndarray, owner: str, name: str, speed: str) -> None:
    """The table holds finite numbers and its first column, the speed, is >= 0 and
    strictly increasing."""
    if not np.isfinite(data).all():
        raise ac.InvalidValue(f"{owner}: {name} holds a value that is not a finite number")
    w = data[:, 0]
    if (w < 0).any():
        raise ac.InvalidValue(f"{owner}: {name} row {int(np.argmax(w < 0)) + 1}: {speed} = "
                              f"{w[w < 0][0]} < 0 (the table is the positive branch, "
                              f"{speed} >= 0)")
    steps = np.diff(w)
    if (steps <= 0).any():
        k = int(np.argmax(steps <= 0)) + 1
        raise ac.InvalidValue(f"{owner}: {name} row {k + 1}: {speed} = {w[k]} does not "
                              f"increase (previous row {w[k - 1]}); the first column must "
                              "be strictly increasing")


def table_value(data: np.ndarray, x, column: int = 1):
    """The ``column`` of a checked table at x: linear pieces, the end segments extended
    linearly.

    Only the inner breakpoints are relations (events): the outer ones, w = 0 among them,
    are where a stuck element sits, and a relation there would sit at zero for as long
    as it is stuck."""
    if data.shape[0] == 1:
        return sp.Float(float(data[0, column]))
    pieces = _Pieces(data[:, 0], data[:, column], "linear")
    leaves = [pieces.leaf(k, x) for k in range(len(pieces.seg))]
    return _search_tree(x, pieces.knots[1:-1], leaves)


def table_at_zero(data: np.ndarray, column: int = 1) -> float:
    """The ``column`` of a checked table at 0, by the same pieces as :func:`table_value`."""
    if data.shape[0] == 1:
        return float(data[0, column])
    (w0, w1), (m0, m1) = data[:2, 0], data[:2, column]
    return float(m0 + (m1 - m0) / (w1 - w0) * (0.0 - w0))


class FrictionModes(ac.Component):
    """The modes of an element with Coulomb friction that sticks (module docstring).

    A domain base declares the path parameter ``sa`` and names, through
    :meth:`relfric`, the relative speed of the rubbing surfaces, its derivative and the
    friction force (positive against a positive speed), and through :meth:`per` the
    factor unit_a / unit_force that reads sa as an acceleration.  An element provides

    * ``free()``: the relation under which the surfaces do not touch, or None where
      there is no free mode;
    * ``break_away()``: (f_max, f_min), the most it holds forwards (> 0) and backwards
      (< 0) at rest;
    * ``sliding_laws()``: (f_forward, f_backward), the friction force while sliding
      forwards and backwards (expressions of the element's variables).

    ``backward = False`` (a one-way clutch) drops the backward modes: w <= 0 is held
    by the freewheel, whatever force that needs.
    """

    backward = True

    def relfric(self) -> tuple:
        """(speed, acceleration, friction force) of the rubbing surfaces."""
        raise NotImplementedError

    def per(self):
        """unit_a / unit_force: sa read as an acceleration."""
        raise NotImplementedError

    def free(self):
        return None

    def mode_relations(self) -> dict:
        """The relations that decide the mode (module docstring), by name."""
        w, sa = self.relfric()[0], self.sa
        f_max, f_min = self.break_away()
        rel = {"forward": w > 0, "start forward": sa > f_max}
        if self.free() is not None:
            rel["free"] = self.free()
        if self.backward:
            rel.update({"backward": w < 0, "start backward": sa < f_min})
        return rel

    def mode_equations(self) -> dict:
        """Per mode, its (acceleration equation, friction force) as expressions
        ``0 = first`` and ``f = second``: the structure of each mode."""
        a, sa = self.relfric()[1], self.sa
        f_max, f_min = self.break_away()
        forward, backward = self.sliding_laws()
        per = self.per()
        modes = {"forward": (per * sa, forward),
                 "start forward": (a - per * (sa - f_max), forward), "locked": (a, sa)}
        if self.free() is not None:
            modes["free"] = (per * sa, sp.Integer(0))
        if self.backward:
            modes.update({"backward": (per * sa, backward),
                          "start backward": (a - per * (sa - f_min), backward)})
        return modes

    def mode_structure(self) -> list:
        """Per mode: its name, the relations that select it, and what determines the
        acceleration and the friction force there (for the index report)."""
        rel, eqs = self.mode_relations(), self.mode_equations()
        w, a, f = self.relfric()
        sa = self.sa
        out = []
        for mode in [m for m in MODES if m in eqs]:
            accel, force = eqs[mode]
            if sa not in accel.free_symbols:
                motion = (f"0 = {accel}: {w} is held (der({w}) = 0, not an independent "
                          f"state); {f} = {sa} from the force balance of the system")
            elif a in accel.free_symbols:
                motion = (f"0 = {accel}: {sa} from {a} (the system's dynamics); "
                          f"{f} = {force}")
            else:
                motion = f"{sa} = 0 (unused); {f} = {force}"
            out.append({"mode": mode, "when": str(rel[mode]) if mode in rel else
                        "none of the above", "structure": motion})
        return out

    def equations(self):
        return self.mode_system()

    def mode_system(self) -> list:
        """The two equations whose branches are the modes: 0 = the acceleration
        equation, f = the friction force (an element that has no modes in some
        configuration replaces ``equations`` and uses this where it has them)."""
        rel, eqs = self.mode_relations(), self.mode_equations()
        order = [m for m in MODES[:-1] if m in rel]        # the first that holds decides
        accel, force = eqs["locked"]
        for mode in reversed(order):
            accel = ac.if_else(rel[mode], eqs[mode][0], accel)
            force = ac.if_else(rel[mode], eqs[mode][1], force)
        return [ac.Eq(0, accel), ac.Eq(self.relfric()[2], force)]

    def loss_power(self):
        """f w >= 0: sliding friction opposes the motion, a locked element does not
        slide."""
        w, _, f = self.relfric()
        return f * w
