"""Modelica.Mechanics.Translational.Examples.InitialConditions (MSL v4.0.0): initial
conditions given on masses or on the springs between them.

Left: a spring from a wall holds m3, which a spring-damper joins to m4; both masses
start at given positions and at rest.  Right: a spring from a wall holds m1, a
spring-damper joins m2; here the springs' elongations (and the spring-damper's rate)
are given instead of the positions.
"""
import acausal as ac
from acausal.library.translational import Fixed, Mass, Spring, SpringDamper

__all__ = ["InitialConditions"]


class InitialConditions(ac.Component):
    """Springs c = 1e3 N/m, spring-dampers c = 111 N/m, d = 1 N.s/m; masses 1 kg."""

    msl_name = "Modelica.Mechanics.Translational.Examples.InitialConditions"
    stop_time = 5.0
    tolerance = 1e-6

    fixed2 = Fixed(s0=1.0)
    s2 = Spring(s_rel0=2.0, c=1e3)
    m3 = Mass(L=3.0, s={"start": 4.5, "fixed": True}, v={"fixed": True}, m=1.0)
    sd2 = SpringDamper(s_rel0=4.0, c=111.0, d=1.0)
    m4 = Mass(L=5.0, s={"start": 12.5, "fixed": True}, v={"fixed": True}, m=1.0)
    fixed1 = Fixed(s0=-1.0)
    s1 = Spring(s_rel0=1.0, c=1e3, s_rel={"start": 0.5, "fixed": True})
    m1 = Mass(L=1.0, v={"fixed": True}, m=1.0)
    sd1 = SpringDamper(s_rel0=1.0, c=111.0, s_rel={"start": 1.0, "fixed": True},
                       v_rel={"fixed": True}, d=1.0)
    m2 = Mass(L=2.0, m=1.0)

    def equations(self):
        return [ac.connect(self.s2.flange_a, self.fixed2.flange),
                ac.connect(self.s1.flange_a, self.fixed1.flange),
                ac.connect(self.m1.flange_a, self.s1.flange_b),
                ac.connect(self.sd1.flange_a, self.m1.flange_b),
                ac.connect(self.m2.flange_a, self.sd1.flange_b),
                ac.connect(self.m4.flange_a, self.sd2.flange_b),
                ac.connect(self.sd2.flange_a, self.m3.flange_b),
                ac.connect(self.m3.flange_a, self.s2.flange_b)]


if __name__ == "__main__":
    res = ac.simulate(InitialConditions(), t_end=InitialConditions.stop_time,
                      rtol=InitialConditions.tolerance)
    print(f"m4.s at {res.t[-1]:g} s: {res['m4.s'][-1]:.6g} m")
