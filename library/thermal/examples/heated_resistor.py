"""A resistor heated by its own current and cooled by convection (electrical + thermal).

A current I flows for t < t_off through a HeatingResistor, R = R_ref (1 + alpha (T - T_ref)),
whose heat port carries a lumped capacity C, cooled to an ambient T_amb through Gc:

    C dT/dt = R(T) I^2 - Gc (T - T_amb)

linear in T, so T(t) is an exponential towards T_inf = (I^2 R_ref (1 - alpha T_ref) +
Gc T_amb)/(Gc - alpha R_ref I^2) with rate (Gc - alpha R_ref I^2)/C while heated, and
towards T_amb with rate Gc/C after t_off.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.electrical import Ground, HeatingResistor, StepCurrent
from acausal.library.thermal import Convection, FixedTemperature, HeatCapacitor

__all__ = ["HeatedResistor"]


class HeatedResistor(ac.Component):
    """I = 2 A for 60 s; R_ref = 10 Ohm, alpha = 4e-3 1/K; C = 50 J/K, Gc = 1 W/K."""

    stop_time = 200.0
    source = StepCurrent(I=-2.0, offset=2.0, startTime=60.0)
    ground = Ground()
    resistor = HeatingResistor(R_ref=10.0, T_ref=293.15, alpha=4e-3)
    body = HeatCapacitor(C=50.0, T={"start": 293.15, "fixed": True})
    convection = Convection()
    Gc = Constant(k=1.0)
    ambient = FixedTemperature(T=293.15)

    def equations(self):
        return [ac.connect(self.source.n, self.resistor.p),
                ac.connect(self.resistor.n, self.source.p, self.ground.p),
                ac.connect(self.resistor.heatPort, self.body.port, self.convection.solid),
                ac.connect(self.convection.fluid, self.ambient.port),
                ac.connect(self.Gc.y, self.convection.Gc)]


if __name__ == "__main__":
    res = ac.simulate(HeatedResistor(), t_end=HeatedResistor.stop_time, rtol=1e-8)
    print(f"peak temperature {res['body.T'].max():.3f} K")
