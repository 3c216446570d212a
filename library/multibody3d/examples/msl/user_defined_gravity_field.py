"""Modelica.Mechanics.MultiBody.Examples.Elementary.UserDefinedGravityField (MSL v4.0.0):
a pendulum of 1000 kg, 10 m long, on a damped revolute joint 20 m above the WGS84 earth
ellipsoid, in the WGS84 normal gravity field (which weakens with the height above the
ellipsoid, here the world's y).

The MSL redeclares the World's gravityAcceleration function; here a World subclass
overrides ``gravityAcceleration`` with the field of
Examples.Elementary.Utilities.theoreticalNormalGravityWGS84.
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.library.multibody3d import Body, FixedTranslation, Revolute, World
from acausal.library.rotational import Damper

from . import MSLNames

__all__ = ["UserDefinedGravityField", "WGS84World"]


class WGS84World(World):
    """A World whose field is the WGS84 normal gravity over the earth ellipsoid, in -y,
    at the geodetic latitude phi, y being the height over the ellipsoid (MSL
    Examples.Elementary.Utilities.theoreticalNormalGravityWGS84, its constants as
    parameters with their units):

        g_n = g_e (1 + k sin^2 phi) / sqrt(1 - e^2 sin^2 phi),   h = r[2],
        g_h = g_n (1 - h/a (2 (1 + f + m - 2 f sin^2 phi) + 3 h/a)),   gravity = (0, -g_h, 0)

    with k = (b/a)(g_p/g_e) - 1 and m = w^2 a^2 b / GM.
    """

    phi = ac.Parameter(0.0, unit="deg", description="geodetic latitude")
    a = ac.Parameter(6378137.0, unit="m", description="semi-major axis of the ellipsoid")
    b = ac.Parameter(6356752.3142, unit="m", description="semi-minor axis of the ellipsoid")
    g_e = ac.Parameter(9.7803253359, unit="m/s2", description="gravity at the equator")
    g_p = ac.Parameter(9.8321849378, unit="m/s2", description="gravity at the poles")
    e2 = ac.Parameter(8.1819190842622e-2**2, description="first eccentricity squared")
    f = ac.Parameter(1 / 298.257223563, description="flattening of the ellipsoid")
    w = ac.Parameter(7292115e-11, unit="rad/s", description="angular velocity of the earth")
    GM = ac.Parameter(3986004.418e8, unit="m3/s2",
                      description="the earth's gravitational constant")

    def gravityAcceleration(self, r):
        k = (self.b / self.a) * (self.g_p / self.g_e) - 1
        m = self.w**2 * self.a**2 * self.b / self.GM
        sinphi2 = sp.sin(self.phi * sp.pi / 180)**2
        g_n = self.g_e * (1 + k * sinphi2) / sp.sqrt(1 - self.e2 * sinphi2)
        ha = r[1] / self.a
        g_h = g_n * (1 - ha * (2 * (1 + self.f + m - 2 * self.f * sinphi2) + 3 * ha))
        return sp.Matrix([0, -g_h, 0])


class UserDefinedGravityField(ac.Component):
    """Demonstrate the modeling of a user-defined gravity field."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.UserDefinedGravityField"
    stop_time = 10.0
    tolerance = 1e-9
    msl_signals = MSLNames()

    geodeticLatitude = ac.Parameter(0.0, unit="deg", description="geodetic latitude")
    height = ac.Parameter(20.0, unit="m",
                          description="height of the pendulum's pivot over the ellipsoid")
    gravity = ac.Variable(shape=3, unit="m/s2",
                          description="gravity acceleration at the body's centre of mass")
    world = WGS84World(gravityType="NoGravity", phi=ac.ref("geodeticLatitude"))
    rev = Revolute(n_1=0.0, n_2=0.0, n_3=1.0, phi={"fixed": True}, w={"fixed": True})
    damper = Damper(d=0.1)
    body = Body(r_CM_1=10.0, r_CM_2=0.0, r_CM_3=0.0, m=1000.0)
    fixedTranslation = FixedTranslation(r_1=0.0, r_2=ac.ref("height"), r_3=0.0)

    def equations(self):
        return [*(ac.Eq(g, g0) for g, g0 in zip(self.gravity, self.body.g_0)),
                ac.connect(self.damper.flange_b, self.rev.axis),
                ac.connect(self.rev.support, self.damper.flange_a),
                ac.connect(self.body.frame_a, self.rev.frame_b),
                ac.connect(self.world.frame_b, self.fixedTranslation.frame_a),
                ac.connect(self.fixedTranslation.frame_b, self.rev.frame_a)]
