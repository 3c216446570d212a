"""Modelica.Mechanics.Rotational.Examples.GenerationOfFMUs (MSL v4.0.0): three ways to
cut a drive train into blocks with signal inputs and outputs, as FMUs are made.

A sine torque drives (1) a direct inertia block feeding an inverse inertia block, (2)
two inertias joined by a spring-damper block that takes angles and speeds, (3) two
inertias joined by a spring block that takes angles.  The blocks that take a speed or
an acceleration impose their angle with it as its derivative (AngleToTorqueAdaptor,
the MSL's Move: a function with a derivative annotation).
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.rotational import Inertia, Torque
from acausal.library.rotational.adaptors import TorqueToAngleAdaptor

from .utilities import DirectInertia, InverseInertia, Spring, SpringDamper

__all__ = ["GenerationOfFMUs"]


class GenerationOfFMUs(ac.Component):
    """sine 10 N.m at 2 Hz; J = 1.1 and 2.2 kg.m2; springDamper c = 1e4 N.m/rad, d = 100
    N.m.s/rad; spring c = 1e4 N.m/rad."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.GenerationOfFMUs"
    stop_time = 1.0
    tolerance = 1e-6

    sine1 = Sine(f=2.0, amplitude=10.0)
    directInertia = DirectInertia(J=1.1)
    inverseInertia = InverseInertia(J=2.2)
    springDamper = SpringDamper(c=1e4, d=100.0)
    inertia2a = Inertia(J=1.1, phi={"fixed": True, "start": 0.0},
                        w={"fixed": True, "start": 0.0})
    torque2 = Torque()
    torqueToAngle2a = TorqueToAngleAdaptor(use_a=False)
    inertia2b = Inertia(J=2.2, phi={"fixed": True, "start": 0.0},
                        w={"fixed": True, "start": 0.0})
    torqueToAngle2b = TorqueToAngleAdaptor(use_a=False)
    spring = Spring(c=1e4)
    inertia3a = Inertia(J=1.1, phi={"fixed": True, "start": 0.0},
                        w={"fixed": True, "start": 0.0})
    force3 = Torque()
    torqueToAngle3a = TorqueToAngleAdaptor(use_w=False, use_a=False)
    inertia3b = Inertia(J=2.2, phi={"fixed": True, "start": 0.0},
                        w={"fixed": True, "start": 0.0})
    torqueToAngle3b = TorqueToAngleAdaptor(use_w=False, use_a=False)

    def equations(self):
        return [ac.connect(self.sine1.y, self.directInertia.tauDrive),
                ac.connect(self.directInertia.phi, self.inverseInertia.phi),
                ac.connect(self.directInertia.w, self.inverseInertia.w),
                ac.connect(self.directInertia.a, self.inverseInertia.a),
                ac.connect(self.inverseInertia.tau, self.directInertia.tau),
                ac.connect(self.sine1.y, self.torque2.tau),
                ac.connect(self.sine1.y, self.force3.tau),
                ac.connect(self.torqueToAngle2b.flange, self.inertia2b.flange_a),
                ac.connect(self.inertia2a.flange_b, self.torqueToAngle2a.flange),
                ac.connect(self.torque2.flange, self.inertia2a.flange_a),
                ac.connect(self.inertia3a.flange_b, self.torqueToAngle3a.flange),
                ac.connect(self.force3.flange, self.inertia3a.flange_a),
                ac.connect(self.torqueToAngle3b.flange, self.inertia3b.flange_a),
                ac.connect(self.torqueToAngle2a.phi, self.springDamper.phi1),
                ac.connect(self.torqueToAngle2a.w, self.springDamper.w1),
                ac.connect(self.torqueToAngle2a.tau, self.springDamper.tau1),
                ac.connect(self.springDamper.tau2, self.torqueToAngle2b.tau),
                ac.connect(self.springDamper.phi2, self.torqueToAngle2b.phi),
                ac.connect(self.springDamper.w2, self.torqueToAngle2b.w),
                ac.connect(self.torqueToAngle3a.phi, self.spring.phi1),
                ac.connect(self.torqueToAngle3a.tau, self.spring.tau1),
                ac.connect(self.spring.phi2, self.torqueToAngle3b.phi),
                ac.connect(self.spring.tau2, self.torqueToAngle3b.tau)]


if __name__ == "__main__":
    res = ac.simulate(GenerationOfFMUs(), t_end=GenerationOfFMUs.stop_time,
                      rtol=GenerationOfFMUs.tolerance)
    print(f"inertia2b.w at {res.t[-1]:g} s: {res['inertia2b.w'][-1]:.6g} rad/s")
