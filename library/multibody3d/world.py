"""The World: the inertial frame and the gravity field (Modelica.Mechanics.MultiBody.World
with Forces.Internal.standardGravityAcceleration).

Bodies find the World as Modelica finds ``inner World world`` (:func:`world_of`)
and evaluate its field at their centre of mass, g_0 = gravityAcceleration(r_CM,0):

* ``gravityType="UniformGravity"`` (default): g_0 = g n/|n|;
* ``"PointGravity"``: g_0 = -mu/|r|^2 r/|r|, a point mass at the world's origin;
* ``"NoGravity"``: g_0 = 0.

A user-defined field is a subclass that overrides ``gravityAcceleration(r)`` (the MSL's
``redeclare function gravityAcceleration``): the method returns the acceleration at r
(world coordinates) as a 3-vector of expressions in r and the subclass's parameters.
"""
from __future__ import annotations

import difflib

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports.spatial import Frame

from .frames import orientation, position
from .interfaces import direction, equal

__all__ = ["World", "GRAVITY_TYPES", "world_of"]

GRAVITY_TYPES = ("NoGravity", "UniformGravity", "PointGravity")


class World(ac.Component):
    """The inertial frame and the gravity field (MSL MultiBody.World):

        frame_b.r_0 = 0,   frame_b.R = I

    One per model: it is the root of the spanning tree along which orientation
    travels (``acausal.ports.spatial``), and its field acts on every body below the
    component that holds it.  The defaults are the MSL's: g = 9.80665 m/s2 along -y,
    mu = 3.986004418e14 m3/s2 (the earth's field constant).  ``gravityType`` is given
    when the World is made: ``World(gravityType="PointGravity", mu=1)``.
    """

    g = ac.Parameter(9.80665, unit="m/s2", description="constant gravity acceleration")
    n_1 = ac.Parameter(0.0, description="direction of gravity, world x")
    n_2 = ac.Parameter(-1.0, description="direction of gravity, world y")
    n_3 = ac.Parameter(0.0, description="direction of gravity, world z")
    mu = ac.Parameter(3.986004418e14, unit="m3/s2", min=0,
                      description="field constant of the point gravity field")
    frame_b = Frame()

    energy_role = "lossless"  # fixed in the world: does no work

    def __init__(self, *, gravityType: str = "UniformGravity", **modifications):
        if gravityType not in GRAVITY_TYPES:
            close = difflib.get_close_matches(str(gravityType), GRAVITY_TYPES, n=1)
            hint = f" (did you mean '{close[0]}'?)" if close else ""
            raise ac.InvalidValue(f"World: gravityType = {gravityType!r} is not one of "
                                  f"{', '.join(GRAVITY_TYPES)}{hint}")
        super().__init__(**modifications)
        self.gravityType = gravityType

    def gravityAcceleration(self, r) -> sp.Matrix:
        """The gravity acceleration at r (world coordinates), resolved in the world
        (MSL Forces.Internal.standardGravityAcceleration)."""
        r = sp.Matrix(r)
        if self.gravityType == "UniformGravity":
            return self.g * direction(self, "n")
        if self.gravityType == "PointGravity":
            return -self.mu * r / sp.sqrt(r.dot(r))**3
        return sp.zeros(3, 1)

    def gravityPotential(self, r):
        """The potential V(r) of the field, g_0 = -grad V (for the energy audit).  A
        subclass with its own gravityAcceleration overrides it, or bodies in its field
        declare no potential energy."""
        if type(self).gravityAcceleration is not World.gravityAcceleration:
            raise NotImplementedError(f"{type(self).__name__} defines its own field; "
                                      "give its potential in gravityPotential(r)")
        r = sp.Matrix(r)
        if self.gravityType == "UniformGravity":
            return -(self.g * direction(self, "n")).dot(r)
        if self.gravityType == "PointGravity":
            return -self.mu / sp.sqrt(r.dot(r))
        return sp.Integer(0)

    def equations(self):
        f = self.frame_b
        return [*equal(position(f), sp.zeros(3, 1)),
                *equal(orientation(f), sp.eye(3))]


def world_of(component):
    """The World that ``component`` sees (MSL ``outer World world``): the first World
    among the sub-components of its enclosing components, the nearest first.
    ``NotInModel`` if there is none."""
    node = component._parent
    while node is not None:
        for child in node.children().values():
            if isinstance(child, World):
                return child
        node = node._parent
    raise ac.NotInModel(f"{component._describe()} needs the gravity field of a World, and "
                        "no enclosing component has a World among its sub-components (the "
                        "MSL's 'inner World world'): add one, world = World()")
