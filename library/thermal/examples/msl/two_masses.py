"""Modelica.Thermal.HeatTransfer.Examples.TwoMasses (MSL v4.0.0): simple conduction demo.

Two heat capacities of 15 J/K, at 100 degC and 0 degC, exchange heat through a conductor
of 10 W/K and approach the temperature of the mean energy, T_final_K =
(C1 T1(0) + C2 T2(0)) / (C1 + C2), which the MSL computes as a parameter with
``fixed=false`` at initialization; here it is a variable constant in time (der = 0)
set by the same initial equation.
"""
import acausal as ac
from acausal.library.thermal import HeatCapacitor, ThermalConductor, celsius

__all__ = ["TwoMasses"]


class TwoMasses(ac.Component):
    """mass1, mass2: C = 15 J/K at 373.15 K and 273.15 K; conduction G = 10 W/K."""

    msl_name = "Modelica.Thermal.HeatTransfer.Examples.TwoMasses"
    stop_time = 1.0
    tolerance = 1e-6

    T_final_K = ac.Variable(unit="K", description="projected final temperature")
    mass1 = HeatCapacitor(C=15.0, T={"start": 373.15, "fixed": True})
    mass2 = HeatCapacitor(C=15.0, T={"start": 273.15, "fixed": True})
    conduction = ThermalConductor(G=10.0)
    Tsensor1 = celsius.TemperatureSensor()
    Tsensor2 = celsius.TemperatureSensor()

    def equations(self):
        return [ac.connect(self.mass1.port, self.conduction.port_a),
                ac.connect(self.conduction.port_b, self.mass2.port),
                ac.connect(self.mass1.port, self.Tsensor1.port),
                ac.connect(self.mass2.port, self.Tsensor2.port),
                ac.Eq(ac.der(self.T_final_K), 0)]

    def initial_equations(self):
        m1, m2 = self.mass1, self.mass2
        return [ac.Eq(self.T_final_K, (m1.T * m1.C + m2.T * m2.C) / (m1.C + m2.C))]


if __name__ == "__main__":
    res = ac.simulate(TwoMasses(), t_end=TwoMasses.stop_time, rtol=TwoMasses.tolerance)
    print(f"mass1.T, mass2.T at {res.t[-1]:g} s: {res['mass1.T'][-1]:.6g}, "
          f"{res['mass2.T'][-1]:.6g} K (T_final_K = {res['T_final_K'][-1]:.6g} K)")
