"""Modelica.Mechanics.Translational.Examples.GenerationOfFMUs (MSL v4.0.0): three ways to
cut a chain of masses into blocks with signal inputs and outputs, as FMUs are made.

A sine force drives (1) a direct mass block feeding an inverse mass block, (2) two
masses joined by a spring-damper block that takes positions and speeds, (3) two masses
joined by a spring block that takes positions.  The blocks that take a speed or an
acceleration impose their position with it as its derivative
(GeneralPositionToForceAdaptor: a function with a derivative annotation).
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.translational import Force, Mass
from acausal.library.translational.adaptors import GeneralForceToPositionAdaptor

from .utilities import DirectMass, InverseMass, Spring, SpringDamper

__all__ = ["GenerationOfFMUs"]


class GenerationOfFMUs(ac.Component):
    """sine 10 N at 2 Hz; m = 1.1 and 2.2 kg; springDamper c = 1e4 N/m, d = 100 N.s/m;
    spring c = 1e4 N/m."""

    msl_name = "Modelica.Mechanics.Translational.Examples.GenerationOfFMUs"
    stop_time = 1.0
    tolerance = 1e-6

    sine1 = Sine(f=2.0, amplitude=10.0)
    directMass = DirectMass(m=1.1)
    inverseMass = InverseMass(m=2.2)
    springDamper = SpringDamper(c=1e4, d=100.0)
    mass2a = Mass(m=1.1, s={"fixed": True, "start": 0.0}, v={"fixed": True, "start": 0.0})
    force2 = Force()
    forceToPosition2a = GeneralForceToPositionAdaptor(use_pder2=False)
    mass2b = Mass(m=2.2, s={"fixed": True, "start": 0.0}, v={"fixed": True, "start": 0.0})
    forceToPosition2b = GeneralForceToPositionAdaptor(use_pder2=False)
    spring = Spring(c=1e4)
    mass3a = Mass(m=1.1, s={"fixed": True, "start": 0.0}, v={"fixed": True, "start": 0.0})
    force3 = Force()
    forceToPosition3a = GeneralForceToPositionAdaptor(use_pder=False, use_pder2=False)
    mass3b = Mass(m=2.2, s={"fixed": True, "start": 0.0}, v={"fixed": True, "start": 0.0})
    forceToPosition3b = GeneralForceToPositionAdaptor(use_pder=False, use_pder2=False)

    def equations(self):
        return [ac.connect(self.sine1.y, self.directMass.fDrive),
                ac.connect(self.directMass.s, self.inverseMass.s),
                ac.connect(self.directMass.v, self.inverseMass.v),
                ac.connect(self.directMass.a, self.inverseMass.a),
                ac.connect(self.inverseMass.f, self.directMass.f),
                ac.connect(self.force2.flange, self.mass2a.flange_a),
                ac.connect(self.mass2a.flange_b, self.forceToPosition2a.flange),
                ac.connect(self.forceToPosition2b.flange, self.mass2b.flange_a),
                ac.connect(self.force3.flange, self.mass3a.flange_a),
                ac.connect(self.mass3a.flange_b, self.forceToPosition3a.flange),
                ac.connect(self.forceToPosition3b.flange, self.mass3b.flange_a),
                ac.connect(self.forceToPosition2a.f, self.springDamper.f1),
                ac.connect(self.springDamper.f2, self.forceToPosition2b.f),
                ac.connect(self.forceToPosition3a.f, self.spring.f1),
                ac.connect(self.spring.f2, self.forceToPosition3b.f),
                ac.connect(self.forceToPosition3a.p, self.spring.s1),
                ac.connect(self.spring.s2, self.forceToPosition3b.p),
                ac.connect(self.forceToPosition2a.p, self.springDamper.s1),
                ac.connect(self.forceToPosition2a.pder, self.springDamper.v1),
                ac.connect(self.springDamper.s2, self.forceToPosition2b.p),
                ac.connect(self.forceToPosition2b.pder, self.springDamper.v2),
                ac.connect(self.sine1.y, self.force2.f),
                ac.connect(self.sine1.y, self.force3.f)]


if __name__ == "__main__":
    res = ac.simulate(GenerationOfFMUs(), t_end=GenerationOfFMUs.stop_time,
                      rtol=GenerationOfFMUs.tolerance)
    print(f"mass2b.v at {res.t[-1]:g} s: {res['mass2b.v'][-1]:.6g} m/s")
