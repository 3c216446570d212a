"""Lumped heat transfer, and a resistor heated by its current, against closed forms."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import thermal as th
from acausal.library.blocks import Constant, Ramp, Sine
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
    film = th.Convection()
    Gc = Constant(k=2.0)
    ambient_ramp = Ramp(height=20.0, duration=10.0, offset=300.0)
    ambient = th.PrescribedTemperature()
    constant_heat = th.FixedHeatFlow(Q_flow=4.0)

    def equations(self):
        return [ac.connect(self.heat.y, self.heater.Q_flow),
                ac.connect(self.heater.port, self.body.port, self.film.solid,
                           self.constant_heat.port),
                ac.connect(self.film.fluid, self.ambient.port),
                ac.connect(self.Gc.y, self.film.Gc),
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


# -- Modelica.Thermal.HeatTransfer examples and components against closed forms

def _simulate(model, **options):
    """ac.simulate, which must reach t_end (a run that stops early fails the test)."""
    res = ac.simulate(model, **options)
    assert res.success, res.message
    if "t_eval" in options:
        assert len(res.t) == len(options["t_eval"])
    return res

def test_two_masses_meet_at_the_mean_temperature():
    """MSL Examples.TwoMasses: T1 - T2 = 100 K exp(-G (1/C1 + 1/C2) t), T1 + T2 constant,
    and T_final_K is the mean of the initial energies (C1 = C2)."""
    from acausal.library.thermal.examples.msl.two_masses import TwoMasses
    t = np.linspace(0, 1, 51)
    res = _simulate(TwoMasses(), t_end=1.0, rtol=1e-10, t_eval=t)
    dT = 100.0 * np.exp(-10.0 * (2 / 15.0) * t)
    assert np.max(np.abs(res["mass1.T"] - res["mass2.T"] - dT)) < 1e-7 * 100
    assert np.allclose(res["mass1.T"] + res["mass2.T"], 373.15 + 273.15, rtol=1e-12)
    assert np.allclose(res["T_final_K"], 323.15, rtol=1e-12)
    assert np.allclose(res["Tsensor1.T.signal"], res["mass1.T"] - 273.15, atol=1e-9)


def test_generation_of_fmus_blocks_act_as_the_joined_capacities():
    """MSL Examples.GenerationOfFMUs: the direct and the inverse capacity are one capacity
    C1 + C2 heated by Q = 1000 sin(2 pi 2 t):  T = T0 + 1000 (1 - cos(4 pi t))/(4 pi (C1 +
    C2)); the lower pair conserves C_a T_a + C_b T_b - int Q dt and its difference decays
    as d(Ta - Tb)/dt = Q/C_a - G (1/C_a + 1/C_b)(Ta - Tb)."""
    from scipy.integrate import solve_ivp
    from acausal.library.thermal.examples.msl.generation_of_fmus import GenerationOfFMUs
    t = np.linspace(0, 1, 201)
    res = _simulate(GenerationOfFMUs(), t_end=1.0, rtol=1e-10, t_eval=t)
    w = 4 * np.pi
    T = 293.15 + 1000.0 * (1 - np.cos(w * t)) / (w * 3.3)
    assert np.max(np.abs(res["directCapacity.heatCapacitor.T"] - T)) < 1e-7 * 200
    assert np.allclose(res["inverseCapacity.mass.T"], res["directCapacity.heatCapacitor.T"],
                       atol=1e-9)
    assert np.allclose(res["directCapacity.derT.signal"], 1000 * np.sin(w * t) / 3.3,
                       atol=1e-5 * 300)
    energy = 1.1 * res["capacitor3a.T"] + 2.2 * res["capacitor3b.T"]
    heat = 1000.0 * (1 - np.cos(w * t)) / w
    assert np.max(np.abs(energy - heat - 3.3 * 293.15)) < 1e-9 * energy[0]
    sol = solve_ivp(lambda s, y: [1000 * np.sin(w * s) / 1.1
                                  - 10.0 * (1 / 1.1 + 1 / 2.2) * y[0]],
                    (0, 1), [0.0], t_eval=t, rtol=1e-12, atol=1e-12)
    assert np.max(np.abs(res["capacitor3a.T"] - res["capacitor3b.T"] - sol.y[0])) < 1e-6 * 50


def _motor_exact(t):
    """MSL Examples.Motor solved by solve_ivp, restarted at every step of the loss table."""
    from scipy.integrate import solve_ivp
    Cw, Cc, G, Gc, Ta, alpha, Tref = 2500.0, 25000.0, 10.0, 25.0, 293.15, 3.03e-3, 368.15

    def rhs(s, y, Pw):
        Tw, Tc = y
        return [(Pw * (1 + alpha * (Tw - Tref)) - G * (Tw - Tc)) / Cw,
                (500.0 + G * (Tw - Tc) - Gc * (Tc - Ta)) / Cc]

    edges = sorted({*np.arange(0, t[-1] + 1, 600.0), *np.arange(360, t[-1], 600.0), t[-1]})
    y, out = [Ta, Ta], np.empty((len(t), 2))
    for a, b in zip(edges[:-1], edges[1:]):
        Pw = 1000.0 if (a % 600.0) >= 360.0 else 100.0
        inside = (t >= a) & (t <= b)
        sol = solve_ivp(rhs, (a, b), y, args=(Pw,), rtol=1e-12, atol=1e-10, dense_output=True)
        out[inside] = sol.sol(t[inside]).T
        y = sol.y[:, -1]
    return out


def test_motor_winding_and_core_follow_the_two_heat_balances():
    """MSL Examples.Motor (its MAP-LIB reference is not vendored): the winding and core
    temperatures against solve_ivp of Cw Tw' = Pw (1 + alpha (Tw - Tref)) - G (Tw - Tc),
    Cc Tc' = Pc + G (Tw - Tc) - Gc (Tc - Ta)."""
    from acausal.library.thermal.examples.motor import Motor
    t = np.linspace(0, 7200, 241)
    res = _simulate(Motor(), t_end=7200.0, rtol=1e-8, t_eval=t)
    exact = _motor_exact(t)
    assert np.max(np.abs(res["winding.T"] - exact[:, 0])) < 1e-5 * 100
    assert np.max(np.abs(res["core.T"] - exact[:, 1])) < 1e-5 * 100
    assert np.allclose(res["Twinding.T.signal"], res["winding.T"] - 273.15, atol=1e-9)


class CollectedHeat(ac.Component):
    """Three fixed heat flows collected into one capacity, which loses heat through a
    convective resistor to a Celsius ambient."""

    q1 = th.FixedHeatFlow(Q_flow=1.0)
    q2 = th.FixedHeatFlow(Q_flow=2.0)
    q3 = th.FixedHeatFlow(Q_flow=3.0)
    collector = th.ThermalCollector(m=3)
    body = th.HeatCapacitor(C=2.0, T={"start": 300.0, "fixed": True})
    Rc = Constant(k=0.5)
    film = th.ConvectiveResistor()
    ambient = th.celsius.FixedTemperature(T=10.0)
    dT = th.RelTemperatureSensor()

    def equations(self):
        sources = (self.q1, self.q2, self.q3)
        return [*(ac.connect(s.port, p) for s, p in zip(sources, self.collector.port_a)),
                ac.connect(self.collector.port_b, self.body.port, self.film.solid,
                           self.dT.port_a),
                ac.connect(self.film.fluid, self.ambient.port, self.dT.port_b),
                ac.connect(self.Rc.y, self.film.Rc)]


def test_collector_sums_heat_flows_into_a_convectively_cooled_capacity():
    """C T' = 6 W - (T - 283.15 K)/Rc: T = T_inf + (T0 - T_inf) exp(-t/(Rc C)), T_inf =
    283.15 + 6 Rc; every collector port sits at the body's temperature."""
    t = np.linspace(0, 5, 51)
    res = _simulate(CollectedHeat(), t_end=5.0, rtol=1e-10, t_eval=t)
    T_inf = 283.15 + 6.0 * 0.5
    T = T_inf + (300.0 - T_inf) * np.exp(-t / (0.5 * 2.0))
    assert np.max(np.abs(res["body.T"] - T)) < 1e-7 * 20
    for k in range(3):
        assert np.allclose(res[f"collector.port_a[{k}].T"], res["body.T"], atol=1e-12)
    assert np.allclose(res["dT.T_rel.signal"], res["body.T"] - 283.15, atol=1e-9)
    assert np.allclose(res["film.Q_flow"], (res["body.T"] - 283.15) / 0.5, rtol=1e-9)


class TemperatureDependentHeating(ac.Component):
    """A capacity heated by a heat flow that grows with its temperature (the MSL's
    alpha), with the set temperature read through the Celsius converters."""

    setpoint = Constant(k=25.0)
    toKelvin = th.celsius.ToKelvin()
    fromKelvin = th.celsius.FromKelvin()
    heater = th.PrescribedHeatFlow(T_ref=300.0, alpha=0.01)
    Q = Constant(k=2.0)
    body = th.HeatCapacitor(C=4.0, T={"start": 300.0, "fixed": True})
    wall = th.celsius.PrescribedTemperature()
    glass = th.ThermalConductor(G=0.5)
    through = th.HeatFlowSensor()

    def equations(self):
        return [ac.connect(self.setpoint.y, self.toKelvin.Celsius),
                ac.connect(self.toKelvin.Kelvin, self.fromKelvin.Kelvin),
                ac.connect(self.fromKelvin.Celsius, self.wall.T),
                ac.connect(self.Q.y, self.heater.Q_flow),
                ac.connect(self.heater.port, self.body.port, self.glass.port_a),
                ac.connect(self.glass.port_b, self.through.port_a),
                ac.connect(self.through.port_b, self.wall.port)]


def test_heat_flow_with_temperature_coefficient_and_celsius_boundaries():
    """C T' = Q (1 + alpha (T - T_ref)) - G (T - T_w), linear in T with rate a = G - Q
    alpha:  T = T_inf + (T0 - T_inf) exp(-a t / C), T_inf = (Q (1 - alpha T_ref) + G T_w)
    / a, T_w = 25 degC through ToKelvin and FromKelvin."""
    t = np.linspace(0, 20, 81)
    res = _simulate(TemperatureDependentHeating(), t_end=20.0, rtol=1e-10, t_eval=t)
    Q, alpha, Tref, G, C, Tw = 2.0, 0.01, 300.0, 0.5, 4.0, 298.15
    a = G - Q * alpha
    T_inf = (Q * (1 - alpha * Tref) + G * Tw) / a
    T = T_inf + (300.0 - T_inf) * np.exp(-a * t / C)
    assert np.max(np.abs(res["body.T"] - T)) < 1e-7 * 20
    assert np.allclose(res["through.Q_flow.signal"], G * (T - Tw), atol=1e-6)
    assert np.allclose(res["body.der_T"], -a / C * (300.0 - T_inf) * np.exp(-a * t / C),
                       atol=1e-7)
