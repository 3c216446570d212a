"""The Boolean-controlled ideal devices of Modelica.Electrical.Analog.Ideal (MSL v4.0.0)
against closed forms and an independent integration: the ideal thyristor latching from
its firing to its current zero, the GTO thyristor stopping with its fire signal, the
triac clamping both half waves, the Boolean two-way and intermediate switches, and the
closer and opener with an arc (the arc voltage's ramp, the quench), the switched
capacitor of the MSL's CauerLowPassSC (a charge C v a period)."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import electrical as el
from acausal.library.blocks import BooleanConstant, BooleanPulse, BooleanStep, Step
from acausal.library.electrical.examples.msl.utilities import SwitchedCapacitor

U, F, VKNEE, R_LOAD, RON, GOFF = 10.0, 1.0, 1.0, 1.0, 1e-5, 1e-5


class FiredBench(ac.Component):
    """u = 10 sin(2 pi t) V on the device in series with 1 Ohm; fired from 0.1 s to
    0.15 s (a pulse of 5 % of 1 s), then again in the negative half wave (0.6 s)."""

    def __init__(self, device, **mods):
        super().__init__(**mods)
        self.src = el.SineVoltage(V=U, f=F)
        self.d = device
        self.R = el.Resistor(R=R_LOAD)
        self.fire = BooleanPulse(width=5.0, period=0.5, startTime=0.1)
        self.gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.d.p), ac.connect(self.d.n, self.R.p),
                ac.connect(self.fire.y, self.d.fire),
                ac.connect(self.R.n, self.src.n, self.gnd.p)]


def _on_current(u):
    """The current of the conducting device: u = (Ron + R) s + Vknee (1 + R Goff)."""
    s = (u - VKNEE * (1 + R_LOAD * GOFF)) / (RON + R_LOAD)
    return s + GOFF * VKNEE


def _off_current(u):
    return GOFF * u / (1 + R_LOAD * GOFF)


def test_ideal_thyristor_conducts_from_its_firing_to_its_current_zero():
    t = np.linspace(0.0, 1.0, 401)
    device = el.IdealThyristor(Vknee=VKNEE, Ron=RON, Goff=GOFF,
                               off={"start": True, "fixed": True})
    res = ac.simulate(FiredBench(device), t_end=1.0, rtol=1e-9, t_eval=t,
                      raise_on_failure=True)
    u = U * np.sin(2 * np.pi * F * t)
    # fired at 0.1 s (u = 5.9 V > Vknee), conducting until s = 0 at u = Vknee (1 + R Goff)
    # on the falling side; the second pulse (0.6 s) finds u < 0 and does nothing
    t_zero = (np.pi - np.arcsin(VKNEE * (1 + R_LOAD * GOFF) / U)) / (2 * np.pi * F)
    on = (t >= 0.1) & (t < t_zero)
    exact = np.where(on, _on_current(u), _off_current(u))
    away = (np.abs(t - 0.1) > 1e-6) & (np.abs(t - t_zero) > 1e-6)
    assert np.max(np.abs(res["R.i"][away] - exact[away])) < 1e-6 * U
    assert list(res["d.off"][away]) == list(~on[away])
    assert np.min(np.abs(np.array([float(e) for e in res.events]) - t_zero)) < 1e-7


def test_ideal_gto_thyristor_stops_with_its_fire_signal():
    t = np.linspace(0.0, 1.0, 401)
    device = el.IdealGTOThyristor(Vknee=VKNEE, Ron=RON, Goff=GOFF,
                                  off={"start": True, "fixed": True})
    res = ac.simulate(FiredBench(device), t_end=1.0, rtol=1e-9, t_eval=t,
                      raise_on_failure=True)
    u = U * np.sin(2 * np.pi * F * t)
    on = (t >= 0.1) & (t < 0.125)                    # 5 % of the 0.5 s period
    exact = np.where(on, _on_current(u), _off_current(u))
    away = (np.abs(t - 0.1) > 1e-6) & (np.abs(t - 0.125) > 1e-6)
    assert np.max(np.abs(res["R.i"][away] - exact[away])) < 1e-6 * U
    # the loss is v i >= 0, Ron i^2 and more while conducting
    assert np.min(res["d.LossPower"]) > -1e-9


class TriacBench(ac.Component):
    """u = 10 sin(2 pi t) V on an always fired ideal triac in series with 20 Ohm."""

    src = el.SineVoltage(V=U, f=F)
    triac = el.IdealTriac(Vknee=VKNEE, capacitor={"v": {"start": 0.0, "fixed": True}},
                          idealThyristor={"off": {"start": True, "fixed": True}},
                          idealThyristor1={"off": {"start": True, "fixed": True}})
    R = el.Resistor(R=20.0)
    fire = BooleanConstant(k=True)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.triac.p),
                ac.connect(self.fire.y, self.triac.fire1),
                ac.connect(self.triac.n, self.src.n, self.gnd.p)]


def test_ideal_triac_conducts_both_half_waves_above_its_knee():
    t = np.linspace(0.0, 2.0, 801)
    res = ac.simulate(TriacBench(), t_end=2.0, rtol=1e-9, t_eval=t, raise_on_failure=True)
    v = res["triac.p.v"] - res["triac.n.v"]
    # idealThyristor1 conducts from p to n, idealThyristor from n to p
    forward, backward = res["triac.idealThyristor1.i"], res["triac.idealThyristor.i"]
    assert np.min(forward) > -GOFF * U and np.min(backward) > -GOFF * U
    assert np.max(forward) > 0.3 and np.max(backward) > 0.3
    # a conducting thyristor clamps the triac to its knee
    assert np.allclose(v[forward > 1e-3], VKNEE + RON * forward[forward > 1e-3], atol=1e-8)
    assert np.allclose(v[backward > 1e-3], -VKNEE - RON * backward[backward > 1e-3],
                       atol=1e-8)
    # and blocks below it: the triac's voltage never exceeds the knee
    assert np.max(np.abs(v)) < VKNEE + RON * 1.0
    # the series R-C across the thyristors (Rdis, Cdis) carries the rest of the current
    assert np.allclose(res["R.i"], forward - backward - res["triac.resistor.i"], atol=1e-9)


class BooleanTwoWayBench(ac.Component):
    """p fed from 10 V through 1 Ohm; n1 and n2 to ground through 1 Ohm and 2 Ohm; the
    control a Boolean step at 0.5 s."""

    src = el.ConstantVoltage(V=10.0)
    R = el.Resistor(R=1.0)
    sw = el.IdealTwoWaySwitch(Ron=1e-6, Goff=1e-7)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=2.0)
    ctl = BooleanStep(startTime=0.5)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.sw.p),
                ac.connect(self.sw.n1, self.R1.p), ac.connect(self.sw.n2, self.R2.p),
                ac.connect(self.ctl.y, self.sw.control),
                ac.connect(self.R1.n, self.R2.n, self.src.n, self.gnd.p)]


def test_boolean_two_way_switch_routes_p_to_n2_while_true():
    res = ac.simulate(BooleanTwoWayBench(), t_end=1.0, rtol=1e-9, t_eval=[0.25, 0.75])
    assert res["R1.i"][0] == pytest.approx(10.0 / 2.0, rel=1e-5)
    assert res["R2.i"][1] == pytest.approx(10.0 / 3.0, rel=1e-5)
    assert abs(res["R2.i"][0]) < 1e-5 and abs(res["R1.i"][1]) < 1e-5
    # LossPower: Ron (10/2 A)^2 in the closed branch, Goff (5 V)^2 in the open one
    assert res["sw.LossPower"][0] == pytest.approx(1e-6 * 25.0 + 1e-7 * 25.0, rel=1e-4)


class BooleanIntermediateBench(ac.Component):
    """p1 at 10 V and p2 at 4 V through 1 Ohm each; n1 and n2 to ground through 1 Ohm
    and 2 Ohm: crossed from 0.5 s."""

    s1 = el.ConstantVoltage(V=10.0)
    s2 = el.ConstantVoltage(V=4.0)
    Ra = el.Resistor(R=1.0)
    Rb = el.Resistor(R=1.0)
    sw = el.IdealIntermediateSwitch(Ron=1e-6, Goff=1e-7)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=2.0)
    ctl = BooleanStep(startTime=0.5)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.s1.p, self.Ra.p), ac.connect(self.Ra.n, self.sw.p1),
                ac.connect(self.s2.p, self.Rb.p), ac.connect(self.Rb.n, self.sw.p2),
                ac.connect(self.sw.n1, self.R1.p), ac.connect(self.sw.n2, self.R2.p),
                ac.connect(self.ctl.y, self.sw.control),
                ac.connect(self.R1.n, self.R2.n, self.s1.n, self.s2.n, self.gnd.p)]


def test_boolean_intermediate_switch_crosses_while_true():
    res = ac.simulate(BooleanIntermediateBench(), t_end=1.0, rtol=1e-9, t_eval=[0.25, 0.75])
    straight, crossed = 0, 1
    assert res["R1.i"][straight] == pytest.approx(5.0, rel=1e-5)
    assert res["R2.i"][straight] == pytest.approx(4.0 / 3.0, rel=1e-5)
    assert res["R1.i"][crossed] == pytest.approx(2.0, rel=1e-5)
    assert res["R2.i"][crossed] == pytest.approx(10.0 / 3.0, rel=1e-5)


V_SRC, L, R_ARC, V0, DVDT, VMAX = 50.0, 0.1, 1.0, 30.0, 1e4, 60.0


class ArcBench(ac.Component):
    """50 V into 0.1 H and 1 Ohm through a switch with an arc, closed by a Boolean step
    at 0.1 s and opened at 0.6 s."""

    def __init__(self, switch, opener, **mods):
        super().__init__(**mods)
        self.src = el.ConstantVoltage(V=V_SRC)
        self.sw = switch
        self.L = el.Inductor(L=L, i={"start": 0.0, "fixed": True})
        self.R = el.Resistor(R=R_ARC)
        # the closer's control: true in [0.1, 0.6); the opener's: its opposite
        self.ctl = BooleanPulse(width=50.0, period=1.0, startTime=0.1) if not opener \
            else _Inverted()
        self.gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.sw.p), ac.connect(self.sw.n, self.L.p),
                ac.connect(self.L.n, self.R.p), ac.connect(self.ctl.y, self.sw.control),
                ac.connect(self.R.n, self.src.n, self.gnd.p)]


class _Inverted(ac.Component):
    """not (0.1 <= time < 0.6)."""

    from acausal.ports import BooleanOutput
    y = BooleanOutput()

    def equations(self):
        return [ac.Eq(self.y, ~((ac.time >= 0.1) & (ac.time < 0.6)))]


def _arc_reference(t_eval):
    """The circuit integrated on its own: closed, L di/dt = V - (R + Ron) i; from the opening at 0.6 s the arc v = min(Vmax, V0 + dVdt
    (t - 0.6)) against the current until it quenches (|i| <= |v| Goff), then the open
    switch's Goff."""
    i_leak = V_SRC * GOFF / (1 + R_ARC * GOFF)       # open: i = Goff v (L Goff = 1 us)

    def closed_current(t):
        r = R_ARC + RON
        return V_SRC / r + (i_leak - V_SRC / r) * np.exp(-(t - 0.1) * r / L)
    i_open = closed_current(0.6)

    def arc(t, y):
        return [(V_SRC - R_ARC * y[0] - min(VMAX, V0 + DVDT * (t - 0.6))) / L]

    def quench(t, y):                   # |i| <= |v| Goff
        return y[0] - min(VMAX, V0 + DVDT * (t - 0.6)) * GOFF
    quench.terminal, quench.direction = True, -1
    sol = solve_ivp(arc, (0.6, 1.0), [i_open], events=quench, rtol=1e-12, atol=1e-12,
                    dense_output=True)
    t_q = float(sol.t_events[0][0])
    out = np.full_like(t_eval, i_leak)
    out[0] = 0.0                                     # i(0) = 0, the leak after 1 us
    closed = (t_eval >= 0.1) & (t_eval < 0.6)
    out[closed] = closed_current(t_eval[closed])
    arcing = (t_eval >= 0.6) & (t_eval < t_q)
    out[arcing] = sol.sol(t_eval[arcing])[0]
    return out, t_q


@pytest.mark.parametrize("cls, opener", [(el.CloserWithArc, False), (el.OpenerWithArc, True)])
def test_switch_with_arc_holds_the_current_until_the_arc_quenches(cls, opener):
    t = np.linspace(0.0, 1.0, 1001)
    switch = cls(V0=V0, dVdt=DVDT, Vmax=VMAX, off={"fixed": True})
    res = ac.simulate(ArcBench(switch, opener), t_end=1.0, rtol=1e-9, t_eval=t,
                      raise_on_failure=True)
    exact, t_q = _arc_reference(t)
    # after the quench the current decays from 0 to the open switch's leak, i = Goff v
    # with v -> 50 V, at the rate of the circuit (tau = L/R): within 5e-4 A of the leak
    before = (t < t_q - 1e-6) & (np.abs(t - 0.1) > 1e-5) & (t > 1e-5)
    assert np.max(np.abs(res["L.i"][before] - exact[before])) < 1e-6 * 50
    after = t > t_q + 1e-3
    assert np.max(np.abs(res["L.i"][after] - exact[after])) < 5e-4
    events = np.array([float(e) for e in res.events])
    assert np.min(np.abs(events - t_q)) < 1e-6          # the quench, at 0.78 s
    quenched = res["sw.quenched"]
    assert not quenched[(t > 0.1) & (t < t_q - 1e-3)].any()
    assert quenched[t > t_q + 1e-3].all()
    # the arc voltage while it burns: the ramp from V0 and the cap Vmax
    burning = (t > 0.6 + 1e-4) & (t < t_q - 1e-4)
    ramp = np.minimum(VMAX, V0 + DVDT * (t[burning] - 0.6))
    assert np.max(np.abs(res["sw.v"][burning] - ramp)) < 1e-9 * VMAX
    assert res["sw.tSwitch"][-1] == pytest.approx(0.6, abs=1e-12)
    assert np.min(res["sw.LossPower"]) > -1e-9


class SwitchedCapacitorBench(ac.Component):
    """1 V through a switched capacitor (clock 10 ms, C = clock/|R|) into Cbig = 1 mF; the
    switches' Goff 1e-12 S (their leak would move 1e-5 V a period)."""

    def __init__(self, R, **mods):
        super().__init__(**mods)
        self.src = el.ConstantVoltage(V=1.0)
        self.sc = SwitchedCapacitor(clock=0.01, R=R,
                                    Capacitor={"v": {"start": 0.0, "fixed": True}},
                                    IdealCommutingSwitch1={"Goff": 1e-12},
                                    IdealCommutingSwitch2={"Goff": 1e-12})
        self.Cbig = el.Capacitor(C=1e-3, v={"start": 0.0, "fixed": True})
        self.gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.sc.p), ac.connect(self.sc.n, self.Cbig.p),
                ac.connect(self.src.n, self.Cbig.n, self.gnd.p)]


@pytest.mark.parametrize("R", [100.0, -100.0])
def test_switched_capacitor_moves_a_charge_c_v_each_period(R):
    """Each period (the clock's first half true) the capacitor C = clock/|R| = 0.1 mF
    shares its charge with Cbig: R > 0, discharged then put between 1 V and Cbig,
    v_k = (Cbig v_k-1 + C)/(Cbig + C); R < 0, charged to 1 V then its + plate grounded,
    v_k = (Cbig v_k-1 - C)/(Cbig + C).  So v_k = +-(1 - a^k), a = Cbig/(Cbig + C): a
    resistance |R| = clock/C, negative for R < 0."""
    clock, C, Cbig = 0.01, 1e-4, 1e-3
    t = clock * (np.arange(1, 21) - 0.25)          # in the second half of each period
    res = ac.simulate(SwitchedCapacitorBench(R), t_end=0.2, rtol=1e-8, t_eval=t,
                      raise_on_failure=True)
    k = np.arange(1, 21)
    exact = np.sign(R) * (1 - (Cbig / (Cbig + C))**k)
    # Ron = 1e-5 Ohm: the charge settles within nanoseconds
    assert np.max(np.abs(res["Cbig.v"] - exact)) < 1e-8
    assert res.compiled.derived_parameters["sc.C"] == pytest.approx(C, rel=1e-12)


class _SourcesThroughAnOpenSwitch(ac.Component):
    """5 V and 2 V sources joined by a closing switch with Ron = 0, held open by its
    control (a step at t = 1 s): open, it carries Goff times the 3 V across it."""

    V1 = el.ConstantVoltage(V=5.0)
    V2 = el.ConstantVoltage(V=2.0)
    sw = el.IdealClosingSwitch(booleanControl=False, Ron=0.0, Goff=1e-5)
    ground = el.Ground()
    step = Step(startTime=1.0)

    def equations(self):
        c = ac.connect
        return [c(self.V1.p, self.sw.p), c(self.sw.n, self.V2.p),
                c(self.V1.n, self.ground.p), c(self.V2.n, self.ground.p),
                c(self.step.y, self.sw.control)]


def test_a_switch_its_control_holds_open_starts_open():
    # the discrete state at the start values: the switch's Boolean 'off' is its equation
    # (not control) there, not its own start value (false: closed), which with Ron = 0
    # would short the two sources in the first solve
    res = ac.simulate(_SourcesThroughAnOpenSwitch(), t_end=0.5)
    assert res.success, res.message
    assert np.all(res["sw.off"] == 1)
    assert np.allclose(res["sw.i"], 1e-5 * 3.0, rtol=1e-9, atol=0)
    # when it closes, the loop of two sources is refused, naming the switch
    res = ac.simulate(_SourcesThroughAnOpenSwitch(), t_end=2.0)
    assert not res.success and "sw.s" in res.message and 0.99 < res.t[-1] <= 1.0 + 1e-9
