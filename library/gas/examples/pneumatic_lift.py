"""A pneumatic cylinder lifting a mass against a spring, fed from a supply through a
throttle (the chamber of Egeland & Gravdahl 14.4.5 with a mass flow in).

Supply p_s -> throttle -> chamber (V = V_0 + A x) -> piston -> mass m on a spring c;
the atmosphere pushes on the other side of the piston:

    (V/(n p)) p' + A x' = m_flow/rho,   rho = rho_0 (p/p_0)^(1/n)
    m_flow = C_d A_t sqrt(2 rho_t (p_s - p))
    m x'' = A (p - p_amb) - m g - c (x - x_0)

Isothermal air (n = 1, p_0/rho_0 = R T): the chamber fills slowly and the piston creeps
up until the chamber reaches the supply pressure, where the spring holds the extra
force A (p_s - p_start): 0.2 m above the start.
"""
import acausal as ac
from acausal.library import translational as tr

from ..restrictions import Throttle
from ..sources import FixedPressure
from ..volumes import PneumaticCylinder

__all__ = ["PneumaticLift", "P_S", "P_AMB", "A", "V_0", "M", "C", "G", "X_0", "P_START",
           "A_T", "C_D", "RHO_T", "P_REF", "RHO_REF"]

P_S, P_AMB, A, V_0 = 4e5, 1e5, 1e-3, 1e-5
M, C, G, X_0 = 10.0, 1000.0, 9.81, 0.05
P_START = P_AMB + M * G / A         # the mass at rest on the gas, the spring relaxed
A_T, C_D, RHO_T = 1e-6, 0.6, 3.6     # the throttle; its gas density at ~3 bar
P_REF, RHO_REF = 1e5, 1.19           # air at 20 C on the isotherm


class PneumaticLift(ac.Component):
    """A = 10 cm2, m = 10 kg, c = 1 kN/m, supply 4 bar through a 1 mm2 throttle."""

    stop_time = 3.0
    supply = FixedPressure(p=P_S)
    valve = Throttle(A=A_T, C_d=C_D, rho=RHO_T)
    cylinder = PneumaticCylinder(A=A, V_0=V_0, n=1.0, p_0=P_REF, rho_0=RHO_REF,
                                 p={"start": P_START, "fixed": True})
    load = tr.Mass(m=M, s={"start": X_0, "fixed": True}, v={"start": 0.0, "fixed": True})
    weight = tr.ConstantForce(f_constant=-M * G)
    atmosphere = tr.ConstantForce(f_constant=-P_AMB * A)
    spring = tr.Spring(c=C)
    ceiling = tr.Fixed(s0=X_0)

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.cylinder.port),
                ac.connect(self.cylinder.flange, self.load.flange_a, self.atmosphere.flange),
                ac.connect(self.load.flange_b, self.weight.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.ceiling.flange)]


if __name__ == "__main__":
    res = ac.simulate(PneumaticLift(), t_end=PneumaticLift.stop_time, rtol=1e-8)
    print(f"piston at {res['load.s'][-1]:.4f} m, chamber at {res['cylinder.p'][-1] / 1e5:.3f} "
          f"bar; final equilibrium x = {X_0 + A * (P_S - P_START) / C:.4f} m")
