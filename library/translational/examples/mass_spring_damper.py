"""Mass-spring-damper released from a displacement (Egeland & Gravdahl 2.1.2, 2.3.4).

    m x'' + d x' + k x = 0                                            (2.8)
    V = m x'^2/2 + k x^2/2,   dV/dt = -d x'^2                        (2.58), (2.60)

with w_0 = sqrt(k/m) = 2 rad/s and zeta = d/(2 sqrt(k m)) = 0.1 here.
"""
import acausal as ac
from acausal.library.translational import Damper, Fixed, Mass, Spring

__all__ = ["MassSpringDamper"]


class MassSpringDamper(ac.Component):
    """m = 1 kg, k = 4 N/m, d = 0.4 N s/m, x(0) = 0.1 m, v(0) = 0."""

    stop_time = 10.0
    wall = Fixed()
    spring = Spring(c=4.0)
    damper = Damper(d=0.4)
    mass = Mass(m=1.0, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring.flange_a, self.damper.flange_a),
                ac.connect(self.spring.flange_b, self.damper.flange_b, self.mass.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(MassSpringDamper(), t_end=MassSpringDamper.stop_time, rtol=1e-8)
    print(f"x(t_end) = {res['mass.s'][-1]:.6e} m")
