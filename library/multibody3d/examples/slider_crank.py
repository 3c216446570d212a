"""Slider-crank mechanism in 3-D: a closed planar loop (the planar library's
``slider_crank``, built from spatial parts).

A crank of length r turns at constant speed about the world's z; a connecting rod of
length l (mass m_rod, centre of mass at its middle) joins the crank pin to a slider
(mass m_s) on a guide along the world's x through the pivot:

    x_s = r cos(theta) + sqrt(l^2 - r^2 sin(theta)^2)

The orientation is written along a tree (``acausal.library.multibody3d``): world -
crank - rod on one branch, world - guide - slider on the other.  The loop closes at
the rod's end with a ``RevolutePlanarLoopConstraint``, which writes only the two
position constraints in the plane, as in the MSL's planar loops.
"""
import acausal as ac
from acausal.library.multibody.examples.slider_crank import slider_position
from acausal.library.multibody3d import (Body, FixedTranslation, Prismatic, Revolute,
                                         RevolutePlanarLoopConstraint, World)
from acausal.library.rotational import ConstantSpeed

__all__ = ["SliderCrank", "slider_position"]


class SliderCrank(ac.Component):
    """r = 0.1 m, l = 0.3 m, crank at 10 rad/s from theta = 0.3 rad; rod 0.5 kg
    (slender, I = m l^2/12 about its centre), slider 1 kg; g = 9.81 m/s^2 in -y."""

    stop_time = 1.0
    r = ac.Parameter(0.1, unit="m", description="crank length")
    l = ac.Parameter(0.3, unit="m", description="connecting rod length")
    half_l = ac.Parameter(lambda c: c.l / 2, unit="m", description="l / 2")
    m_rod = ac.Parameter(0.5, unit="kg", description="connecting rod mass")
    I_rod = ac.Parameter(lambda c: c.m_rod * c.l**2 / 12, unit="kg.m2",
                         description="rod inertia about its centre, normal to it")
    m_s = ac.Parameter(1.0, unit="kg", description="slider mass")
    drive = ConstantSpeed(w_fixed=10.0)
    world = World(g=9.81)
    crank_joint = Revolute(phi={"start": 0.3, "fixed": True})
    crank = FixedTranslation(r_1=ac.ref("r"))
    # the rod's angle follows from the crank's: no preference, start on the intended
    # branch (rod to the right of the crank)
    pin = Revolute(phi={"start": -0.4, "state_select": "default"},
                   w={"state_select": "default"})
    rod_a = FixedTranslation(r_1=ac.ref("half_l"))
    rod = Body(m=ac.ref("m_rod"), I_11=0.0, I_22=ac.ref("I_rod"), I_33=ac.ref("I_rod"))
    rod_b = FixedTranslation(r_1=ac.ref("half_l"))
    loop = RevolutePlanarLoopConstraint(n=(0.0, 0.0, 1.0))
    guide = Prismatic(s={"start": 0.39, "state_select": "default"},
                      v={"state_select": "default"})
    slider = Body(m=ac.ref("m_s"))

    def equations(self):
        return [ac.connect(self.drive.flange, self.crank_joint.axis),
                ac.connect(self.world.frame_b, self.crank_joint.frame_a, self.guide.frame_a),
                ac.connect(self.crank_joint.frame_b, self.crank.frame_a),
                ac.connect(self.crank.frame_b, self.pin.frame_a),
                ac.connect(self.pin.frame_b, self.rod_a.frame_a),
                ac.connect(self.rod_a.frame_b, self.rod.frame_a, self.rod_b.frame_a),
                ac.connect(self.rod_b.frame_b, self.loop.frame_a),
                ac.connect(self.guide.frame_b, self.slider.frame_a, self.loop.frame_b)]


if __name__ == "__main__":
    import numpy as np
    compiled = ac.compile(SliderCrank())
    print(compiled.report)
    res = ac.simulate(compiled, t_end=SliderCrank.stop_time, rtol=1e-8)
    err = np.max(np.abs(res["guide.s"] - slider_position(res["crank_joint.phi"])))
    print(f"max |x_s - closed form| = {err:.2e} m")
