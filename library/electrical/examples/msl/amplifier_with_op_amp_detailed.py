"""Modelica.Electrical.Analog.Examples.AmplifierWithOpAmpDetailed (MSL v4.0.0): an
inverting amplifier (gain -2) built around the detailed op-amp model, supplied with
+-15 V and driven by a 12 V, 1 kHz sine, so that the output saturates and slews."""
import acausal as ac
from acausal.library.electrical import (ConstantVoltage, Ground, OpAmpDetailed, Resistor,
                                        SineVoltage)

__all__ = ["AmplifierWithOpAmpDetailed"]


class AmplifierWithOpAmpDetailed(ac.Component):
    """resistor = 10 kOhm, resistor1 = 20 kOhm, load resistor2 = 10 kOhm."""

    msl_name = "Modelica.Electrical.Analog.Examples.AmplifierWithOpAmpDetailed"
    stop_time = 0.003
    tolerance = 2e-08

    opAmp = OpAmpDetailed()
    resistor = Resistor(R=10000.0)
    resistor1 = Resistor(R=20000.0)
    resistor2 = Resistor(R=10000.0)
    sineVoltage = SineVoltage(V=12.0, f=1000.0)
    ground = Ground()
    constantVoltage = ConstantVoltage(V=15.0)
    constantVoltage1 = ConstantVoltage(V=-15.0)

    def initial_equations(self):
        return [ac.Eq(self.resistor2.i, 0), ac.Eq(self.opAmp.q_fp1, 0),
                ac.Eq(self.opAmp.q_fr1, 0), ac.Eq(self.opAmp.q_fr2, 0),
                ac.Eq(self.opAmp.q_fr3, 0)]

    def equations(self):
        c = ac.connect
        return [c(self.resistor.n, self.opAmp.m), c(self.resistor1.n, self.resistor2.p),
                c(self.resistor.p, self.sineVoltage.p), c(self.resistor1.p, self.opAmp.m),
                c(self.sineVoltage.n, self.ground.p), c(self.opAmp.p, self.ground.p),
                c(self.resistor2.n, self.ground.p),
                c(self.opAmp.p_supply, self.constantVoltage.p),
                c(self.opAmp.m_supply, self.constantVoltage1.p),
                c(self.constantVoltage.n, self.constantVoltage1.n),
                c(self.constantVoltage1.n, self.ground.p),
                c(self.opAmp.outp, self.resistor2.p)]


if __name__ == "__main__":
    res = ac.simulate(AmplifierWithOpAmpDetailed(), t_end=0.003, rtol=2e-8)
    print(f"opAmp.v_source at {res.t[-1]:g} s: {res['opAmp.v_source'][-1]:.6g} V")
