"""Modelica.Electrical.Analog.Examples.ThyristorBehaviourTest (MSL v4.0.0): a
thyristor in series with 10 Ohm and 2 uH on a 30 V, 10 kHz sine, fired by 5 mA gate
pulses (10 % of a 100 us period from 20 us on)."""
import acausal as ac
from acausal.library.electrical import (Ground, Inductor, PulseCurrent, Resistor,
                                        SineVoltage, Thyristor)

__all__ = ["ThyristorBehaviourTest"]


class ThyristorBehaviourTest(ac.Component):
    """The thyristor's default data; vControl starts at 0 (fixed)."""

    msl_name = "Modelica.Electrical.Analog.Examples.ThyristorBehaviourTest"
    stop_time = 0.0002
    tolerance = 1e-06

    ground = Ground()
    sineVoltage = SineVoltage(V=30.0, f=10000.0)
    resistor = Resistor(R=10.0)
    pulseCurrent = PulseCurrent(width=10.0, period=0.0001, startTime=0.00002, I=0.005)
    thyristor_v4_1 = Thyristor(vControl={"fixed": True}, vAK={"start": 0.0},
                               vGK={"start": 0.0})
    inductor = Inductor(L=2e-6, i={"start": 0.0, "fixed": True})

    def equations(self):
        c = ac.connect
        return [c(self.sineVoltage.n, self.ground.p),
                c(self.sineVoltage.p, self.thyristor_v4_1.Anode),
                c(self.resistor.p, self.thyristor_v4_1.Cathode),
                c(self.pulseCurrent.n, self.thyristor_v4_1.Gate),
                c(self.resistor.p, self.pulseCurrent.p),
                c(self.resistor.n, self.inductor.p), c(self.inductor.n, self.ground.p)]


if __name__ == "__main__":
    res = ac.simulate(ThyristorBehaviourTest(), t_end=0.0002, rtol=1e-6)
    print(f"inductor.i at {res.t[-1]:g} s: {res['inductor.i'][-1]:.6g} A")
