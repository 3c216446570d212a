"""Modelica.Mechanics.Translational.Examples.ElastoGap (MSL v4.0.0): a mass between two
spring-dampers, and the same between two elasto-gaps.

Each mass starts at rest at 2 m, between a spring-damper (or elasto-gap) from the end
of a rod at -2 m and another to the end of a rod at +2 m (the rods of 2 m reach either
side of a fixed point at 0).  The spring-dampers push and pull the mass towards 0.5 m;
the elasto-gaps (s_rel0 = 1.5 m) only push, where their gap is closed.
"""
import acausal as ac
from acausal.library.translational import ElastoGap as ElastoGapElement
from acausal.library.translational import Fixed, Mass, Rod, SpringDamper

__all__ = ["ElastoGap"]


class ElastoGap(ac.Component):
    """c = 10 N/m, d = 1.5 N.s/m; m = 1 kg; spring-dampers s_rel0 = 1 m, elasto-gaps
    s_rel0 = 1.5 m."""

    msl_name = "Modelica.Mechanics.Translational.Examples.ElastoGap"
    stop_time = 5.0
    tolerance = 1e-6

    d = ac.Parameter(1.5, unit="N.s/m", description="damping constant")

    fixed = Fixed()
    rod1 = Rod(L=2.0)
    rod2 = Rod(L=2.0)
    springDamper1 = SpringDamper(c=10.0, s_rel0=1.0, s_rel={"fixed": False, "start": 1.0},
                                 d=ac.ref("d"))
    springDamper2 = SpringDamper(c=10.0, s_rel0=1.0, s_rel={"fixed": False, "start": 1.0},
                                 d=ac.ref("d"))
    mass1 = Mass(s={"fixed": True, "start": 2.0}, L=0.0, m=1.0, v={"fixed": True})
    elastoGap1 = ElastoGapElement(c=10.0, s_rel={"fixed": False, "start": 1.5},
                                  s_rel0=1.5, d=ac.ref("d"))
    elastoGap2 = ElastoGapElement(c=10.0, s_rel={"fixed": False, "start": 1.5},
                                  s_rel0=1.5, d=ac.ref("d"))
    mass2 = Mass(s={"fixed": True, "start": 2.0}, L=0.0, m=1.0, v={"fixed": True})

    def equations(self):
        return [ac.connect(self.rod1.flange_b, self.fixed.flange),
                ac.connect(self.fixed.flange, self.rod2.flange_a),
                ac.connect(self.springDamper1.flange_a, self.rod1.flange_a),
                ac.connect(self.springDamper2.flange_b, self.rod2.flange_b),
                ac.connect(self.springDamper1.flange_b, self.mass1.flange_a),
                ac.connect(self.mass1.flange_b, self.springDamper2.flange_a),
                ac.connect(self.rod1.flange_a, self.elastoGap1.flange_a),
                ac.connect(self.rod2.flange_b, self.elastoGap2.flange_b),
                ac.connect(self.elastoGap1.flange_b, self.mass2.flange_a),
                ac.connect(self.mass2.flange_b, self.elastoGap2.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(ElastoGap(), t_end=ElastoGap.stop_time, rtol=ElastoGap.tolerance)
    print(f"mass2.s at {res.t[-1]:g} s: {res['mass2.s'][-1]:.6g} m")
