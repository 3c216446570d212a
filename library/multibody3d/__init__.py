"""Spatial multibody mechanics (shaped like Modelica.Mechanics.MultiBody).

The frame (``acausal.ports.spatial.Frame``) carries the orientation R as nine across
variables, three of them independent: an overdetermined connector.  The MSL writes the
nine equalities along a spanning tree of the connections (Connections.root/branch) and
three residues where a loop closes; this framework has no such rule, and a connection
writes every across equality.  So R is written in one direction only: the World writes
its frame's R = I, every joint and rigid part writes R_b = R_rel R_a for its frame_b,
and bodies, force elements and sensors only read R.  Every connection set then holds
exactly one frame whose R is written, and the nine equalities of a connection are
balanced.  The price: a kinematic loop would write R twice (the compiler refuses it as
over-determined, naming the frame's hint) unless it is closed by a joint that writes no
orientation (``RevolutePlanarLoopConstraint``, the MSL's joint for planar loops);
frame_a of a joint must face the World; and a free body needs an explicit FreeMotion
joint (the MSL's body states, made a component).

Bodies find the World as Modelica finds ``inner World world``: the nearest enclosing
component that has a World among its sub-components (``world.world_of``), and read
its gravity field (uniform, point or user-defined) at their centre of mass.
"""
from ... import _lazy_exports

__all__ = ["World", "Fixed", "Body", "BodyShape", "BodyBox", "BodyCylinder", "PointMass",
           "FixedTranslation", "FixedRotation", "Revolute", "Prismatic", "Spherical",
           "FreeMotion", "Universal", "RevolutePlanarLoopConstraint", "FreeMotionScalarInit",
           "JointUPS", "Spring", "Damper",
           "SpringDamperParallel", "SpringDamperSeries", "LineForceWithMass",
           "LineForceWithTwoMasses",
           "WorldForce", "WorldTorque", "ForceAndTorque", "AbsolutePosition",
           "AbsoluteVelocity", "AbsoluteAngularVelocity", "RelativePosition",
           "CutForceAndTorque", "RollingWheel", "RollingWheelSet", "RollingWheelJoint",
           "RollingWheelSetJoint", "Mounting1D", "WhippleBicycle", "Wheelset", "WheelsetDAE"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".world": ("World",),
    ".parts": ("Fixed", "Body", "BodyShape", "PointMass", "FixedTranslation",
               "FixedRotation"),
    ".shapes": ("BodyBox", "BodyCylinder"),
    ".joints": ("Revolute", "Prismatic", "Spherical", "FreeMotion", "Universal",
                "RevolutePlanarLoopConstraint", "FreeMotionScalarInit"),
    ".assemblies": ("JointUPS",),
    ".forces": ("Spring", "Damper", "SpringDamperParallel", "SpringDamperSeries",
                "LineForceWithMass",
                "LineForceWithTwoMasses", "WorldForce", "WorldTorque", "ForceAndTorque"),
    ".sensors": ("AbsolutePosition", "AbsoluteVelocity", "AbsoluteAngularVelocity",
                 "RelativePosition", "CutForceAndTorque"),
    ".wheels": ("RollingWheel", "RollingWheelSet", "RollingWheelJoint",
                "RollingWheelSetJoint", "Mounting1D"),
    ".bicycle": ("WhippleBicycle",),
    ".wheelset": ("Wheelset",),
    ".wheelset_dae": ("WheelsetDAE",),
}, submodules=("frames", "interfaces"))
