"""Rigid bodies turning in space: the heavy symmetric top on a ball joint and the free
body spinning near its intermediate axis (Egeland & Gravdahl 7.3.8-7.3.9, Euler's
equations (7.104)-(7.106); the orientation in Euler parameters, 6.9.6).

* ``HeavyTop``: a symmetric top, its tip on a Spherical joint at the World's origin,
  its symmetry axis the body's y, the centre of mass l along it.  Started in steady
  precession: tilted by theta from the vertical, with spin omega_3 about the symmetry
  axis and the precession rate Omega about the vertical that solves the steady-state
  condition

      Omega (I_3 omega_3 - I_1' Omega cos(theta)) = m g l,   I_1' = I_1 + m l^2

  (the slow root), the axis turns about the vertical at Omega with theta constant.
* ``TennisRacket``: a free body (FreeMotion from the World, no gravity) with principal
  inertias I_1 < I_2 < I_3, spun about the intermediate axis with a small disturbance:
  it flips over again and again (the intermediate-axis instability) while its kinetic
  energy and its angular momentum in the world stay constant.
"""
import numpy as np

import acausal as ac
from acausal.library.multibody3d import Body, FreeMotion, Spherical, World

__all__ = ["HeavyTop", "TennisRacket", "top_precession_rate"]

TOP = dict(m=1.0, l=0.1, I_1=0.002, I_3=0.004, theta=0.5, omega_3=100.0, g=9.80665)


def top_precession_rate(m, l, I_1, I_3, theta, omega_3, g):
    """The slow steady precession rate Omega of the heavy symmetric top (module
    docstring)."""
    I_1p = I_1 + m * l**2
    a, b, c = I_1p * np.cos(theta), -I_3 * omega_3, m * g * l
    return (-b - np.sqrt(b**2 - 4 * a * c)) / (2 * a)


def _top_start():
    p = TOP
    Omega = top_precession_rate(**p)
    # tilted about the world's z: the symmetry axis at (-sin theta, cos theta, 0); the
    # vertical in body coordinates is (sin theta, cos theta, 0), so
    # w = Omega (sin theta, cos theta, 0) + (omega_3 - Omega cos theta) (0, 1, 0)
    th = p["theta"]
    return dict(angles_start=(0.0, 0.0, th), angles_fixed=True,
                w_rel={"start": [Omega * np.sin(th), p["omega_3"], 0.0], "fixed": True})


class HeavyTop(ac.Component):
    """m = 1 kg, l = 0.1 m, I_1 = 0.002 kg m^2, I_3 = 0.004 kg m^2 about the centre of
    mass; tilted 0.5 rad, spinning at 100 rad/s, in steady precession."""

    stop_time = 2.0
    world = World()
    pivot = Spherical(**_top_start())
    top = Body(m=TOP["m"], r_CM_2=TOP["l"], I_11=TOP["I_1"], I_22=TOP["I_3"],
               I_33=TOP["I_1"])

    def equations(self):
        return [ac.connect(self.world.frame_b, self.pivot.frame_a),
                ac.connect(self.pivot.frame_b, self.top.frame_a)]


RACKET = dict(I_1=1.0, I_2=2.0, I_3=3.0, w=(0.01, 1.0, 0.01))


def _fixed(value):
    return {"start": value, "fixed": True}


class TennisRacket(ac.Component):
    """Principal inertias 1, 2, 3 kg m^2; w = (0.01, 1, 0.01) rad/s in the body at the
    start, no gravity; the body flips over five times in 100 s."""

    stop_time = 100.0
    world = World(g=0.0)
    joint = FreeMotion(angles_fixed=True, w_rel_b=_fixed(list(RACKET["w"])),
                       r_rel_a=_fixed(0.0), v_rel_a=_fixed(0.0))
    body = Body(m=1.0, I_11=RACKET["I_1"], I_22=RACKET["I_2"], I_33=RACKET["I_3"])

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.body.frame_a)]


if __name__ == "__main__":
    for model in (HeavyTop, TennisRacket):
        compiled = ac.compile(model())
        print(compiled.report)
        res = ac.simulate(compiled, t_end=model.stop_time, rtol=1e-8)
        print(model.__name__, res.stats)
