"""Force elements of spatial multibody systems (Modelica.Mechanics.MultiBody.Forces):
line forces between two frames (springs, dampers, with optional point masses on the
line, and with 1-D translational flanges), and forces and torques given by signals.
They read the frames' positions and orientations and write only cut forces and torques
(except where a line force is told to fix a frame's orientation,
``fixedRotationAtFrame_a/b``)."""
from __future__ import annotations

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.library.thermal.conditional import PartialElementaryConditionalHeatPort
from acausal.ports import RealInput, TranslationalFlange
from acausal.ports.spatial import Frame

from .frames import force, orientation, position, resolve1, resolve2, torque
from .interfaces import PartialTwoFrames, equal
from .world import world_of

__all__ = ["LineForceBase", "PartialLineForce", "Spring", "Damper", "SpringDamperParallel",
           "SpringDamperSeries",
           "LineForceWithMass", "LineForceWithTwoMasses", "WorldForce", "WorldTorque",
           "ForceAndTorque", "RESOLVE_IN_FRAME"]

RESOLVE_IN_FRAME = ("world", "frame_a", "frame_b", "frame_resolve")


def _flag(cls, name, value):
    if not isinstance(value, bool):
        raise ac.InvalidValue(f"{cls}: {name} = {value!r} must be True or False")
    return value


class LineForceBase(PartialTwoFrames):
    """The geometry of an element acting along the line between the frame origins
    (MSL MultiBody.Interfaces.LineForceBase):

        r_rel_0 = r_0,b - r_0,a,   length = |r_rel_0|,   s = length,   e_rel_0 = r_rel_0 / s

    The direction is undefined at s = 0 (the MSL guards s by s_small, which only moves
    the division by zero to a wrong direction).

    An element connected directly to another line force has no body between them to
    set that frame's orientation: ``fixedRotationAtFrame_a=True`` (or ``_b``), given
    when it is made, makes the element set R = I at that frame (a root of the
    orientation tree, as the MSL's Connections.root) and take the torque there;
    otherwise it takes no torque there, t = 0.
    """

    s = ac.Variable(start=1.0, unit="m", state_select="avoid",
                    description="distance between the frame origins (= length)")
    length = ac.Variable(start=1.0, unit="m", description="distance between the frame origins")
    r_rel_0 = ac.Variable(shape=3, unit="m",
                          description="frame_b's origin from frame_a's, world frame")
    e_rel_0 = ac.Variable(shape=3, description="unit vector from frame_a to frame_b, world frame")

    def __init__(self, *, fixedRotationAtFrame_a: bool = False,
                 fixedRotationAtFrame_b: bool = False, **modifications):
        name = type(self).__name__
        self.fixedRotationAtFrame_a = _flag(name, "fixedRotationAtFrame_a",
                                            fixedRotationAtFrame_a)
        self.fixedRotationAtFrame_b = _flag(name, "fixedRotationAtFrame_b",
                                            fixedRotationAtFrame_b)
        super().__init__(**modifications)

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = sp.Matrix(self.r_rel_0)
        zero = sp.zeros(3, 1)
        return [*equal(r, position(b) - position(a)),
                ac.Eq(self.length, sp.sqrt(r.dot(r))),
                ac.Eq(self.s, self.length),
                *equal(sp.Matrix(self.e_rel_0), r / self.s),
                *(equal(orientation(a), sp.eye(3)) if self.fixedRotationAtFrame_a
                  else equal(torque(a), zero)),
                *(equal(orientation(b), sp.eye(3)) if self.fixedRotationAtFrame_b
                  else equal(torque(b), zero))]


def _mass(c, name="m"):
    """True unless the mass is the number 0 (the MSL's ``if m > 0``)."""
    value = c.parameter_value(name)
    return not (isinstance(value, (int, float)) and value == 0)


class _PointMassesOnLine(LineForceBase):
    """The line force's cut forces, with point masses on the line: fa and fb are the
    forces the element's law exerts at its frame_a and frame_b ends (fa > 0 pulls
    frame_a towards frame_b), ``_masses()`` the masses' own forces f1, f2 in the world
    (MSL LineForceWithMass / LineForceWithTwoMasses, power balance of the line):

        frame_a.f = R_a (f1 - e_rel_0 fa),   frame_b.f = R_b (f2 - e_rel_0 fb)
    """

    def cut_forces(self, fa, fb, f1, f2) -> list:
        e = sp.Matrix(self.e_rel_0)
        return [*equal(force(self.frame_a), resolve2(orientation(self.frame_a), f1 - e * fa)),
                *equal(force(self.frame_b), resolve2(orientation(self.frame_b), f2 - e * fb))]


class _OneMassOnLine(_PointMassesOnLine):
    """A point mass m at lengthFraction of the way from frame_a to frame_b (MSL
    LineForceWithMass):

        r_CM_0 = r_0,a + r_rel_0 h,   v_CM_0 = der(r_CM_0),
        ag_CM_0 = der(v_CM_0) - world.gravityAcceleration(r_CM_0),
        f1 = m (1 - h) ag_CM_0,   f2 = m h ag_CM_0

    With m = 0 (the default) the point mass and its variables are left out (they are 0).
    """

    m = ac.Parameter(0.0, unit="kg", min=0, description="point mass on the line")
    lengthFraction = ac.Parameter(0.5, min=0, max=1,
                                  description="place of the mass, from frame_a (0) to "
                                              "frame_b (1)")
    r_CM_0 = ac.Variable(shape=3, unit="m", state_select="avoid",
                         description="position of the point mass, world frame")
    v_CM_0 = ac.Variable(shape=3, unit="m/s", state_select="avoid",
                         description="der(r_CM_0)")
    ag_CM_0 = ac.Variable(shape=3, unit="m/s2",
                          description="der(v_CM_0) - gravity acceleration")

    def line_forces(self, fa, fb) -> list:
        r, v, ag = sp.Matrix(self.r_CM_0), sp.Matrix(self.v_CM_0), sp.Matrix(self.ag_CM_0)
        if not _mass(self):
            zero = sp.zeros(3, 1)
            return [*equal(r, zero), *equal(v, zero), *equal(ag, zero),
                    *self.cut_forces(fa, fb, zero, zero)]
        h = self.lengthFraction
        g = world_of(self).gravityAcceleration(r)
        return [*equal(r, position(self.frame_a) + sp.Matrix(self.r_rel_0) * h),
                *equal(v, r.applyfunc(ac.der)),
                *equal(ag, v.applyfunc(ac.der) - g),
                *self.cut_forces(fa, fb, self.m * (1 - h) * ag, self.m * h * ag)]


class PartialLineForce(_PointMassesOnLine):
    """A massless force element along the line with the tension f as its law (MSL
    MultiBody.Interfaces.PartialLineForce): f > 0 pulls the frames towards each other,

        frame_a.f = -R_a e_rel_0 f,   frame_b.f = R_b e_rel_0 f
    """

    f = ac.Variable(unit="N", description="tension force along the line")

    def equations(self):
        zero = sp.zeros(3, 1)
        return self.cut_forces(self.f, -self.f, zero, zero)


class Spring(_OneMassOnLine):
    """Linear spring along the line, with an optional mass m on it at lengthFraction
    (MSL MultiBody.Forces.Spring: a LineForceWithMass with a translational spring):

        f = c (s - s_unstretched)
    """

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    s_unstretched = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    f = ac.Variable(unit="N", description="tension force along the line")

    def stored_energy(self):
        """c (s - s_unstretched)^2 / 2, and the mass's m |v_CM|^2/2 + m V(r_CM)."""
        spring = self.c * (self.s - self.s_unstretched)**2 / 2
        if not _mass(self):
            return spring
        v = sp.Matrix(self.v_CM_0)
        return (spring + self.m * v.dot(v) / 2
                + self.m * world_of(self).gravityPotential(sp.Matrix(self.r_CM_0)))

    def equations(self):
        return [ac.Eq(self.f, self.c * (self.s - self.s_unstretched)),
                *self.line_forces(self.f, -self.f)]


class Damper(PartialLineForce, PartialElementaryConditionalHeatPort):
    """Linear damper along the line (MSL MultiBody.Forces.Damper):

        f = d der(s),   lossPower = f der(s)

    ``useHeatPort=True``: lossPower leaves through ``heatPort``."""

    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")

    def loss_power(self):
        """f der(s) = d der(s)^2."""
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.f, self.d * ac.der(self.s)),
                ac.Eq(self.lossPower, self.f * ac.der(self.s))]


class SpringDamperParallel(PartialLineForce, PartialElementaryConditionalHeatPort):
    """Spring and damper in parallel (MSL MultiBody.Forces.SpringDamperParallel):

        f_d = d der(s),   f = c (s - s_unstretched) + f_d,   lossPower = f_d der(s)

    ``useHeatPort=True``: lossPower leaves through ``heatPort``.
    """

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    s_unstretched = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")
    f_d = ac.Variable(unit="N", description="damping force")

    def stored_energy(self):
        return self.c * (self.s - self.s_unstretched)**2 / 2

    def loss_power(self):
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.f_d, self.d * ac.der(self.s)),
                ac.Eq(self.f, self.c * (self.s - self.s_unstretched) + self.f_d),
                ac.Eq(self.lossPower, self.f_d * ac.der(self.s))]


class SpringDamperSeries(PartialLineForce, PartialElementaryConditionalHeatPort):
    """Linear spring and linear damper in series along the line (MSL
    MultiBody.Forces.SpringDamperSeries; frame_a - damper - spring - frame_b):

        f = c (s - s_unstretched - s_damper),   d der(s_damper) = f
        lossPower = f der(s_damper)

    s_damper, the damper's length, starts from its start value, fixed (the MSL's
    parameter s_damper_start is ``s_damper={"start": ...}`` here).
    ``useHeatPort=True``: lossPower leaves through ``heatPort``.
    """

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    s_unstretched = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")
    s_damper = ac.Variable(start=0.0, fixed=True, unit="m",
                           description="actual length of damper (frame_a - damper - "
                                       "spring - frame_b)")

    def stored_energy(self):
        return self.c * (self.s - self.s_unstretched - self.s_damper)**2 / 2

    def loss_power(self):
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.f, self.c * (self.s - self.s_unstretched - self.s_damper)),
                ac.Eq(self.d * ac.der(self.s_damper), self.f),
                ac.Eq(self.lossPower, self.f * ac.der(self.s_damper))]


class LineForceWithMass(_OneMassOnLine):
    """A line force whose law is a 1-D translational element between ``flange_a`` and
    ``flange_b``, with an optional point mass on the line (MSL
    MultiBody.Forces.LineForceWithMass):

        flange_a.s = 0,   flange_b.s = length,   fa = flange_a.f,   fb = flange_b.f

    Connect both flanges (the MSL's treatment of a single connected flange, fa = -fb,
    needs cardinality(), which acausal has not).
    """

    flange_a = TranslationalFlange()
    flange_b = TranslationalFlange()

    def equations(self):
        return [ac.Eq(self.flange_a.s, 0), ac.Eq(self.flange_b.s, self.length),
                *self.line_forces(self.flange_a.f, self.flange_b.f)]


class LineForceWithTwoMasses(_PointMassesOnLine):
    """A line force whose law is a 1-D translational element between ``flange_a`` and
    ``flange_b``, with point masses m_a at L_a from frame_a and m_b at L_b from frame_b
    on the line (MSL MultiBody.Forces.LineForceWithTwoMasses; power balance of the line,
    L = length, e = e_rel_0):

        r_CM1_0 = r_0,a + e L_a,   r_CM2_0 = r_0,b - e L_b,
        ag_CMi_0 = der(der(r_CMi_0)) - world.gravityAcceleration(r_CMi_0),
        aux1 = ag_CM1_0 m_a L_a/L - ag_CM2_0 m_b L_b/L,   aux2 = aux1 - (aux1 . e) e,
        f1 = m_a ag_CM1_0 - aux2,   f2 = m_b ag_CM2_0 + aux2,
        flange_a.s = 0,   flange_b.s = L,   fa = flange_a.f,   fb = flange_b.f
    """

    m_a = ac.Parameter(0.0, unit="kg", min=0, description="point mass a on the line")
    m_b = ac.Parameter(0.0, unit="kg", min=0, description="point mass b on the line")
    L_a = ac.Parameter(0.0, unit="m", description="distance of mass a from frame_a, "
                                                  "towards frame_b")
    L_b = ac.Parameter(lambda c: c.L_a, unit="m",
                       description="distance of mass b from frame_b, towards frame_a")
    flange_a = TranslationalFlange()
    flange_b = TranslationalFlange()
    r_CM1_0 = ac.Variable(shape=3, unit="m", state_select="avoid",
                          description="position of point mass a, world frame")
    r_CM2_0 = ac.Variable(shape=3, unit="m", state_select="avoid",
                          description="position of point mass b, world frame")
    v_CM1_0 = ac.Variable(shape=3, unit="m/s", state_select="avoid", description="der(r_CM1_0)")
    v_CM2_0 = ac.Variable(shape=3, unit="m/s", state_select="avoid", description="der(r_CM2_0)")
    ag_CM1_0 = ac.Variable(shape=3, unit="m/s2",
                           description="der(v_CM1_0) - gravity acceleration")
    ag_CM2_0 = ac.Variable(shape=3, unit="m/s2",
                           description="der(v_CM2_0) - gravity acceleration")

    def equations(self):
        a, b = self.frame_a, self.frame_b
        e = sp.Matrix(self.e_rel_0)
        fa, fb = self.flange_a.f, self.flange_b.f
        flanges = [ac.Eq(self.flange_a.s, 0), ac.Eq(self.flange_b.s, self.length)]
        names = ("r_CM1_0", "r_CM2_0", "v_CM1_0", "v_CM2_0", "ag_CM1_0", "ag_CM2_0")
        r1, r2, v1, v2, ag1, ag2 = (sp.Matrix(getattr(self, n)) for n in names)
        if not (_mass(self, "m_a") or _mass(self, "m_b")):
            zero = sp.zeros(3, 1)
            return [*flanges, *(q for x in (r1, r2, v1, v2, ag1, ag2) for q in equal(x, zero)),
                    *self.cut_forces(fa, fb, zero, zero)]
        world = world_of(self)
        aux1 = ag1 * (self.m_a * self.L_a / self.length) - ag2 * (self.m_b * self.L_b
                                                                   / self.length)
        aux2 = aux1 - e * aux1.dot(e)
        return [*flanges,
                *equal(r1, position(a) + e * self.L_a),
                *equal(r2, position(b) - e * self.L_b),
                *equal(v1, r1.applyfunc(ac.der)), *equal(v2, r2.applyfunc(ac.der)),
                *equal(ag1, v1.applyfunc(ac.der) - world.gravityAcceleration(r1)),
                *equal(ag2, v2.applyfunc(ac.der) - world.gravityAcceleration(r2)),
                *self.cut_forces(fa, fb, self.m_a * ag1 - aux2, self.m_b * ag2 + aux2)]


def _signals(ports) -> sp.Matrix:
    return sp.Matrix([p.signal for p in ports])


class WorldForce(ac.Component):
    """Force given in world coordinates by three signals ``force[0..2]``, acting on
    frame_b at its origin (MSL MultiBody.Forces.WorldForce, resolveInFrame = world):

        f_b = -R_b force,   t_b = 0
    """

    frame_b = Frame()

    energy_role = "source"

    def build(self):
        self.force = [RealInput() for _ in range(3)]

    def equations(self):
        b = self.frame_b
        return [*equal(force(b), -resolve2(orientation(b), _signals(self.force))),
                *equal(torque(b), sp.zeros(3, 1))]


class WorldTorque(ac.Component):
    """Torque given in world coordinates by three signals ``torque[0..2]``, acting on
    frame_b (MSL MultiBody.Forces.WorldTorque, resolveInFrame = world):

        t_b = -R_b torque,   f_b = 0
    """

    frame_b = Frame()

    energy_role = "source"

    def build(self):
        self.torque = [RealInput() for _ in range(3)]

    def equations(self):
        b = self.frame_b
        return [*equal(torque(b), -resolve2(orientation(b), _signals(self.torque))),
                *equal(force(b), sp.zeros(3, 1))]


class ForceAndTorque(PartialTwoFrames):
    """A force and a torque between frame_a and frame_b, given by the signals
    ``force[0..2]`` and ``torque[0..2]`` resolved in ``resolveInFrame`` ("world",
    "frame_a", "frame_b" (default) or "frame_resolve", which then has a frame of that
    name that takes no force), acting on frame_b and, in reaction, on frame_a
    (MSL MultiBody.Forces.ForceAndTorque, its BasicForce and BasicTorque):

        f_b_0 = -force_0,   t_b_0 = -torque_0 (in the world),
        frame_b.f = R_b f_b_0,   frame_b.t = R_b t_b_0,
        frame_a.f = -R_a f_b_0,   frame_a.t = -R_a (t_b_0 + (r_0,b - r_0,a) x f_b_0)
    """

    energy_role = "source"

    def __init__(self, *, resolveInFrame: str = "frame_b", **modifications):
        if resolveInFrame not in RESOLVE_IN_FRAME:
            raise ac.InvalidValue(f"ForceAndTorque: resolveInFrame = {resolveInFrame!r} is "
                                  f"not one of {', '.join(RESOLVE_IN_FRAME)}")
        self.resolveInFrame = resolveInFrame
        super().__init__(**modifications)

    def build(self):
        self.force = [RealInput() for _ in range(3)]
        self.torque = [RealInput() for _ in range(3)]
        if self.resolveInFrame == "frame_resolve":
            self.frame_resolve = Frame()

    def _in_world(self, v) -> sp.Matrix:
        frame = {"world": None, "frame_a": self.frame_a, "frame_b": self.frame_b,
                 "frame_resolve": getattr(self, "frame_resolve", None)}[self.resolveInFrame]
        return v if frame is None else resolve1(orientation(frame), v)

    def equations(self):
        a, b = self.frame_a, self.frame_b
        f_b_0 = -self._in_world(_signals(self.force))
        t_b_0 = -self._in_world(_signals(self.torque))
        r_0 = position(b) - position(a)
        eqs = [*equal(force(b), resolve2(orientation(b), f_b_0)),
               *equal(torque(b), resolve2(orientation(b), t_b_0)),
               *equal(force(a), -resolve2(orientation(a), f_b_0)),
               *equal(torque(a), -resolve2(orientation(a), t_b_0 + r_0.cross(f_b_0)))]
        if self.resolveInFrame == "frame_resolve":
            zero = sp.zeros(3, 1)
            eqs += [*equal(force(self.frame_resolve), zero),
                    *equal(torque(self.frame_resolve), zero)]
        return eqs
