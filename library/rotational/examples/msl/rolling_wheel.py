"""Modelica.Mechanics.Rotational.Examples.RollingWheel (MSL v4.0.0): coupling the
rotational and translational domains.

A torque step drives a wheel inertia; the wheel rolls without slip (radius 1 m) and
pushes a mass against a drag force quadratic in its speed.
"""
import acausal as ac
from acausal.library.rotational import IdealRollingWheel, Inertia, TorqueStep
from acausal.library.translational import Mass, QuadraticSpeedDependentForce

__all__ = ["RollingWheel"]


class RollingWheel(ac.Component):
    """A 10 N.m step at 0.1 s; J = 1 kg.m2, m = 1 kg; drag -10 N at 5 m/s."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.RollingWheel"
    stop_time = 5.0
    tolerance = 1e-6

    idealRollingWheel = IdealRollingWheel(radius=1.0)
    inertia = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                      w={"start": 0.0, "fixed": True})
    torqueStep = TorqueStep(stepTorque=10.0, offsetTorque=0.0, startTime=0.1,
                            useSupport=False)
    mass = Mass(L=0.0, m=1.0)
    quadraticSpeedDependentForce = QuadraticSpeedDependentForce(
        f_nominal=-10.0, ForceDirection=False, v_nominal=5.0)

    def equations(self):
        return [ac.connect(self.torqueStep.flange, self.inertia.flange_a),
                ac.connect(self.inertia.flange_b, self.idealRollingWheel.flangeR),
                ac.connect(self.idealRollingWheel.flangeT, self.mass.flange_a),
                ac.connect(self.quadraticSpeedDependentForce.flange, self.mass.flange_b)]


if __name__ == "__main__":
    res = ac.simulate(RollingWheel(), t_end=RollingWheel.stop_time,
                      rtol=RollingWheel.tolerance)
    print(f"inertia.w at {res.t[-1]:g} s: {res['inertia.w'][-1]:.6g} rad/s")
