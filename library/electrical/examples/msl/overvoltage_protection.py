"""Modelica.Electrical.Analog.Examples.OvervoltageProtection (MSL v4.0.0): two Zener
diodes back to back limit the voltage of an RC load fed from a 10 V, 5 Hz sine
through 20 Ohm."""
import acausal as ac
from acausal.library.electrical import (Capacitor, Ground, Resistor, SineVoltage,
                                        ZDiode)

__all__ = ["OvervoltageProtection"]


class OvervoltageProtection(ac.Component):
    """Rv = 20 Ohm, RL = 2 kOhm, CL = 0.1 uF; the diodes' default data (Bv = 5.1 V)."""

    msl_name = "Modelica.Electrical.Analog.Examples.OvervoltageProtection"
    stop_time = 0.4
    tolerance = 1e-6

    sineVoltage = SineVoltage(offset=0.0, V=10.0, f=5.0)
    Rv = Resistor(R=20.0)
    RL = Resistor(R=2000.0)
    ground = Ground()
    CL = Capacitor(C=1e-7, v={"start": 0.0, "fixed": True})
    zDiode = ZDiode()
    zDiode1 = ZDiode(v={"start": 0.0})

    def equations(self):
        c = ac.connect
        return [c(self.sineVoltage.p, self.Rv.p), c(self.RL.p, self.CL.p),
                c(self.RL.n, self.CL.n), c(self.sineVoltage.n, self.zDiode.p),
                c(self.zDiode.p, self.ground.p), c(self.zDiode.p, self.RL.n),
                c(self.zDiode1.p, self.Rv.n), c(self.RL.p, self.Rv.n),
                c(self.zDiode1.n, self.zDiode.n)]


if __name__ == "__main__":
    res = ac.simulate(OvervoltageProtection(), t_end=0.4, rtol=1e-6)
    print(f"CL.v at {res.t[-1]:g} s: {res['CL.v'][-1]:.6g} V")
