"""Electrical devices with the MSL's conditional heat port (``useHeatPort``): the resistor
and conductor at the temperature their own loss sets (a closed form), and the energy a
diode's and the MOS transistors' losses carry into a heat capacity (conservation)."""
import numpy as np
import pytest

import acausal as ac
from acausal.library import electrical as el
from acausal.library.thermal import HeatCapacitor, ThermalConductor, celsius


class SelfHeated(ac.Component):
    """A 220 V, 1 Hz sine on a resistor and a conductor (100 Ohm, 0.01 S at 20 degC,
    alpha = 1e-3 1/K), each cooled through 50 W/K to 20 degC: without heat capacity the
    temperature rise x follows the loss at once, 50 x = v^2 / (100 (1 + 1e-3 x))."""

    src = el.SineVoltage(V=220.0, f=1.0)
    R = el.Resistor(R=100.0, alpha=1e-3, T_ref=293.15, useHeatPort=True)
    G = el.Conductor(G=0.01, alpha=1e-3, T_ref=293.15, useHeatPort=True)
    tcR = ThermalConductor(G=50.0)
    tcG = ThermalConductor(G=50.0)
    ambient = celsius.FixedTemperature(T=20.0)
    gnd = el.Ground()

    def equations(self):
        c = ac.connect
        return [c(self.src.p, self.R.p, self.G.p), c(self.src.n, self.R.n, self.G.n, self.gnd.p),
                c(self.R.heatPort, self.tcR.port_a), c(self.G.heatPort, self.tcG.port_a),
                c(self.tcR.port_b, self.tcG.port_b, self.ambient.port)]


def test_resistor_and_conductor_at_the_temperature_of_their_own_loss():
    t = np.linspace(0.0, 1.0, 201)
    res = ac.simulate(SelfHeated(), t_end=1.0, rtol=1e-10, t_eval=t, raise_on_failure=True)
    v = 220.0 * np.sin(2 * np.pi * t)
    x = (-5000.0 + np.sqrt(5000.0**2 + 20.0 * v**2)) / 10.0     # 5 x^2 + 5000 x = v^2
    R_actual = 100.0 * (1 + 1e-3 * x)
    for name in ("R", "G"):
        assert np.allclose(res[f"{name}.T_heatPort"], 293.15 + x, rtol=0, atol=1e-7)
        # to the algebraic solve's tolerance, judged on the amplitudes 2.2 A and 484 W
        assert np.allclose(res[f"{name}.i"], v / R_actual, rtol=0, atol=1e-9 * 2.2)
        assert np.allclose(res[f"{name}.LossPower"], v**2 / R_actual, rtol=0,
                           atol=1e-9 * 484)
        assert np.allclose(res[f"{name}.heatPort.Q_flow"], -v**2 / R_actual, rtol=0,
                           atol=1e-9 * 484)
    assert np.allclose(res["R.R_actual"], R_actual, rtol=1e-12)
    assert np.allclose(res["G.G_actual"], 1 / R_actual, rtol=1e-12)
    assert 293.15 + x.max() > 302.0               # 9.6 K at the peak


class HeatedDevices(ac.Component):
    """A temperature-dependent diode, a PMOS and an NMOS, each on a heat capacity of its
    own (0.01 J/K, at 20 degC), with the energy of its loss integrated beside it:
    C (T - T0) = integral of LossPower dt.  (The transistors' gates on a 5 V, 1 Hz sine;
    the PMOS from 5 V into 1 kOhm to ground, the NMOS from ground into 1 kOhm to 5 V.)"""

    sine = el.SineVoltage(V=1.0, f=1.0)
    diode = el.Diode(useTemperatureDependency=True)
    R = el.Resistor(R=1.0)
    Cd = HeatCapacitor(C=0.01, T={"start": 293.15, "fixed": True})
    vdd = el.ConstantVoltage(V=5.0)
    gate = el.SineVoltage(V=5.0, f=1.0)
    pmos = el.PMOS(useTemperatureDependency=True)
    nmos = el.NMOS(useTemperatureDependency=True)
    load_p = el.Resistor(R=1000.0)
    load_n = el.Resistor(R=1000.0)
    Cp = HeatCapacitor(C=0.01, T={"start": 293.15, "fixed": True})
    Cn = HeatCapacitor(C=0.01, T={"start": 293.15, "fixed": True})
    gnd = el.Ground()
    E_diode = ac.Variable(start=0.0, fixed=True, unit="J")
    E_pmos = ac.Variable(start=0.0, fixed=True, unit="J")
    E_nmos = ac.Variable(start=0.0, fixed=True, unit="J")

    def equations(self):
        c = ac.connect
        return [c(self.sine.p, self.diode.p), c(self.diode.n, self.R.p),
                c(self.diode.heatPort, self.Cd.port),
                c(self.vdd.p, self.pmos.S, self.pmos.B, self.load_n.p),
                c(self.pmos.D, self.load_p.p), c(self.nmos.D, self.load_n.n),
                c(self.gate.p, self.pmos.G, self.nmos.G),
                c(self.pmos.heatPort, self.Cp.port), c(self.nmos.heatPort, self.Cn.port),
                c(self.sine.n, self.R.n, self.vdd.n, self.gate.n, self.nmos.S, self.nmos.B,
                  self.load_p.n, self.gnd.p),
                ac.Eq(ac.der(self.E_diode), self.diode.LossPower),
                ac.Eq(ac.der(self.E_pmos), self.pmos.LossPower),
                ac.Eq(ac.der(self.E_nmos), self.nmos.LossPower)]


def test_the_losses_of_heated_semiconductors_reach_their_heat_capacities():
    t = np.linspace(0.0, 2.0, 201)
    res = ac.simulate(HeatedDevices(), t_end=2.0, rtol=1e-9, t_eval=t, raise_on_failure=True)
    for device, cap in (("diode", "Cd"), ("pmos", "Cp"), ("nmos", "Cn")):
        heat = 0.01 * (res[f"{cap}.T"] - 293.15)
        energy = res[f"E_{device}"]
        assert energy[-1] > 1e-4, device                      # it heats
        assert np.max(np.abs(heat - energy)) < 1e-6 * energy[-1], device
        # the device is at its heat port's temperature
        assert np.allclose(res[f"{device}.T_heatPort"], res[f"{cap}.T"], atol=1e-9)
    # the diode's thermal voltage follows its temperature: vt_t = k T / q
    assert np.allclose(res["diode.vt_t"], 1.380649e-23 / 1.602176634e-19 * res["Cd.T"],
                       rtol=1e-12)


def test_a_temperature_dependent_device_without_its_port_sits_at_T():
    for device in (el.Diode(useTemperatureDependency=True, useHeatPort=False, T=320.0),
                   el.NMOS(useTemperatureDependency=True, useHeatPort=False, T=320.0)):
        with pytest.raises(ac.AbsentComponent, match="useHeatPort"):
            device.heatPort
    assert el.NPN(useTemperatureDependency=True).heatPort is not None


# -- HeatingNPN_NORGate solved on its own ---------------------------------------------------
# With CapVal = tauVal = 0 the gate is algebraic but for the heat capacity: at each time
# the collector and base potentials and the two transistors' temperatures (each at the
# capacity's T plus its loss over 0.01 W/K) solve the static Ebers-Moll circuit, and
# C dT/dt = P1 + P2.

K_Q = 1.380649e-23 / 1.602176634e-19


def _exlin2(x, lo=-100.0, hi=40.0):
    if x < lo:
        return np.exp(lo) * (1 + x - lo)
    if x > hi:
        return np.exp(hi) * (1 + x - hi)
    return np.exp(x)


def _npn(vB, vC, Th):
    """Collector and base currents and loss of the gate's NPN (Bf = 100, Br = 1,
    Is = 1e-14, Vak = 0, Gbc = Gbe = 1e-12, XTI = 3, EG = 1.11, Tnom = 300.15) at Th."""
    vt = K_Q * Th
    is_t = 1e-14 * (Th / 300.15) ** 3 * _exlin2((Th / 300.15 - 1) * 1.11 / vt)
    ibc = is_t * (_exlin2((vB - vC) / vt) - 1) + (vB - vC) * 1e-12
    ibe = is_t * (_exlin2(vB / vt) - 1) + vB * 1e-12
    loss = (vB - vC) * ibc + vB * ibe / 100.0 + (ibe - ibc) * vC
    return (ibe - ibc) - ibc, ibe / 100.0 + ibc, loss


def _trapezoid(t, start):
    if t < start or t >= start + 500.0:
        return 0.0
    s = (t - start) % 50.0
    return 6.0 * min(s / 5.0, 1.0, max(0.0, (25.0 - s) / 5.0))


def _nor_gate_reference(t_out):
    from scipy.integrate import solve_ivp
    from scipy.optimize import root
    guess = [0.0, 0.0, 0.0]

    def potentials(t, Th1, Th2):
        V, V1, V2 = 6.0 * min(t / 5.0, 1.0), _trapezoid(t, 55.0), _trapezoid(t, 65.0)

        def F(x):                                   # the node currents in mA
            vC, vB1, vB2 = x
            iC1, iB1, _ = _npn(vB1, vC, Th1)
            iC2, iB2, _ = _npn(vB2, vC, Th2)
            return [1e3 * ((V - vC) / 40.0 - iC1 - iC2), 1e3 * ((V1 - vB1) / 1800.0 - iB1),
                    1e3 * ((V2 - vB2) / 1800.0 - iB2)]
        best = None
        for g in (guess, [V, min(V1, 0.7), min(V2, 0.7)], [0.05, min(V1, 0.75),
                                                            min(V2, 0.75)]):
            sol = root(F, g, method="hybr", tol=1e-15)
            r = np.max(np.abs(F(sol.x)))
            if best is None or r < best[0]:
                best = (r, sol.x)
        assert best[0] < 1e-9
        guess[:] = best[1]
        return best[1]

    def rhs(t, y):
        Th1 = Th2 = y[0]
        for _ in range(200):                        # Th = T + loss / G, a contraction
            vC, vB1, vB2 = potentials(t, Th1, Th2)
            new1 = y[0] + _npn(vB1, vC, Th1)[2] / 0.01
            new2 = y[0] + _npn(vB2, vC, Th2)[2] / 0.01
            if abs(new1 - Th1) + abs(new2 - Th2) < 1e-12:
                break
            Th1, Th2 = Th1 + 0.7 * (new1 - Th1), Th2 + 0.7 * (new2 - Th2)
        return [0.01 * (new1 - y[0] + new2 - y[0]) / 0.1]

    corners = sorted({0.0, 5.0, 200.0} | {s + 50.0 * p + c for s in (55.0, 65.0)
                                          for p in range(3) for c in (0, 5, 20, 25)})
    out, y = np.empty(len(t_out)), [293.15]
    for a, b in zip(corners, corners[1:]):
        sol = solve_ivp(rhs, (a, b), y, method="LSODA", rtol=1e-10, atol=1e-10,
                        dense_output=True)
        inside = (t_out >= a) & (t_out < b)
        if inside.any():
            out[inside] = sol.sol(t_out[inside])[0]
        y = [sol.y[0, -1]]
    return out


@pytest.mark.slow
def test_heating_npn_nor_gate_against_its_equations_solved_on_their_own():
    """MAP-LIB's reference of HeatingNPN_NORGate drifts above this solution by up to
    0.021 K (5e-4 of its 39 K rise, inside the harness's bound); acausal agrees with it
    to 5e-5 K (measured: 5e-6 K)."""
    from acausal.library.electrical.examples.msl.heating_circuits import HeatingNPN_NORGate
    t = np.array([30.0, 62.0, 72.0, 95.0, 112.0, 122.0, 145.0, 170.0, 190.0])
    res = ac.simulate(HeatingNPN_NORGate(), t_end=200.0, rtol=1e-10, t_eval=t,
                      raise_on_failure=True)
    exact = _nor_gate_reference(t)
    assert exact[-1] - exact[0] > 38.0
    assert np.max(np.abs(res["HeatCapacitor1.T"] - exact)) < 5e-5
