"""Double-acting cylinder lifting a mass through orifices (Egeland & Gravdahl 4.3.4).

Supply -> orifice -> chamber a; chamber b -> orifice -> tank; the rod drives a mass
held by a spring and pulled by gravity:

    ((V_a0 + A_a x)/beta) p_a' = q_a - A_a x'      ((V_b0 - A_b x)/beta) p_b' = A_b x' - q_b
    m x'' = A_a p_a - A_b p_b - k x - m g                                 (4.83)-(4.85)
"""
import acausal as ac
from acausal.library import translational as tr

from ..components import Cylinder, TurbulentOrifice
from ..sources import FixedPressure

__all__ = ["CylinderWithMass"]


class CylinderWithMass(ac.Component):
    """Single-rod cylinder A_a = 2e-3, A_b = 1.2e-3 m2, 100 bar supply, a 50 kg mass on a
    2e5 N/m spring; both chambers start at 20 bar, the mass at rest at x = 0."""

    stop_time = 0.2
    supply = FixedPressure(p=1e7)
    tank = FixedPressure(p=0.0)
    inlet = TurbulentOrifice(A=2e-6)
    outlet = TurbulentOrifice(A=2e-6)
    cylinder = Cylinder(A_a=2e-3, A_b=1.2e-3, V_a0=2e-4, V_b0=3e-4,
                        p_a={"start": 2e6, "fixed": True}, p_b={"start": 2e6, "fixed": True})
    load = tr.Mass(m=50.0, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    spring = tr.Spring(c=2e5)
    gravity = tr.ConstantForce(f_constant=-50.0 * 9.81)
    housing = tr.Fixed()

    def equations(self):
        return [ac.connect(self.supply.port, self.inlet.port_a),
                ac.connect(self.inlet.port_b, self.cylinder.port_a),
                ac.connect(self.cylinder.port_b, self.outlet.port_a),
                ac.connect(self.outlet.port_b, self.tank.port),
                ac.connect(self.cylinder.flange, self.load.flange_a),
                ac.connect(self.load.flange_b, self.spring.flange_b, self.gravity.flange),
                ac.connect(self.spring.flange_a, self.housing.flange)]


if __name__ == "__main__":
    res = ac.simulate(CylinderWithMass(), t_end=CylinderWithMass.stop_time, rtol=1e-8)
    print(f"rod position at t_end: {res['load.s'][-1]:.5f} m")
