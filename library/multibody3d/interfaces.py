"""Partial models of spatial multibody mechanics (Modelica.Mechanics.MultiBody.Interfaces).

Which component writes a frame's orientation R (the overdetermined part of the
connector, ``acausal.ports.spatial``): the World, and every joint and rigid part for its
frame_b from its frame_a (``propagate``).  Bodies, force elements and sensors only read
it.

The World is found as Modelica finds an ``inner`` declaration (``world.world_of``):
the nearest enclosing component that has a World among its sub-components.  Bodies read
the gravity field there (``World.gravityAcceleration``), at their own centre of mass.
"""
from __future__ import annotations

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports.spatial import Frame

from .frames import orientation, unit

__all__ = ["PartialOneFrame_a", "PartialTwoFrames", "PartialRigidTwoFrames", "propagate",
           "equal", "direction", "vector_of"]


def equal(lhs, rhs) -> list:
    """Entry-wise ac.Eq of two equally shaped matrices (vector and matrix equations as
    the MSL writes them)."""
    lhs, rhs = sp.Matrix(lhs), sp.Matrix(rhs)
    return [ac.Eq(a, b) for a, b in zip(lhs, rhs)]


def direction(component, prefix: str = "n") -> sp.Matrix:
    """The unit vector of the component's parameters ``<prefix>_1..3`` (an axis, the
    direction of gravity).

    Given as numbers, the vector is normalized here and enters the equations as numbers
    (an axis is structural: the compiler already takes its zero entries as structural
    zeros, and sqrt(n_2^2) of the symbolic form would become |n_2|, a relation that the
    solver watched as a zero crossing).  Bound to other parameters (``ac.ref``), it is
    normalized symbolically.  All three equal to 0 define no direction: an
    ``InvalidValue`` naming the component, rather than a division by zero that the
    compiler would report as a structurally singular model."""
    names = [f"{prefix}_{k}" for k in (1, 2, 3)]
    values = [component.parameter_value(n) for n in names]
    if all(isinstance(v, (int, float)) for v in values):
        norm = sum(v * v for v in values) ** 0.5
        if norm == 0:
            where = f"'{component.path}' ({type(component).__name__})"
            raise ac.InvalidValue(f"{where}: {', '.join(names)} are all 0, so the vector "
                                  f"{prefix} has no direction")
        return sp.Matrix([v / norm for v in values])
    return unit([getattr(component, n) for n in names])


def vector_of(component, prefix: str) -> sp.Matrix:
    """The 3-vector of the component's scalar parameters ``<prefix>_1..3`` (the MSL's
    ``r_CM[1..3]``), as symbols."""
    return sp.Matrix([getattr(component, f"{prefix}_{k}") for k in (1, 2, 3)])


def propagate(frame_a, frame_b, R_rel=None) -> list:
    """The branch of the spanning tree from frame_a to frame_b (MSL Connections.branch
    written in one direction): R_b = R_rel R_a."""
    R_a = orientation(frame_a)
    R_b = R_a if R_rel is None else R_rel * R_a
    return equal(orientation(frame_b), R_b)


class PartialOneFrame_a(ac.Component):
    """One frame, frame_a, that reads its orientation from what it is connected to."""

    frame_a = Frame()


class PartialTwoFrames(ac.Component):
    """Two frames, frame_a and frame_b."""

    frame_a = Frame()
    frame_b = Frame()


class PartialRigidTwoFrames(PartialTwoFrames):
    """Two frames of which frame_b follows frame_a: the component writes frame_b's
    position and orientation from frame_a's, and frame_a's cut force and torque."""
