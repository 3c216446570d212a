"""Lumped heat transfer, and a resistor heated by its current, against closed forms."""
import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import thermal as th
from acausal.library.blocks import Ramp, Sine
from acausal.library.thermal.examples.heated_resistor import HeatedResistor


def _heated_resistor_temperature(t, I=2.0, R_ref=10.0, alpha=4e-3, T_ref=293.15, C=50.0,
                                 Gc=1.0, T_amb=293.15, t_off=60.0):
    """C T' = I^2 R_ref (1 + alpha (T - T_ref)) - Gc (T - T_amb), then I = 0 after t_off."""
    rate = (Gc - alpha * R_ref * I**2) / C
    T_inf = (I**2 * R_ref * (1 - alpha * T_ref) + Gc * T_amb) / (Gc - alpha * R_ref * I**2)
    heating = T_inf + (T_amb - T_inf) * np.exp(-rate * np.minimum(t, t_off))
    T_off = T_inf + (T_amb - T_inf) * np.exp(-rate * t_off)
    cooling = T_amb + (T_off - T_amb) * np.exp(-Gc / C * np.maximum(t - t_off, 0))
    return np.where(t <= t_off, heating, cooling)


def test_heated_resistor_heats_and_cools_by_convection():
    t = np.linspace(0, 200, 201)
    res = ac.simulate(HeatedResistor(), t_end=200, rtol=1e-10, t_eval=t)
    T = res["body.T"]
    assert np.max(np.abs(T - _heated_resistor_temperature(t))) < 1e-7 * 300
    assert T.max() - 293.15 > 25.0
    # R follows the port temperature, and the heat port carries the losses R i^2
    R = 10.0 * (1 + 4e-3 * (T - 293.15))
    assert np.allclose(res["resistor.R"], R, rtol=1e-12)
    i = res["resistor.i"]
    assert np.allclose(-res["resistor.heatPort.Q_flow"], R * i**2, rtol=1e-12, atol=1e-12)


class TwoBodies(ac.Component):
    """Two heat capacities exchanging heat through a conductor and a resistor in series."""

    hot = th.HeatCapacitor(C=2.0, T={"start": 400.0, "fixed": True})
    conductor = th.ThermalConductor(G=0.5)
    resistor = th.ThermalResistor(R=1.0)
    flow = th.HeatFlowSensor()
    cold = th.HeatCapacitor(C=3.0, T={"start": 300.0, "fixed": True})
    thermometer = th.TemperatureSensor()

    def equations(self):
        return [ac.connect(self.hot.port, self.conductor.port_a),
                ac.connect(self.conductor.port_b, self.resistor.port_a),
                ac.connect(self.resistor.port_b, self.flow.port_a),
                ac.connect(self.flow.port_b, self.cold.port, self.thermometer.port)]


def test_two_bodies_equalize_and_conserve_energy():
    t = np.linspace(0, 20, 101)
    res = ac.simulate(TwoBodies(), t_end=20, rtol=1e-10, t_eval=t)
    G = 1 / (1 / 0.5 + 1.0)                        # 0.5 W/K and 1 K/W in series
    rate = G * (1 / 2.0 + 1 / 3.0)
    dT = 100.0 * np.exp(-rate * t)
    assert np.max(np.abs(res["hot.T"] - res["cold.T"] - dT)) < 1e-7 * 100
    energy = 2.0 * res["hot.T"] + 3.0 * res["cold.T"]
    assert np.max(np.abs(energy - energy[0])) < 1e-9 * energy[0]
    assert np.allclose(res["flow.Q_flow.signal"], G * dT, atol=1e-6)
    assert np.allclose(res["thermometer.T.signal"], res["cold.T"], atol=1e-12)


class PrescribedBoundaries(ac.Component):
    """A capacity heated by a sine heat flow and tied by convection to a ramped temperature."""

    heat = Sine(amplitude=5.0, f=0.1)
    heater = th.PrescribedHeatFlow()
    body = th.HeatCapacitor(C=10.0, T={"start": 300.0, "fixed": True})
    film = th.Convection(Gc=2.0)
    ambient_ramp = Ramp(height=20.0, duration=10.0, offset=300.0)
    ambient = th.PrescribedTemperature()
    constant_heat = th.FixedHeatFlow(Q_flow=4.0)

    def equations(self):
        return [ac.connect(self.heat.y, self.heater.Q_flow),
                ac.connect(self.heater.port, self.body.port, self.film.port_a,
                           self.constant_heat.port),
                ac.connect(self.film.port_b, self.ambient.port),
                ac.connect(self.ambient_ramp.y, self.ambient.T)]


def test_prescribed_boundaries_first_order_response():
    """C T' = Q(t) + Q0 - Gc (T - T_a(t)), against solve_ivp (restarted at the ramp's end)."""
    def rhs(t, y):
        Ta = 300.0 + 20.0 * min(t / 10.0, 1.0)
        return [(5.0 * np.sin(0.2 * np.pi * t) + 4.0 - 2.0 * (y[0] - Ta)) / 10.0]

    t = np.linspace(0, 20, 81)
    part1 = solve_ivp(rhs, (0, 10), [300.0], rtol=1e-12, atol=1e-12, dense_output=True)
    part2 = solve_ivp(rhs, (10, 20), part1.y[:, -1], rtol=1e-12, atol=1e-12, dense_output=True)
    exact = np.where(t <= 10, part1.sol(np.minimum(t, 10))[0], part2.sol(np.maximum(t, 10))[0])
    res = ac.simulate(PrescribedBoundaries(), t_end=20, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["body.T"] - exact)) < 1e-7 * 300
