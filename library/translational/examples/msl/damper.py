"""Modelica.Mechanics.Translational.Examples.Damper (MSL v4.0.0): three ways to damp a
mass moving towards a wall.

Each mass (1 m long, starting at 3 m with 10 m/s) is connected to a wall at 4.5 m:
through a damper; through a damper and a spring in parallel; through a spring-damper.
"""
import acausal as ac
from acausal.library.translational import Damper as DamperElement
from acausal.library.translational import Fixed, Mass, Spring, SpringDamper

__all__ = ["Damper"]

_START = {"s": {"start": 3.0, "fixed": True}, "v": {"start": 10.0, "fixed": True}}


class Damper(ac.Component):
    """d = 25 N.s/m, c = 1 N/m, s_rel0 = 1 m, m = 1 kg."""

    msl_name = "Modelica.Mechanics.Translational.Examples.Damper"
    stop_time = 1.0
    tolerance = 1e-6

    mass1 = Mass(L=1.0, m=1.0, **_START)
    damper1 = DamperElement(d=25.0)
    fixed1 = Fixed(s0=4.5)
    mass2 = Mass(L=1.0, m=1.0, **_START)
    damper2 = DamperElement(d=25.0)
    fixed2 = Fixed(s0=4.5)
    mass3 = Mass(L=1.0, m=1.0, **_START)
    fixed3 = Fixed(s0=4.5)
    spring2 = Spring(s_rel0=1.0, c=1.0)
    springDamper3 = SpringDamper(s_rel0=1.0, d=25.0, c=1.0)

    def equations(self):
        return [ac.connect(self.mass1.flange_b, self.damper1.flange_a),
                ac.connect(self.mass2.flange_b, self.damper2.flange_a),
                ac.connect(self.damper2.flange_b, self.spring2.flange_b),
                ac.connect(self.damper2.flange_a, self.spring2.flange_a),
                ac.connect(self.mass3.flange_b, self.springDamper3.flange_a),
                ac.connect(self.damper1.flange_b, self.fixed1.flange),
                ac.connect(self.damper2.flange_b, self.fixed2.flange),
                ac.connect(self.springDamper3.flange_b, self.fixed3.flange)]


if __name__ == "__main__":
    res = ac.simulate(Damper(), t_end=Damper.stop_time, rtol=Damper.tolerance)
    print(f"mass3.s at {res.t[-1]:g} s: {res['mass3.s'][-1]:.6g} m")
