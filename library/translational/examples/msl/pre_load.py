"""Modelica.Mechanics.Translational.Examples.PreLoad (MSL v4.0.0): the preload of a spool
by a spring between two plates, with stiff elasto-gaps as the contacts.

The spool (with a sleeve of two rods) sits between two spring plates that a preloaded
spring pushes apart against the housing's stops (outer contacts) and against the spool's
shoulders (inner contacts).  A slow sine force moves the spool; the spring holds it
until the force exceeds the preload, then one plate lifts off its stop.
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.translational import Damper, ElastoGap, Fixed, Force, Mass, Rod, Spring

__all__ = ["PreLoad"]


class PreLoad(ac.Component):
    """Contacts c = 1e6 N/m, d = 250 N.s/m; spool 0.15 kg, plates 10 g; spring 20e3 N/m
    (s_rel0 = 25 mm); friction 2500 N.s/m; force 150 N at 0.01 Hz."""

    msl_name = "Modelica.Mechanics.Translational.Examples.PreLoad"
    stop_time = 100.0
    tolerance = 1e-6

    innerContactA = ElastoGap(c=1000e3, d=250.0, s_rel0=0.001)
    innerContactB = ElastoGap(c=1000e3, d=250.0, s_rel0=0.001)
    spool = Mass(L=0.19, m=0.150, s={"start": 0.01475, "fixed": True}, v={"fixed": True})
    fixedLe = Fixed(s0=-0.0955)
    springPlateA = Mass(m=10e-3, L=0.002, s={"start": -0.093, "fixed": True},
                        v={"fixed": True})
    springPlateB = Mass(m=10e-3, s={"start": -0.06925, "fixed": True}, L=0.002,
                        v={"fixed": True})
    spring = Spring(c=20e3, s_rel0=0.025)
    outerContactA = ElastoGap(c=1000e3, d=250.0, s_rel0=0.0015)
    outerContactB = ElastoGap(c=1000e3, d=250.0, s_rel0=0.0015)
    rod1 = Rod(L=0.007)
    friction = Damper(d=2500.0)
    force = Force()
    housing = Rod(L=0.0305)
    rod3 = Rod(L=0.00575)
    rod4 = Rod(L=0.00575)
    rod2 = Rod(L=0.007)
    sineForce = Sine(amplitude=150.0, f=0.01)

    def equations(self):
        return [ac.connect(self.outerContactA.flange_b, self.springPlateA.flange_a),
                ac.connect(self.springPlateA.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.springPlateB.flange_a),
                ac.connect(self.springPlateB.flange_b, self.outerContactB.flange_a),
                ac.connect(self.outerContactB.flange_b, self.housing.flange_b),
                ac.connect(self.springPlateA.flange_b, self.rod1.flange_a),
                ac.connect(self.innerContactA.flange_a, self.rod3.flange_a),
                ac.connect(self.innerContactA.flange_b, self.rod1.flange_b),
                ac.connect(self.rod2.flange_a, self.innerContactB.flange_a),
                ac.connect(self.rod4.flange_b, self.innerContactB.flange_b),
                ac.connect(self.friction.flange_b, self.rod3.flange_a),
                ac.connect(self.rod3.flange_b, self.rod4.flange_a),
                ac.connect(self.rod2.flange_b, self.springPlateB.flange_a),
                ac.connect(self.spool.flange_a, self.rod4.flange_a),
                ac.connect(self.sineForce.y, self.force.f),
                ac.connect(self.force.flange, self.spool.flange_a),
                ac.connect(self.outerContactA.flange_a, self.fixedLe.flange),
                ac.connect(self.housing.flange_a, self.fixedLe.flange),
                ac.connect(self.friction.flange_a, self.fixedLe.flange)]


if __name__ == "__main__":
    res = ac.simulate(PreLoad(), t_end=PreLoad.stop_time, rtol=PreLoad.tolerance)
    print(f"spool.s at {res.t[-1]:g} s: {res['spool.s'][-1]:.6g} m")
