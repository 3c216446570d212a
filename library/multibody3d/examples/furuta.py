"""The Furuta pendulum (Egeland & Gravdahl 7.6, 8.2.7, (7.173)-(7.196), (8.36)-(8.46)).

An arm of inertia J_1 about the vertical turns on a motor-driven revolute joint
(theta_1, torque T); at its end, L_1 out, a second revolute with its axis along the arm
carries a point mass m on a massless rod of length L_2 (theta_2 = 0 upright):

    (J_1 + m L_1^2 + m L_2^2 sin^2 theta_2) theta_1'' - m L_1 L_2 cos theta_2 theta_2''
        + 2 m L_2^2 theta_1' theta_2' sin theta_2 cos theta_2
        + m L_1 L_2 theta_2'^2 sin theta_2 = T                                   (8.45)
    m L_2^2 theta_2'' - m L_1 L_2 cos theta_2 theta_1''
        - m L_2^2 sin theta_2 cos theta_2 theta_1'^2 - m g L_2 sin theta_2 = 0       (8.46)

and the energy (7.195) changes as V' = theta_1' T (7.196).

The book's inertial frame has n_3 up; the World's y is up, so the book's axes
(n_1, n_2, n_3) are the world's (z, x, y), a cyclic and so right-handed relabelling.
The arm (the book's b_2) is then along the turned frame's x, the pendulum rod (c_3)
along y, and theta_1 = ``arm_joint.phi``, theta_2 = ``pendulum_joint.phi``.
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.multibody3d import Body, FixedTranslation, Revolute, World
from acausal.library.rotational import Torque

__all__ = ["FurutaPendulum"]


class FurutaPendulum(ac.Component):
    """Pendulum released at theta_2 = 0.2 rad from the upright, arm at rest; motor torque
    T = 0.05 sin(2 pi t) N m.

    J_1 = 0.01 kg m^2, m = 0.1 kg, L_1 = 0.2 m, L_2 = 0.3 m, g = 9.80665 m/s^2.
    """

    stop_time = 2.0
    J_1 = ac.Parameter(0.01, unit="kg.m2", min=0, description="arm inertia about the vertical")
    m = ac.Parameter(0.1, unit="kg", min=0, description="pendulum point mass")
    L_1 = ac.Parameter(0.2, unit="m", min=0, description="arm length")
    L_2 = ac.Parameter(0.3, unit="m", min=0, description="pendulum length")
    world = World()
    torque_signal = Sine(amplitude=0.05, f=1.0)
    motor = Torque()
    arm_joint = Revolute(n_1=0.0, n_2=1.0, n_3=0.0,
                         phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    arm = Body(m=0.0, I_11=0.0, I_22=ac.ref("J_1"), I_33=0.0)
    arm_rod = FixedTranslation(r_1=ac.ref("L_1"))
    pendulum_joint = Revolute(n_1=1.0, n_2=0.0, n_3=0.0,
                              phi={"start": 0.2, "fixed": True}, w={"start": 0.0, "fixed": True})
    pendulum_rod = FixedTranslation(r_2=ac.ref("L_2"))
    mass = Body(m=ac.ref("m"), I_11=0.0, I_22=0.0, I_33=0.0)

    def equations(self):
        return [ac.connect(self.torque_signal.y, self.motor.tau),
                ac.connect(self.motor.flange, self.arm_joint.axis),
                ac.connect(self.world.frame_b, self.arm_joint.frame_a),
                ac.connect(self.arm_joint.frame_b, self.arm.frame_a, self.arm_rod.frame_a),
                ac.connect(self.arm_rod.frame_b, self.pendulum_joint.frame_a),
                ac.connect(self.pendulum_joint.frame_b, self.pendulum_rod.frame_a),
                ac.connect(self.pendulum_rod.frame_b, self.mass.frame_a)]


if __name__ == "__main__":
    compiled = ac.compile(FurutaPendulum())
    print(compiled.report)
    res = ac.simulate(compiled, t_end=FurutaPendulum.stop_time, rtol=1e-8)
    print(f"theta_1(t_end) = {res['arm_joint.phi'][-1]:.5f} rad, theta_2(t_end) = "
          f"{res['pendulum_joint.phi'][-1]:.5f} rad")
