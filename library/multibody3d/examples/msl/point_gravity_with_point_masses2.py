"""Modelica.Mechanics.MultiBody.Examples.Elementary.PointGravityWithPointMasses2 (MSL
v4.0.0): six point masses of 1 kg rigidly joined by bars 1 m long along +-x, +-y, +-z
from a centre that moves freely (a FreeMotion joint from the World) in the point
gravity field of the World (mu = 5 m3/s2), started by the positions and velocities of
four of the masses; and, for comparison, the same system made of Bodies with zero
inertia (``SystemWithStandardBodies``), whose free-motion states (the MSL's root body
pointMass1, started with its orientation and angular velocity) are on a FreeMotion
from the World to pointMass1.
"""
import acausal as ac
from acausal.library.multibody3d import Body, FixedTranslation, FreeMotion, PointMass, World

from . import MSLNames

__all__ = ["PointGravityWithPointMasses2", "SystemWithStandardBodies"]

_ARMS = {"fixedTranslation": (1.0, 0.0, 0.0), "fixedTranslation1": (-1.0, 0.0, 0.0),
         "fixedTranslation2": (0.0, 1.0, 0.0), "fixedTranslation3": (0.0, -1.0, 0.0),
         "fixedTranslation4": (0.0, 0.0, 1.0), "fixedTranslation5": (0.0, 0.0, -1.0)}
# which arm carries which mass
_MASS_OF = {"fixedTranslation": "pointMass1", "fixedTranslation1": "pointMass2",
            "fixedTranslation2": "pointMass3", "fixedTranslation3": "pointMass4",
            "fixedTranslation4": "pointMass5", "fixedTranslation5": "pointMass6"}


def _arm(r):
    return FixedTranslation(r_1=r[0], r_2=r[1], r_3=r[2])


def _body():
    """Body used at all places of the comparison model, with zero inertia tensor."""
    return Body(m=1.0, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0, I_11=0.0, I_22=0.0, I_33=0.0,
                I_21=0.0, I_31=0.0, I_32=0.0)


class SystemWithStandardBodies(ac.Component):
    """For comparison purposes, an equivalent model with Bodies instead of PointMasses:
    the free body's states on a FreeMotion from the World to pointMass1 (r_0 = (3, 0,
    0), v_0 = (0, 0, -1), not turned, not turning), the arms from the centre turned
    round for fixedTranslation, which now leads from pointMass1 back to the centre."""

    freeMotion = FreeMotion(r_rel_a={"start": [3.0, 0.0, 0.0], "fixed": True},
                            v_rel_a={"start": [0.0, 0.0, -1.0], "fixed": True},
                            angles_fixed=True, w_rel_b={"fixed": True})

    def build(self):
        for name, r in _ARMS.items():
            setattr(self, name, _arm(r))
        for k in range(1, 7):
            setattr(self, f"pointMass{k}", _body())

    def frame_a(self):
        """The frame the FreeMotion drives (the MSL's root body)."""
        return self.pointMass1.frame_a

    def equations(self):
        centre = self.fixedTranslation1.frame_a
        return [*(ac.connect(centre, getattr(self, name).frame_a) for name in _ARMS
                  if name != "fixedTranslation1"),
                *(ac.connect(getattr(self, arm).frame_b, getattr(self, mass).frame_a)
                  for arm, mass in _MASS_OF.items())]


class PointGravityWithPointMasses2(ac.Component):
    """Rigidly connected point masses in a point gravity field."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.PointGravityWithPointMasses2"
    stop_time = 3.0
    tolerance = 1e-7
    msl_signals = MSLNames()
    msl_known_failure = (
        "reference: freeMotion.v_rel_a[3] differs by 1.9e-3 of its amplitude from the "
        "model solved at 1e-10 (acausal at the tolerance 1e-7: 3.6e-4)")

    world = World(gravityType="PointGravity", mu=5.0)
    freeMotion = FreeMotion()
    referenceSystem = SystemWithStandardBodies()
    pointMass1 = PointMass(m=1.0, r_0={"start": [3.0, 0.0, 0.0], "fixed": True},
                           v_0={"start": [0.0, 0.0, -1.0], "fixed": True})
    pointMass2 = PointMass(m=1.0)
    pointMass3 = PointMass(m=1.0, r_0={"start": [2.0, 1.0, 0.0], "fixed": [True, False, False]},
                           v_0={"start": [0.0, 0.0, -1.0], "fixed": [True, False, False]})
    pointMass4 = PointMass(m=1.0, r_0={"start": [2.0, -1.0, 0.0], "fixed": [False, False, True]},
                           v_0={"start": [0.0, 0.0, -1.0], "fixed": [False, False, True]})
    pointMass5 = PointMass(m=1.0, r_0={"start": [2.0, 0.0, 1.0], "fixed": [False, False, True]},
                           v_0={"start": [0.0, 0.0, -1.0], "fixed": [False, False, True]})
    pointMass6 = PointMass(m=1.0)

    def build(self):
        for name, r in _ARMS.items():
            setattr(self, name, _arm(r))

    def equations(self):
        centre = self.fixedTranslation1.frame_a
        ref = self.referenceSystem
        return [*(ac.connect(centre, getattr(self, name).frame_a) for name in _ARMS
                  if name != "fixedTranslation1"),
                *(ac.connect(getattr(self, arm).frame_b, getattr(self, mass).frame_a)
                  for arm, mass in _MASS_OF.items()),
                ac.connect(self.world.frame_b, self.freeMotion.frame_a),
                ac.connect(self.freeMotion.frame_b, centre),
                ac.connect(self.world.frame_b, ref.freeMotion.frame_a),
                ac.connect(ref.freeMotion.frame_b, ref.frame_a())]
