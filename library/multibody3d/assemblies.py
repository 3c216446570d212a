"""Joint aggregations that close a kinematic loop analytically
(Modelica.Mechanics.MultiBody.Joints.Assemblies).

They write the orientation of the frames they carry (frame_ia, frame_ib) from frame_a's
and the positions of frame_a and frame_b, but neither frame_b's orientation nor any
constraint: a loop through them closes without a cut joint.
"""
from __future__ import annotations

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import TranslationalFlange
from acausal.ports.spatial import Frame

from .frames import force, orientation, position, resolve1, resolve2, torque
from .interfaces import PartialTwoFrames, equal

__all__ = ["JointUPS"]


def _numbers(c, prefix, given=None):
    names = [f"{prefix}_{k}" for k in (1, 2, 3)]
    if given is None:
        values = [c.parameter_value(n) for n in names]
    else:
        values = [given.get(n, c.declarations()[n].value) for n in names]
    if not all(isinstance(v, (int, float)) for v in values):
        raise ac.InvalidValue(f"{c._describe()}: {prefix}_1..3 fix the joint's axes and must "
                              "be numbers, not expressions of other parameters")
    v = np.array(values, dtype=float)
    if not np.linalg.norm(v) > 0:
        raise ac.InvalidValue(f"{c._describe()}: {prefix}_1, {prefix}_2, {prefix}_3 are all "
                              "0, so the vector has no direction")
    return v


class JointUPS(PartialTwoFrames):
    """Universal - prismatic - spherical joint aggregation: the rod from frame_a (at the
    universal joint) to frame_b (at the spherical joint) carries frame_ia at frame_a and
    frame_ib at frame_b, and its length is driven through the 1-D flanges ``axis`` and
    ``bearing`` (MSL MultiBody.Joints.Assemblies.JointUPS).  No constraint, no state:

        rAxis_0 = r_0,b - r_0,a,   axisLength = |rAxis_0| = s + s_offset,
        eAxis_a = R_a rAxis_0 / axisLength,   e2_a = n1_a x eAxis_a / |n1_a x eAxis_a|,
        e3_a = eAxis_a x e2_a,
        R_ia = [eAxis_ia, e2_ia, e3_ia] [eAxis_a, e2_a, e3_a]^T R_a,   R_ib = R_ia,
        r_0,ia = r_0,a,   r_0,ib = r_0,b,   bearing.s = 0,   axis.s = s,   axis.f = f

    and the balance of the massless rod (resolved in frame_a; f_ia, t_ia, t_ib by R_ia^T):

        f_bd = -eAxis_a f - e2_a (n1_a . t_cd)/(axisLength (n1_a . e3_a))
               + e3_a (e2_a . t_cd)/axisLength,   t_cd = t_ia + t_ib,
        0 = f_b + R_b R_ib^T f_ib - R_b R_a^T f_bd,   t_b = 0,
        0 = f_a + f_ia + f_bd,   0 = t_a + t_cd + rAxis_a x f_bd

    n1_a is the universal joint's first axis (in frame_a), nAxis_ia the rod's direction
    in frame_ia; both are numbers (they fix the joint's geometry).
    """

    n1_a_1 = ac.Parameter(0.0, description="axis 1 of the universal joint in frame_a, x")
    n1_a_2 = ac.Parameter(0.0, description="axis 1 of the universal joint in frame_a, y")
    n1_a_3 = ac.Parameter(1.0, description="axis 1 of the universal joint in frame_a, z")
    nAxis_ia_1 = ac.Parameter(1.0, description="rod direction in frame_ia, x")
    nAxis_ia_2 = ac.Parameter(0.0, description="rod direction in frame_ia, y")
    nAxis_ia_3 = ac.Parameter(0.0, description="rod direction in frame_ia, z")
    s_offset = ac.Parameter(0.0, unit="m",
                            description="distance of frame_a and frame_b = s + s_offset")
    frame_ia = Frame()
    frame_ib = Frame()
    axis = TranslationalFlange()
    bearing = TranslationalFlange()
    s = ac.Variable(start=1.0, unit="m", description="rod length less s_offset")
    f = ac.Variable(unit="N", description="driving force in the rod (= axis.f)")
    axisLength = ac.Variable(start=1.0, unit="m",
                             description="distance between frame_a and frame_b")
    rAxis_0 = ac.Variable(shape=3, unit="m", description="frame_b from frame_a, world frame")
    rAxis_a = ac.Variable(shape=3, unit="m", description="frame_b from frame_a, in frame_a")
    eAxis_a = ac.Variable(shape=3, description="rod direction, in frame_a")
    n2_a = ac.Variable(shape=3, description="n1_a x eAxis_a")
    length_n2_a = ac.Variable(start=1.0, description="|n2_a|")
    e2_a = ac.Variable(shape=3, description="axis 2 of the universal joint, in frame_a")
    e3_a = ac.Variable(shape=3, description="eAxis_a x e2_a")

    energy_role = "lossless"  # an ideal joint: the flanges take what the frames give

    def build(self):
        # guesses for Newton's method where a loop of the rod's balance is solved: the rod
        # along its axis in frame_ia, frame_ia near frame_a (the parameters' values
        # when the joint is made; a bound parameter leaves the guesses at 0)
        try:
            axes = self.axes_ia(self._mods)
        except ac.ModelError:
            return
        for name, value in zip(("eAxis_a", "e2_a", "e3_a"), axes):
            own = self._mods.get(name, {})
            self._mods[name] = {"start": value.tolist(), **(own if isinstance(own, dict)
                                                            else {"start": own})}

    def axes_ia(self, values=None):
        """eAxis_ia, e2_ia, e3_ia (numbers): the rod's frame in frame_ia (from the given
        ``values`` of the parameters, else from the model's)."""
        n1 = _numbers(self, "n1_a", values)
        e_axis = _numbers(self, "nAxis_ia", values)
        e_axis = e_axis / np.linalg.norm(e_axis)
        n2 = np.cross(n1, e_axis)
        if not np.linalg.norm(n2) > 1e-10:
            raise ac.InvalidValue(f"{self._describe()}: n1_a is parallel to nAxis_ia (the "
                                  "universal joint's singular position)")
        e2 = n2 / np.linalg.norm(n2)
        return e_axis, e2, np.cross(e_axis, e2)

    def equations(self):
        a, b, ia, ib = self.frame_a, self.frame_b, self.frame_ia, self.frame_ib
        R_a, R_b = orientation(a), orientation(b)
        V = {name: sp.Matrix(getattr(self, name))
             for name in ("rAxis_0", "rAxis_a", "eAxis_a", "n2_a", "e2_a", "e3_a")}
        n1 = sp.Matrix(_numbers(self, "n1_a"))
        L = self.axisLength
        T_ia = sp.Matrix(np.column_stack(self.axes_ia()))
        T_a = sp.Matrix.hstack(V["eAxis_a"], V["e2_a"], V["e3_a"])
        R_ia_a = T_ia * T_a.T
        t_cd = resolve1(R_ia_a, torque(ia) + torque(ib))
        f_bd = (-V["eAxis_a"] * self.f - V["e2_a"] * n1.dot(t_cd) / (L * n1.dot(V["e3_a"]))
                + V["e3_a"] * V["e2_a"].dot(t_cd) / L)
        zero = sp.zeros(3, 1)
        return [ac.Eq(L, self.s + self.s_offset),
                ac.Eq(self.bearing.s, 0), ac.Eq(self.axis.s, self.s),
                ac.Eq(self.axis.f, self.f),
                *equal(V["rAxis_0"], position(b) - position(a)),
                *equal(V["rAxis_a"], resolve2(R_a, V["rAxis_0"])),
                ac.Eq(L, sp.sqrt(V["rAxis_0"].dot(V["rAxis_0"]))),
                *equal(V["eAxis_a"], V["rAxis_a"] / L),
                *equal(V["n2_a"], n1.cross(V["eAxis_a"])),
                ac.Eq(self.length_n2_a, sp.sqrt(V["n2_a"].dot(V["n2_a"]))),
                *equal(V["e2_a"], V["n2_a"] / self.length_n2_a),
                *equal(V["e3_a"], V["eAxis_a"].cross(V["e2_a"])),
                *equal(position(ia), position(a)),
                *equal(position(ib), position(b)),
                *equal(orientation(ia), R_ia_a * R_a),
                *equal(orientation(ib), orientation(ia)),
                *equal(zero, force(b) + R_b * orientation(ib).T * force(ib)
                       - R_b * R_a.T * f_bd),
                *equal(torque(b), zero),
                *equal(zero, force(a) + resolve1(R_ia_a, force(ia)) + f_bd),
                *equal(zero, torque(a) + t_cd + V["rAxis_a"].cross(f_bd))]
