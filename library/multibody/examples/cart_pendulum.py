"""Cart with an inverted pendulum, driven by a current-controlled DC motor through a
pulley (Egeland & Gravdahl 7.5.1, (7.153)-(7.162)).

The cart (mass m_v) runs on a Prismatic joint; the pendulum is a point mass m_b on a
massless bar of length L_b on a Revolute on the cart, upright at theta_b = 0.  The
motor, J_m theta_m'' = K_T u - T_L (7.157), drives the cart through a string over a
pulley of radius r: T_L = r F, x' = r theta_m' (7.158), modelled as a RackAndPinion
on the joint's flange.  The book notes that the cart takes the force F as input while
the motor also takes F as input, so the two models "must be combined" by hand into

    (m + m_b) x'' + m_b L_b cos(theta_b) theta_b'' - m_b theta_b'^2 L_b sin(theta_b)
        = (K_T / r) u,    m = m_v + J_m / r^2                                 (7.161)
    m_b L_b^2 theta_b'' + m_b L_b x'' cos(theta_b) = m_b L_b g sin(theta_b)      (7.162)

Here the pulley's x = r theta_m is a position constraint between the motor angle and
the cart position, and index reduction combines the equations.  The book's theta_b
(positive from the upright towards +x) is ``-joint.phi``; the book's x is ``track.s``.
"""
import numpy as np

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.electromechanical import CurrentControlledDCMotor
from acausal.library.multibody import Body, FixedFrame, FixedTranslation, Prismatic, Revolute
from acausal.library.rotational import RackAndPinion

__all__ = ["CartPendulumMotor"]


class CartPendulumMotor(ac.Component):
    """Pendulum released upright at rest; motor current u = cos(2 pi t) A.

    m_v = 1 kg, m_b = 0.2 kg, L_b = 0.5 m, K_T = 0.1 N m/A, J_m = 2e-4 kg m^2,
    r = 0.02 m (J_m / r^2 = 0.5 kg).
    """

    stop_time = 2.0
    m_v = ac.Parameter(1.0, unit="kg", description="cart mass")
    m_b = ac.Parameter(0.2, unit="kg", description="pendulum mass")
    L_b = ac.Parameter(0.5, unit="m", description="pendulum length")
    K_T = ac.Parameter(0.1, unit="N.m/A", description="motor torque constant")
    J_m = ac.Parameter(2e-4, unit="kg.m2", description="motor inertia")
    r = ac.Parameter(0.02, unit="m", description="pulley radius")
    current = Sine(amplitude=1.0, f=1.0, phase=np.pi / 2)
    motor = CurrentControlledDCMotor(k=ac.ref("K_T"), J=ac.ref("J_m"), R=1.0, L=1e-3)
    pulley = RackAndPinion(r=ac.ref("r"))
    world = FixedFrame()
    track = Prismatic(ex=1.0, ey=0.0, s={"start": 0.0, "fixed": True},
                      v={"start": 0.0, "fixed": True})
    cart = Body(m=ac.ref("m_v"), J=0.0)
    joint = Revolute(phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    bar = FixedTranslation(rx=0.0, ry=ac.ref("L_b"))
    bob = Body(m=ac.ref("m_b"), J=0.0)

    def equations(self):
        return [ac.connect(self.current.y, self.motor.i_d),
                ac.connect(self.motor.flange, self.pulley.flangeR),
                ac.connect(self.pulley.flangeT, self.track.flange),
                ac.connect(self.world.frame, self.track.frame_a),
                ac.connect(self.track.frame_b, self.cart.frame, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.bob.frame)]


if __name__ == "__main__":
    compiled = ac.compile(CartPendulumMotor())
    print(compiled.report)
    res = ac.simulate(compiled, t_end=CartPendulumMotor.stop_time, rtol=1e-8)
    print(f"x(t_end) = {res['track.s'][-1]:.4f} m, theta_b(t_end) = "
          f"{-res['joint.phi'][-1]:.4f} rad")
