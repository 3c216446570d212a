"""Modelica.Electrical.Analog.Examples.AD_DA_conversion (MSL v4.0.0): a 10 Hz sine between
0 and 10 V converted to 7 bits and back, both converters triggered by a digital pulse
('1' for 1 % of each millisecond)."""
import acausal as ac
from acausal.library.electrical import Ground, Resistor, SineVoltage
from acausal.library.electrical.converters import AD_Converter, DA_Converter
from acausal.library.electrical.digital import Logic, Pulse

__all__ = ["AD_DA_conversion"]


class AD_DA_conversion(ac.Component):
    """Compare the input voltage aD_Converter.p.v with the output voltage dA_Converter.p.v."""

    msl_name = "Modelica.Electrical.Analog.Examples.AD_DA_conversion"
    stop_time = 0.2
    tolerance = 1e-6

    N = 7                       # digital signal width (a structural Integer parameter)
    aD_Converter = AD_Converter(N=N, Rin=1e6, VRefLow=0.0, VRefHigh=10.0)
    pulse = Pulse(pulse=int(Logic["1"]), quiet=int(Logic["0"]), nperiod=-1, width=1.0,
                  period=0.001, startTime=0.0)
    dA_Converter = DA_Converter(N=N, Vref=10.0)
    ground = Ground()
    sineVoltage = SineVoltage(V=5.0, f=10.0, offset=5.0)
    resistor = Resistor(R=1.0)

    def equations(self):
        c = ac.connect
        return [c(self.pulse.y, self.aD_Converter.trig),
                c(self.sineVoltage.p, self.aD_Converter.p),
                c(self.sineVoltage.n, self.aD_Converter.n),
                c(self.ground.p, self.sineVoltage.n),
                c(self.sineVoltage.p, self.resistor.p),
                c(self.dA_Converter.trig, self.pulse.y),
                *(c(y, x) for y, x in zip(self.aD_Converter.y, self.dA_Converter.x)),
                c(self.dA_Converter.p, self.resistor.n),
                c(self.dA_Converter.n, self.ground.p)]


if __name__ == "__main__":
    res = ac.simulate(AD_DA_conversion(), t_end=0.2, rtol=1e-6)
    print(f"dA_Converter.p.v at {res.t[-1]:g} s: {res['dA_Converter.p.v'][-1]:.6g} V")
