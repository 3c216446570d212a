"""Slider-crank mechanism: a closed kinematic loop.

A crank of length r turns at constant speed about a fixed pivot; a connecting rod of
length l (mass m_rod, centre of mass at its middle) joins the crank pin to a slider
(mass m_s) on a horizontal guide through the pivot.  With the crank angle theta from
+x, the slider position is

    x_s = r cos(theta) + sqrt(l^2 - r^2 sin(theta)^2)

The loop world - crank - rod - slider - guide - world closes through three Revolutes
and a Prismatic; the loop-closure equations are position constraints between the
joint angles (index 3), and the drive takes the torque the motion needs.  Only one
joint coordinate is free: the crank angle is the state.
"""
import numpy as np

import acausal as ac
from acausal.library.multibody import Body, FixedFrame, FixedTranslation, Prismatic, Revolute
from acausal.library.rotational import ConstantSpeed

__all__ = ["SliderCrank", "slider_position"]


class SliderCrank(ac.Component):
    """r = 0.1 m, l = 0.3 m, crank at 10 rad/s from theta = 0.3 rad;
    rod 0.5 kg (J = m l^2 / 12), slider 1 kg."""

    stop_time = 1.0
    r = ac.Parameter(0.1, unit="m", description="crank length")
    l = ac.Parameter(0.3, unit="m", description="connecting rod length")
    half_l = ac.Parameter(lambda c: c.l / 2, unit="m", description="l / 2")
    m_rod = ac.Parameter(0.5, unit="kg", description="connecting rod mass")
    J_rod = ac.Parameter(lambda c: c.m_rod * c.l**2 / 12, unit="kg.m2",
                         description="rod inertia about its centre")
    m_s = ac.Parameter(1.0, unit="kg", description="slider mass")
    drive = ConstantSpeed(w_fixed=10.0)
    world = FixedFrame()
    crank_joint = Revolute(phi={"start": 0.3, "fixed": True})
    crank = FixedTranslation(rx=ac.ref("r"), ry=0.0)
    # the other joints of the loop follow from the crank angle: no preference for them,
    # and start values on the intended branch (rod to the right of the crank)
    pin = Revolute(phi={"start": -0.4, "state_select": "default"},
                   w={"state_select": "default"})
    rod_a = FixedTranslation(rx=ac.ref("half_l"), ry=0.0)
    rod = Body(m=ac.ref("m_rod"), J=ac.ref("J_rod"))
    rod_b = FixedTranslation(rx=ac.ref("half_l"), ry=0.0)
    slider_joint = Revolute(phi={"start": 0.1, "state_select": "default"},
                            w={"state_select": "default"})
    slider = Body(m=ac.ref("m_s"), J=0.0)
    guide = Prismatic(ex=1.0, ey=0.0, s={"start": 0.39, "state_select": "default"},
                      v={"state_select": "default"})

    def equations(self):
        return [ac.connect(self.drive.flange, self.crank_joint.flange),
                ac.connect(self.world.frame, self.crank_joint.frame_a, self.guide.frame_a),
                ac.connect(self.crank_joint.frame_b, self.crank.frame_a),
                ac.connect(self.crank.frame_b, self.pin.frame_a),
                ac.connect(self.pin.frame_b, self.rod_a.frame_a),
                ac.connect(self.rod_a.frame_b, self.rod.frame, self.rod_b.frame_a),
                ac.connect(self.rod_b.frame_b, self.slider_joint.frame_a),
                ac.connect(self.slider_joint.frame_b, self.slider.frame, self.guide.frame_b)]


def slider_position(theta: np.ndarray, r: float = 0.1, l: float = 0.3) -> np.ndarray:
    """Closed-form slider position.

    Parameters
    ----------
    theta : array_like
        Crank angle from +x [rad].
    r, l : float
        Crank and connecting-rod lengths [m].

    Returns
    -------
    numpy.ndarray
        x_s = r cos(theta) + sqrt(l^2 - r^2 sin(theta)^2) [m].
    """
    return r * np.cos(theta) + np.sqrt(l**2 - (r * np.sin(theta))**2)


if __name__ == "__main__":
    compiled = ac.compile(SliderCrank())
    print(compiled.report)
    res = ac.simulate(compiled, t_end=SliderCrank.stop_time, rtol=1e-8)
    err = np.max(np.abs(res["guide.s"] - slider_position(res["crank_joint.phi"])))
    print(f"max |x_s - closed form| = {err:.2e} m")
