"""Electrical components, sources and sensors against closed forms, equivalent circuits
and scipy's solve_ivp (rtol 1e-10) on the hand-written circuit equations."""
import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import electrical as el
from acausal.library.blocks import Sine, Step


class HalfWaveRectifier(ac.Component):
    """5 V, 50 Hz through a diode into C = 100 uF with a 100 Ohm load."""

    source = el.SineVoltage(V=5.0, f=50.0)
    diode = el.Diode()
    C = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    load = el.Resistor(R=100.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.diode.p),
                ac.connect(self.diode.n, self.C.p, self.load.p),
                ac.connect(self.source.n, self.C.n, self.load.n, self.ground.p)]


def _diode_current(v, Ids=1e-6, Vt=0.04, Maxexp=15.0, R=1e8):
    x = v / Vt
    law = np.exp(Maxexp) * (1 + x - Maxexp) if x > Maxexp else np.exp(x)
    return Ids * (law - 1) + v / R


def test_half_wave_rectifier_against_solve_ivp():
    def rhs(t, y):
        v_d = 5.0 * np.sin(2 * np.pi * 50.0 * t) - y[0]
        return [(_diode_current(v_d) - y[0] / 100.0) / 1e-4]

    t = np.linspace(0, 0.04, 81)
    ref = solve_ivp(rhs, (0, 0.04), [0.0], method="Radau", rtol=1e-10, atol=1e-12, t_eval=t)
    res = ac.simulate(HalfWaveRectifier(), t_end=0.04, rtol=1e-10, t_eval=t)
    assert np.max(ref.y[0]) > 4.0                     # the capacitor charges to ~ peak - 0.5 V
    assert np.max(np.abs(res["C.v"] - ref.y[0])) < 1e-7 * 5.0
    # the diode law holds at every output point
    v_d, i_d = res["diode.v"], res["diode.i"]
    assert np.max(np.abs(i_d - np.array([_diode_current(v) for v in v_d]))) < 1e-9


class OpAmpCircuits(ac.Component):
    """An inverting amplifier (R2/R1 = 3) and an integrator (R C = 0.01 s) on a sine."""

    source = el.SineVoltage(V=1.0, f=5.0)
    ground = el.Ground()
    R1 = el.Resistor(R=1e3)
    R2 = el.Resistor(R=3e3)
    amplifier = el.IdealOpAmp3Pin()
    Ri = el.Resistor(R=1e4)
    Ci = el.Capacitor(C=1e-6, v={"start": 0.0, "fixed": True})
    integrator = el.IdealOpAmp3Pin()

    def equations(self):
        return [ac.connect(self.source.p, self.R1.p, self.Ri.p),
                ac.connect(self.R1.n, self.R2.p, self.amplifier.in_n),
                ac.connect(self.R2.n, self.amplifier.out),
                ac.connect(self.Ri.n, self.Ci.p, self.integrator.in_n),
                ac.connect(self.Ci.n, self.integrator.out),
                ac.connect(self.source.n, self.ground.p, self.amplifier.in_p,
                           self.integrator.in_p)]


def test_ideal_opamp_inverting_amplifier_and_integrator():
    t = np.linspace(0, 0.4, 81)
    res = ac.simulate(OpAmpCircuits(), t_end=0.4, rtol=1e-10, t_eval=t)
    w = 2 * np.pi * 5.0
    v_in = np.sin(w * t)
    assert np.max(np.abs(res["amplifier.out.v"] + 3.0 * v_in)) < 1e-9
    v_int = -(1 - np.cos(w * t)) / w / (1e4 * 1e-6)
    assert np.max(np.abs(res["integrator.out.v"] - v_int)) < 1e-7 * 6.4
    # virtual ground, the op-amp's equation v_n = v_p = 0: judged on the scale of the
    # potentials around it (the input's 1 V), to 10 rtol (the solver resolves its
    # unknowns to a fraction of rtol)
    assert np.max(np.abs(res["amplifier.in_n.v"])) < 1e-9 * np.max(np.abs(v_in))


class TransformerWithLoad(ac.Component):
    """230 V / 50 Hz through 50 Ohm on the primary; RC load (R = 10 Ohm, C = 1 mF) on
    the secondary."""

    source = el.SineVoltage(V=230.0, f=50.0)
    Rs = el.Resistor(R=50.0)
    transformer = el.IdealTransformer(n=10.0)
    R = el.Resistor(R=10.0)
    C = el.Capacitor(C=1e-3, v={"start": 0.0, "fixed": True})
    ground1 = el.Ground()
    ground2 = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.Rs.p),
                ac.connect(self.Rs.n, self.transformer.p1),
                ac.connect(self.source.n, self.transformer.n1, self.ground1.p),
                ac.connect(self.transformer.p2, self.R.p, self.C.p),
                ac.connect(self.transformer.n2, self.R.n, self.C.n, self.ground2.p)]


class ReflectedLoad(ac.Component):
    """The same load referred to the primary: R n^2, C / n^2."""

    source = el.SineVoltage(V=230.0, f=50.0)
    Rs = el.Resistor(R=50.0)
    R = el.Resistor(R=10.0 * 100.0)
    C = el.Capacitor(C=1e-3 / 100.0, v={"start": 0.0, "fixed": True})
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.Rs.p),
                ac.connect(self.Rs.n, self.R.p, self.C.p),
                ac.connect(self.source.n, self.R.n, self.C.n, self.ground.p)]


def test_ideal_transformer_is_lossless_and_reflects_impedance():
    t = np.linspace(0, 0.06, 61)
    res = ac.simulate(TransformerWithLoad(), t_end=0.06, rtol=1e-10, t_eval=t)
    ref = ac.simulate(ReflectedLoad(), t_end=0.06, rtol=1e-10, t_eval=t)
    tr = "transformer."
    v1 = np.max(np.abs(res[tr + "v1"]))                # 230 V: bounds relative to it
    assert np.max(np.abs(res[tr + "v1"] - 10.0 * res[tr + "v2"])) < 1e-9 * v1
    p1, p2 = res[tr + "v1"] * res[tr + "i1"], res[tr + "v2"] * res[tr + "i2"]
    assert np.max(np.abs(p1 + p2)) < 1e-9 * np.max(np.abs(p1))
    assert np.max(np.abs(10.0 * res["C.v"] - ref["C.v"])) < 1e-7 * 230.0


class SourcesOnResistors(ac.Component):
    """Every voltage and current source on its own 2 Ohm resistor; the pulse current
    also charges a capacitor (a state, so that the solver steps)."""

    ramp_v = el.RampVoltage(V=3.0, duration=0.5, offset=1.0, startTime=0.2)
    pulse_v = el.PulseVoltage(V=2.0, width=25.0, period=0.4, offset=-1.0, startTime=0.1)
    step_i = el.StepCurrent(I=1.5, offset=0.5, startTime=0.3)
    ramp_i = el.RampCurrent(I=-2.0, duration=0.3, startTime=0.4)
    sine_i = el.SineCurrent(I=0.7, f=3.0, phase=0.2, startTime=0.05)
    pulse_i = el.PulseCurrent(I=1.0, width=50.0, period=0.2)
    C = el.Capacitor(C=1.0)
    ground = el.Ground()

    def __init__(self, **mods):
        super().__init__(**mods)
        self.loads = [el.Resistor(R=2.0) for _ in range(6)]

    def equations(self):
        sources = [self.ramp_v, self.pulse_v, self.step_i, self.ramp_i, self.sine_i,
                   self.pulse_i]
        return [*(eq for src, load in zip(sources, self.loads)
                  for eq in (ac.connect(src.p, load.p), ac.connect(src.n, load.n, self.ground.p))),
                ac.connect(self.pulse_i.p, self.C.p), ac.connect(self.C.n, self.ground.p)]


def test_source_waveforms():
    t = np.linspace(0, 1, 201)
    res = ac.simulate(SourcesOnResistors(), t_end=1, rtol=1e-8, t_eval=t)
    assert np.allclose(res["ramp_v.v"], 1.0 + 3.0 * np.clip((t - 0.2) / 0.5, 0, 1), atol=1e-12)
    phase = np.mod(t - 0.1, 0.4) / 0.4
    away = np.minimum(np.abs(phase - 0.25), np.minimum(phase, 1 - phase)) > 1e-6
    pulse = np.where((t >= 0.1) & (phase < 0.25), 1.0, -1.0)
    assert np.allclose(res["pulse_v.v"][away], pulse[away], atol=1e-12)
    assert np.allclose(res["step_i.i"], np.where(t >= 0.3, 2.0, 0.5), atol=1e-12)
    assert np.allclose(res["ramp_i.i"], -2.0 * np.clip((t - 0.4) / 0.3, 0, 1), atol=1e-12)
    sine = np.where(t >= 0.05, 0.7 * np.sin(6 * np.pi * (t - 0.05) + 0.2), 0.0)
    assert np.allclose(res["sine_i.i"], sine, atol=1e-12)
    # a current source's i flows p -> n through it, so its resistor carries -i
    assert np.allclose(res["loads[2].v"], -2.0 * res["step_i.i"], atol=1e-12)


class MeasuredRC(ac.Component):
    """A signal-driven voltage source charging C through R, with all three sensors."""

    reference = Sine(amplitude=10.0, f=2.0)
    source = el.SignalVoltage()
    meter = el.PowerSensor()
    ammeter = el.CurrentSensor()
    R = el.Resistor(R=100.0)
    C = el.Capacitor(C=1e-3, v={"start": 0.0, "fixed": True})
    voltmeter = el.VoltageSensor()
    probe = el.PotentialSensor()
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.reference.y, self.source.v),
                ac.connect(self.source.p, self.meter.pc, self.meter.pv),
                ac.connect(self.meter.nc, self.ammeter.p),
                ac.connect(self.ammeter.n, self.R.p),
                ac.connect(self.R.n, self.C.p, self.voltmeter.p, self.probe.p),
                ac.connect(self.source.n, self.C.n, self.voltmeter.n, self.meter.nv,
                           self.ground.p)]


def test_signal_voltage_rc_and_sensors():
    """RC low-pass on v = 10 sin(w t): closed form; power in = R i^2 + d/dt(C v^2/2)."""
    t = np.linspace(0, 1, 101)
    res = ac.simulate(MeasuredRC(), t_end=1, rtol=1e-10, t_eval=t)
    w, tau = 4 * np.pi, 0.1
    vc = 10.0 * (np.sin(w * t) - w * tau * np.cos(w * t) + w * tau * np.exp(-t / tau)) \
        / (1 + (w * tau)**2)
    assert np.max(np.abs(res["C.v"] - vc)) < 1e-7 * 10.0
    assert np.allclose(res["voltmeter.v.signal"], res["C.v"], atol=1e-12)
    assert np.allclose(res["probe.phi.signal"], res["C.v"], atol=1e-12)
    i = res["ammeter.i.signal"]
    assert np.allclose(i, res["R.i"], atol=1e-12)
    stored = 1e-3 * res["C.v"] * res["der(C.v)"]
    power = res["meter.power.signal"]
    assert np.max(np.abs(power - (100.0 * i**2 + stored))) < 1e-9 * np.max(np.abs(power))


class ChargedBySignalCurrent(ac.Component):
    reference = Sine(amplitude=0.5, f=1.0)
    source = el.SignalCurrent()
    C = el.Capacitor(C=0.1, v={"start": 0.0, "fixed": True})
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.reference.y, self.source.i),
                ac.connect(self.source.n, self.C.p),
                ac.connect(self.source.p, self.C.n, self.ground.p)]


def test_signal_current_charges_capacitor():
    t = np.linspace(0, 2, 81)
    res = ac.simulate(ChargedBySignalCurrent(), t_end=2, rtol=1e-10, t_eval=t)
    v = 0.5 / 0.1 * (1 - np.cos(2 * np.pi * t)) / (2 * np.pi)
    assert np.max(np.abs(res["C.v"] - v)) < 1e-7 * 1.6


class IdealRectifier(ac.Component):
    """5 V, 50 Hz (phase -0.3 rad) through 1 Ohm and an ideal diode into 100 uF || 100 Ohm."""

    source = el.SineVoltage(V=5.0, f=50.0, phase=-0.3)
    Rs = el.Resistor(R=1.0)
    diode = el.IdealDiode()
    C = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    load = el.Resistor(R=100.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.Rs.p), ac.connect(self.Rs.n, self.diode.p),
                ac.connect(self.diode.n, self.C.p, self.load.p),
                ac.connect(self.source.n, self.C.n, self.load.n, self.ground.p)]


RON = GOFF = 1e-5


def _ideal_rectifier_reference(t):
    """Conducting: i = (u - v_c)/(Rs + Ron); blocking: i = Goff (u - v_c)/(1 + Rs Goff);
    integrated by solve_ivp, restarted at every switching."""
    def u(x):
        return 5.0 * np.sin(2 * np.pi * 50.0 * x - 0.3)

    def rhs(x, y):
        du = u(x) - y[0]
        i = du / (1.0 + RON) if du >= 0 else GOFF * du / (1 + GOFF)
        return [(i - y[0] / 100.0) / 1e-4]

    def switches(x, y):
        return u(x) - y[0]
    switches.terminal = True

    pieces, t0, y0 = [], 0.0, [0.0]
    while True:
        sol = solve_ivp(rhs, (t0, t[-1]), y0, rtol=1e-11, atol=1e-12, events=switches,
                        dense_output=True)
        pieces.append(sol)
        if sol.status == 0:
            break
        t0 = sol.t_events[0][0] + 1e-12
        y0 = sol.sol(t0)
    return np.array([next(p for p in pieces if x <= p.t[-1] + 1e-12).sol(x)[0] for x in t])


def test_ideal_diode_rectifier_against_solve_ivp():
    t = np.linspace(0, 0.04, 81)
    exact = _ideal_rectifier_reference(t)
    res = ac.simulate(IdealRectifier(), t_end=0.04, rtol=1e-9, t_eval=t)
    assert np.max(exact) > 4.0
    assert np.max(np.abs(res["C.v"] - exact)) < 1e-7 * 5.0
    assert len(res.events) >= 4                       # on, off, on, off
    # the characteristic holds to the Newton tolerance of the torn loop (rtol * 5 V)
    on = res["diode.s"] >= 0
    assert np.allclose(res["diode.v"][on], RON * res["diode.i"][on], rtol=0, atol=5e-9)
    assert np.allclose(res["diode.i"][~on], GOFF * res["diode.v"][~on], rtol=0, atol=5e-9)


def test_ideal_diode_rectifier_at_tight_tolerance():
    t = np.linspace(0, 0.04, 81)
    res = ac.simulate(IdealRectifier(), t_end=0.04, rtol=1e-10, t_eval=t,
                      raise_on_failure=True)
    assert np.max(np.abs(res["C.v"] - _ideal_rectifier_reference(t))) < 1e-7 * 5.0


class SwitchedRC(ac.Component):
    """2 V charges C = 1 mF through 1 kOhm once a switch closes at 0.5 s; a second
    switch in series opens at 2 s and the capacitor keeps its charge."""

    close_at = Step(height=1.0, startTime=0.5)
    open_at = Step(height=1.0, startTime=2.0)
    source = el.ConstantVoltage(V=2.0)
    closing = el.IdealClosingSwitch(Goff=0.0)
    opening = el.IdealOpeningSwitch(Goff=0.0)
    R = el.Resistor(R=1e3)
    C = el.Capacitor(C=1e-3, v={"start": 0.0, "fixed": True})
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.close_at.y, self.closing.control),
                ac.connect(self.open_at.y, self.opening.control),
                ac.connect(self.source.p, self.closing.p),
                ac.connect(self.closing.n, self.opening.p),
                ac.connect(self.opening.n, self.R.p),
                ac.connect(self.R.n, self.C.p),
                ac.connect(self.source.n, self.C.n, self.ground.p)]


def test_ideal_switches_close_and_open():
    t = np.linspace(0, 3, 121)
    res = ac.simulate(SwitchedRC(), t_end=3, rtol=1e-10, t_eval=t)
    tau = (1e3 + 2e-5) * 1e-3
    charging = 2.0 * (1 - np.exp(-(np.clip(t, 0.5, 2.0) - 0.5) / tau))
    assert np.max(np.abs(res["C.v"] - charging)) < 1e-7 * 2.0
    # open with Goff = 0: no current, judged on the charging current 2 V/1 kOhm
    assert np.max(np.abs(res["R.i"][t > 2.0])) < 1e-9 * 2.0 / 1e3
