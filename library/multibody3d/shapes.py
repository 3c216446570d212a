"""Bodies whose mass and inertia follow from a shape of uniform density
(Modelica.Mechanics.MultiBody.Parts.BodyBox and BodyCylinder).

Each is a ``Body`` at frame_a and a massless bar from frame_a to frame_b at r, as
``BodyShape``; the shape lies along ``lengthDirection`` (by default r - r_shape) from
r_shape, its ``length`` by default |r - r_shape|, its width by default length/20 (the
World's defaultWidthFraction).  The derived mass, centre of mass and inertia are
numbers when the shape's parameters are numbers (the rotation from the shape's axes to
frame_a, MSL Frames.from_nxy, is then computed with the MSL's fallbacks for a zero or
parallel width direction), and expressions of them when they are bound to other
parameters.
"""
from __future__ import annotations

import numbers

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac

from .frames import from_nxy
from .interfaces import PartialRigidTwoFrames, equal
from .parts import Body, FixedTranslation

__all__ = ["BodyBox", "BodyCylinder"]

_WIDTH_FRACTION = 20     # MSL World.defaultWidthFraction


def _vector(c, prefix):
    """The values of ``<prefix>_1..3``: numbers (numpy) if they are, else sympy."""
    values = [c.parameter_value(f"{prefix}_{k}") for k in (1, 2, 3)]
    if all(isinstance(v, numbers.Real) for v in values):
        return np.array(values, dtype=float)
    return sp.Matrix(values)


def _difference(c, k):
    """r_k - r_shape_k, a number when both are numbers."""
    return _value(c, f"r_{k}") - _value(c, f"r_shape_{k}")


def _value(c, name):
    return c.parameter_value(name)


def _norm(v):
    if isinstance(v, np.ndarray):
        return float(np.linalg.norm(v))
    return sp.sqrt(v.dot(v))


def _rotation(n_x, n_y):
    """from_nxy: numbers when the directions are numbers, else the plain formula."""
    if isinstance(n_x, np.ndarray) and isinstance(n_y, np.ndarray):
        return sp.Matrix(from_nxy(n_x, n_y))
    n_x, n_y = sp.Matrix(n_x), sp.Matrix(n_y)
    e_x = n_x / sp.sqrt(n_x.dot(n_x))
    e_z = e_x.cross(n_y)
    e_z = e_z / sp.sqrt(e_z.dot(e_z))
    return sp.Matrix.vstack(e_x.T, e_z.cross(e_x).T, e_z.T)


def _centre_of_mass(c, k):
    e = _vector(c, "lengthDirection")
    e = e / _norm(e)
    return _vector(c, "r_shape")[k] + e[k] * _value(c, "length") / 2


def _inertia_entry(c, i, j):
    """I[i, j] = (R^T diag(I_shape) R)[i, j], R from frame_a to the shape's axes."""
    R = _rotation(_vector(c, "lengthDirection"), _vector(c, "widthDirection"))
    I = R.T * sp.diag(*c.principal_inertia()) * R
    value = I[i, j]
    return float(value) if value.is_number else value


class _PartialShape(PartialRigidTwoFrames):
    """The shape's placement and the Body and bar it is made of."""

    r_1 = ac.Parameter(0.1, unit="m", description="frame_b from frame_a, x (in frame_a)")
    r_2 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, y (in frame_a)")
    r_3 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, z (in frame_a)")
    r_shape_1 = ac.Parameter(0.0, unit="m", description="shape origin from frame_a, x")
    r_shape_2 = ac.Parameter(0.0, unit="m", description="shape origin from frame_a, y")
    r_shape_3 = ac.Parameter(0.0, unit="m", description="shape origin from frame_a, z")
    lengthDirection_1 = ac.Parameter(lambda c: _difference(c, 1),
                                     description="length direction in frame_a, x")
    lengthDirection_2 = ac.Parameter(lambda c: _difference(c, 2),
                                     description="length direction in frame_a, y")
    lengthDirection_3 = ac.Parameter(lambda c: _difference(c, 3),
                                     description="length direction in frame_a, z")
    length = ac.Parameter(lambda c: _norm(_vector(c, "r") - _vector(c, "r_shape")),
                          unit="m", description="length of the shape, |r - r_shape|")
    density = ac.Parameter(7700.0, unit="kg/m3", min=0,
                           description="density (steel 7700 .. 7900, wood 400 .. 800)")
    r_CM_1 = ac.Parameter(lambda c: _centre_of_mass(c, 0), unit="m",
                          description="centre of mass from frame_a, x")
    r_CM_2 = ac.Parameter(lambda c: _centre_of_mass(c, 1), unit="m",
                          description="centre of mass from frame_a, y")
    r_CM_3 = ac.Parameter(lambda c: _centre_of_mass(c, 2), unit="m",
                          description="centre of mass from frame_a, z")
    I_11 = ac.Parameter(lambda c: _inertia_entry(c, 0, 0), unit="kg.m2",
                        description="inertia I[1,1] about the CM, in frame_a")
    I_22 = ac.Parameter(lambda c: _inertia_entry(c, 1, 1), unit="kg.m2",
                        description="inertia I[2,2] about the CM, in frame_a")
    I_33 = ac.Parameter(lambda c: _inertia_entry(c, 2, 2), unit="kg.m2",
                        description="inertia I[3,3] about the CM, in frame_a")
    I_21 = ac.Parameter(lambda c: _inertia_entry(c, 1, 0), unit="kg.m2",
                        description="inertia I[2,1] about the CM, in frame_a")
    I_31 = ac.Parameter(lambda c: _inertia_entry(c, 2, 0), unit="kg.m2",
                        description="inertia I[3,1] about the CM, in frame_a")
    I_32 = ac.Parameter(lambda c: _inertia_entry(c, 2, 1), unit="kg.m2",
                        description="inertia I[3,2] about the CM, in frame_a")
    r_0 = ac.Variable(shape=3, unit="m", description="position of frame_a's origin, world frame")
    v_0 = ac.Variable(shape=3, unit="m/s", description="velocity of frame_a's origin, world frame")
    a_0 = ac.Variable(shape=3, unit="m/s2",
                      description="acceleration of frame_a's origin, world frame")
    body = Body(m=ac.ref("m"), r_CM_1=ac.ref("r_CM_1"), r_CM_2=ac.ref("r_CM_2"),
                r_CM_3=ac.ref("r_CM_3"), I_11=ac.ref("I_11"), I_22=ac.ref("I_22"),
                I_33=ac.ref("I_33"), I_21=ac.ref("I_21"), I_31=ac.ref("I_31"),
                I_32=ac.ref("I_32"))
    frameTranslation = FixedTranslation(r_1=ac.ref("r_1"), r_2=ac.ref("r_2"),
                                        r_3=ac.ref("r_3"))

    def equations(self):
        return [*equal(sp.Matrix(self.r_0), sp.Matrix(self.body.r_0)),
                *equal(sp.Matrix(self.v_0), sp.Matrix(self.body.v_0)),
                *equal(sp.Matrix(self.a_0), sp.Matrix(self.body.a_0)),
                ac.connect(self.frame_a, self.body.frame_a, self.frameTranslation.frame_a),
                ac.connect(self.frameTranslation.frame_b, self.frame_b)]


class BodyBox(_PartialShape):
    """A box of the given length (along lengthDirection), width (along widthDirection)
    and height, hollow inside innerWidth x innerHeight (MSL MultiBody.Parts.BodyBox):

        mo = rho L w h,   mi = rho L w_i h_i,   m = mo - mi,
        r_CM = r_shape + e_length L/2,
        I = R^T diag(mo (w^2 + h^2) - mi (w_i^2 + h_i^2), mo (L^2 + h^2) - mi (L^2 + h_i^2),
                     mo (L^2 + w^2) - mi (L^2 + w_i^2)) R / 12

    R = from_nxy(lengthDirection, widthDirection) turns frame_a into the box's axes.
    """

    widthDirection_1 = ac.Parameter(0.0, description="width direction in frame_a, x")
    widthDirection_2 = ac.Parameter(1.0, description="width direction in frame_a, y")
    widthDirection_3 = ac.Parameter(0.0, description="width direction in frame_a, z")
    width = ac.Parameter(lambda c: c.length / _WIDTH_FRACTION, unit="m",
                         description="width of the box (length/20)")
    height = ac.Parameter(lambda c: c.width, unit="m", description="height of the box")
    innerWidth = ac.Parameter(0.0, unit="m", description="width of the inner box surface")
    innerHeight = ac.Parameter(lambda c: c.innerWidth, unit="m",
                               description="height of the inner box surface")
    mo = ac.Parameter(lambda c: c.density * c.length * c.width * c.height, unit="kg",
                      description="mass of the box without its hole")
    mi = ac.Parameter(lambda c: c.density * c.length * c.innerWidth * c.innerHeight,
                      unit="kg", description="mass of the hole")
    m = ac.Parameter(lambda c: c.mo - c.mi, unit="kg", description="mass of the box")

    def principal_inertia(self):
        L, w, h = self.length, self.width, self.height
        wi, hi, mo, mi = self.innerWidth, self.innerHeight, self.mo, self.mi
        return [(mo * (w**2 + h**2) - mi * (wi**2 + hi**2)) / 12,
                (mo * (L**2 + h**2) - mi * (L**2 + hi**2)) / 12,
                (mo * (L**2 + w**2) - mi * (L**2 + wi**2)) / 12]


class BodyCylinder(_PartialShape):
    """A cylinder (a tube if innerDiameter > 0) of the given length along
    lengthDirection (MSL MultiBody.Parts.BodyCylinder):

        mo = rho pi L r^2,   mi = rho pi L r_i^2,   m = mo - mi,
        I22 = (mo (L^2 + 3 r^2) - mi (L^2 + 3 r_i^2)) / 12,
        I = R^T diag((mo r^2 - mi r_i^2)/2, I22, I22) R

    R = from_nxy(lengthDirection, (0, 1, 0)).
    """

    widthDirection_1 = ac.Parameter(0.0, description="(fixed) width direction, x")
    widthDirection_2 = ac.Parameter(1.0, description="(fixed) width direction, y")
    widthDirection_3 = ac.Parameter(0.0, description="(fixed) width direction, z")
    diameter = ac.Parameter(lambda c: c.length / _WIDTH_FRACTION, unit="m",
                            description="diameter of the cylinder (length/20)")
    innerDiameter = ac.Parameter(0.0, unit="m", description="inner diameter of the cylinder")
    mo = ac.Parameter(lambda c: c.density * sp.pi * c.length * c.diameter**2 / 4, unit="kg",
                      description="mass of the cylinder without its hole")
    mi = ac.Parameter(lambda c: c.density * sp.pi * c.length * c.innerDiameter**2 / 4,
                      unit="kg", description="mass of the hole")
    m = ac.Parameter(lambda c: c.mo - c.mi, unit="kg", description="mass of the cylinder")

    def principal_inertia(self):
        L, r, ri = self.length, self.diameter / 2, self.innerDiameter / 2
        mo, mi = self.mo, self.mi
        I22 = (mo * (L**2 + 3 * r**2) - mi * (L**2 + 3 * ri**2)) / 12
        return [(mo * r**2 - mi * ri**2) / 2, I22, I22]
