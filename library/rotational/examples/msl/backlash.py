"""Modelica.Mechanics.Rotational.Examples.Backlash (MSL v4.0.0): three inertias released
from 90 degrees on a spring-damper to the ground, without backlash, through an
ElastoBacklash and through an ElastoBacklash2 (b = 45 degrees)."""
import acausal as ac
from acausal.library.rotational import (ElastoBacklash, ElastoBacklash2, Fixed, Inertia,
                                        SpringDamper)

__all__ = ["Backlash"]

_RELEASED = {"w": {"fixed": True, "start": 0.0},
             "phi": {"fixed": True, "start": 1.570796326794897}}


class Backlash(ac.Component):
    """c = 20e3 N.m/rad, d = 50 N.m.s/rad, J = 5 kg.m2, b = pi/4."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.Backlash"
    stop_time = 1.0
    tolerance = 1e-6

    fixed1 = Fixed()
    springDamper = SpringDamper(c=20e3, d=50.0, phi_nominal=1.0)
    inertia1 = Inertia(J=5.0, **_RELEASED)
    fixed2 = Fixed()
    elastoBacklash = ElastoBacklash(c=20e3, d=50.0, b=0.7853981633974483, phi_nominal=1.0)
    inertia2 = Inertia(J=5.0, **_RELEASED)
    fixed3 = Fixed()
    elastoBacklash2 = ElastoBacklash2(c=20e3, d=50.0, phi_nominal=1.0, b=0.78539816339745)
    inertia3 = Inertia(J=5.0, **_RELEASED)

    def equations(self):
        return [ac.connect(self.springDamper.flange_b, self.inertia1.flange_a),
                ac.connect(self.elastoBacklash.flange_b, self.inertia2.flange_a),
                ac.connect(self.fixed1.flange, self.springDamper.flange_a),
                ac.connect(self.fixed2.flange, self.elastoBacklash.flange_a),
                ac.connect(self.elastoBacklash2.flange_b, self.inertia3.flange_a),
                ac.connect(self.fixed3.flange, self.elastoBacklash2.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(Backlash(), t_end=Backlash.stop_time, rtol=Backlash.tolerance)
    print(f"inertia2.phi at {res.t[-1]:g} s: {res['inertia2.phi'][-1]:.6g} rad")
