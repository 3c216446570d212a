"""Modelica.Electrical.Analog.Examples.Resistor (MSL v4.0.0): a resistor with a
temperature coefficient (R = 100 Ohm at 20 degC, alpha = 1e-3 1/K) on a 220 V, 1 Hz sine;
its loss leaves through its heat port and a thermal conductance of 50 W/K to 20 degC."""
import acausal as ac
from acausal.library.electrical import Ground, Resistor as BasicResistor, SineVoltage
from acausal.library.thermal import ThermalConductor, celsius

__all__ = ["Resistor"]


class Resistor(ac.Component):
    """Resistor with simple thermal network: the resistor's temperature follows its loss
    without delay (no heat capacity)."""

    msl_name = "Modelica.Electrical.Analog.Examples.Resistor"
    stop_time = 5.0
    tolerance = 1e-6

    resistor = BasicResistor(R=100.0, alpha=1e-3, T_ref=293.15, i={"start": 0.0},
                             useHeatPort=True)
    G = Ground()
    SineVoltage1 = SineVoltage(V=220.0, f=1.0)
    thermalConductor = ThermalConductor(G=50.0)
    fixedTemperature = celsius.FixedTemperature(T=20.0)

    def equations(self):
        c = ac.connect
        return [c(self.SineVoltage1.n, self.G.p),
                c(self.resistor.heatPort, self.thermalConductor.port_a),
                c(self.SineVoltage1.p, self.resistor.p), c(self.G.p, self.resistor.n),
                c(self.thermalConductor.port_b, self.fixedTemperature.port)]


if __name__ == "__main__":
    res = ac.simulate(Resistor(), t_end=5.0, rtol=1e-6)
    print(f"resistor.LossPower at {res.t[-1]:g} s: {res['resistor.LossPower'][-1]:.6g} W")
