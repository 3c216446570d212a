"""Modelica.Mechanics.Translational.Examples.WhyArrows (MSL v4.0.0): what the flange
arrows of a rigid element mean.

Three rods of 1 m hang from one fixed point, turned different ways: the position sensors
at their free ends read -1, 1 and 1 m.  Two masses of 2 m length on springs from a wall
at -1.9 m, connected with their flange_b, oscillate identically.
"""
import acausal as ac
from acausal.library.translational import Fixed, Mass, PositionSensor, Rod, Spring

__all__ = ["WhyArrows"]


class WhyArrows(ac.Component):
    """Rods L = 1 m; masses m = 1 kg, L = 2 m; springs c = 11 N/m, s_rel0 = 2 m."""

    msl_name = "Modelica.Mechanics.Translational.Examples.WhyArrows"
    stop_time = 1.0
    tolerance = 1e-6

    fixed = Fixed()
    rod1 = Rod(L=1.0)
    rod2 = Rod(L=1.0)
    rod3 = Rod(L=1.0)
    positionSensor2 = PositionSensor()
    positionSensor1 = PositionSensor()
    positionSensor3 = PositionSensor()
    fixed1 = Fixed(s0=-1.9)
    spring1 = Spring(s_rel0=2.0, c=11.0)
    mass1 = Mass(L=2.0, s={"fixed": True}, v={"fixed": True}, m=1.0)
    fixed2 = Fixed(s0=-1.9)
    spring2 = Spring(s_rel0=2.0, c=11.0)
    inertia2 = Mass(L=2.0, m=1.0, s={"fixed": True}, v={"fixed": True})

    def equations(self):
        return [ac.connect(self.spring1.flange_b, self.mass1.flange_b),
                ac.connect(self.spring2.flange_b, self.inertia2.flange_b),
                ac.connect(self.rod3.flange_b, self.positionSensor3.flange),
                ac.connect(self.rod1.flange_a, self.positionSensor1.flange),
                ac.connect(self.rod1.flange_b, self.fixed.flange),
                ac.connect(self.rod3.flange_a, self.fixed.flange),
                ac.connect(self.fixed.flange, self.rod2.flange_a),
                ac.connect(self.rod2.flange_b, self.positionSensor2.flange),
                ac.connect(self.fixed1.flange, self.spring1.flange_a),
                ac.connect(self.fixed2.flange, self.spring2.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(WhyArrows(), t_end=WhyArrows.stop_time, rtol=WhyArrows.tolerance)
    print(f"mass1.s at {res.t[-1]:g} s: {res['mass1.s'][-1]:.6g} m")
