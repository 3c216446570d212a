"""A heated body under P temperature control through a 0..1 kW limiter, shared by the
steady-state, linearization and output-consistency tests.

    C T' = Q - G (T - T_amb),   Q = clip(K_p (T_set - T), 0, Q_max)

with C = 5 kJ/K, G = 10 W/K, K_p = 100 W/K, Q_max = 1 kW, T_amb = 293.15 K; the body
starts at ambient temperature (modify ``body={"T": {...}}`` for another start).
"""
import acausal as ac
from acausal.library import thermal as th
from acausal.library.blocks import Constant, Feedback, Gain, Limiter

__all__ = ["LimitedHeater", "heater_equilibrium", "C_TH", "G", "K_P", "Q_MAX", "T_AMB"]

C_TH, G, K_P, Q_MAX, T_AMB = 5e3, 10.0, 100.0, 1e3, 293.15


class LimitedHeater(ac.Component):
    """Heat capacitor, loss to ambient, P controller through a Limiter."""

    body = th.HeatCapacitor(C=C_TH, T={"start": T_AMB})
    loss = th.ThermalConductor(G=G)
    ambient = th.FixedTemperature(T=T_AMB)
    heater = th.PrescribedHeatFlow()
    sensor = th.TemperatureSensor()
    set_point = Constant(k=323.15)
    error = Feedback()
    gain = Gain(k=K_P)
    limit = Limiter(uMax=Q_MAX, uMin=0.0)

    def equations(self):
        return [ac.connect(self.body.port, self.loss.port_a, self.heater.port,
                           self.sensor.port),
                ac.connect(self.loss.port_b, self.ambient.port),
                ac.connect(self.set_point.y, self.error.u1),
                ac.connect(self.sensor.T, self.error.u2),
                ac.connect(self.error.y, self.gain.u),
                ac.connect(self.gain.y, self.limit.u),
                ac.connect(self.limit.y, self.heater.Q_flow)]


def heater_equilibrium(t_set):
    """(T, Q) by hand: the unsaturated balance K_p (T_set - T) = G (T - T_amb), else the
    limit that balance violates."""
    T = (K_P * t_set + G * T_AMB) / (K_P + G)
    Q = K_P * (t_set - T)
    if Q > Q_MAX:
        return T_AMB + Q_MAX / G, Q_MAX
    if Q < 0.0:
        return T_AMB, 0.0
    return T, Q
