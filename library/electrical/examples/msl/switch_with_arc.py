"""Modelica.Electrical.Analog.Examples.SwitchWithArc and ControlledSwitchWithArc (MSL
v4.0.0): a 50 V source drives 0.1 H and 1 Ohm through a switch, once without and once
with an arc (V0 = 30 V, dVdt = 10 kV/s, Vmax = 60 V) that holds the current for a while
after the switch opens."""
import acausal as ac
from acausal.library.blocks import BooleanPulse
from acausal.library.electrical import (CloserWithArc, ConstantVoltage,
                                        ControlledCloserWithArc,
                                        ControlledIdealClosingSwitch, Ground,
                                        IdealClosingSwitch, Inductor, Resistor, SineVoltage)

__all__ = ["SwitchWithArc", "ControlledSwitchWithArc"]


class _TwoCircuits(ac.Component):
    """The two circuits the examples compare, switch1 without and switch2 with an arc."""

    ground1 = Ground()
    constantVoltage1 = ConstantVoltage(V=50.0)
    inductor1 = Inductor(L=0.1, i={"start": 0.0, "fixed": True})
    resistor1 = Resistor(R=1.0)
    ground2 = Ground()
    constantVoltage2 = ConstantVoltage(V=50.0)
    inductor2 = Inductor(L=0.1, i={"start": 0.0, "fixed": True})
    resistor2 = Resistor(R=1.0)

    def equations(self):
        c = ac.connect
        return [c(self.inductor1.n, self.resistor1.p), c(self.resistor1.n, self.ground1.p),
                c(self.constantVoltage1.n, self.ground1.p),
                c(self.switch1.n, self.inductor1.p), c(self.constantVoltage1.p, self.switch1.p),
                c(self.inductor2.n, self.resistor2.p), c(self.resistor2.n, self.ground2.p),
                c(self.constantVoltage2.n, self.ground2.p),
                c(self.switch2.n, self.inductor2.p), c(self.constantVoltage2.p, self.switch2.p)]


class SwitchWithArc(_TwoCircuits):
    """Comparison of switch models both with and without arc: a Boolean pulse (1 s
    period) closes both switches for half of each period."""

    msl_name = "Modelica.Electrical.Analog.Examples.SwitchWithArc"
    stop_time = 2.0
    tolerance = 1e-7

    booleanPulse = BooleanPulse(period=1.0)
    switch1 = IdealClosingSwitch()
    switch2 = CloserWithArc(dVdt=10000.0, V0=30.0, Vmax=60.0, off={"fixed": True})

    def equations(self):
        c = ac.connect
        return [c(self.booleanPulse.y, self.switch1.control),
                c(self.booleanPulse.y, self.switch2.control)]


class ControlledSwitchWithArc(_TwoCircuits):
    """Comparison of controlled switch models both with and without arc: both switches
    closed while a 1 V, 1 Hz sine is above 0.5 V."""

    msl_name = "Modelica.Electrical.Analog.Examples.ControlledSwitchWithArc"
    stop_time = 6.0
    tolerance = 1e-7
    # while the switches are open nothing moves, and a step of the integrator could span
    # the sine's rise above 0.5 V and its fall below (1/3 s apart): a relation that
    # crosses twice within one step is not seen
    msl_simulate = {"max_step": 0.05}

    switch1 = ControlledIdealClosingSwitch()
    switch2 = ControlledCloserWithArc(V0=30.0, dVdt=10000.0, Vmax=60.0, off={"fixed": True})
    sineVoltage = SineVoltage(V=1.0, f=1.0)
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.sineVoltage.p, self.switch1.control),
                c(self.sineVoltage.p, self.switch2.control),
                c(self.sineVoltage.n, self.ground.p)]


if __name__ == "__main__":
    for model in (SwitchWithArc, ControlledSwitchWithArc):
        res = ac.simulate(model(), t_end=model.stop_time, rtol=model.tolerance)
        print(f"{model.__name__}: inductor2.i at {res.t[-1]:g} s: "
              f"{res['inductor2.i'][-1]:.6g} A")
