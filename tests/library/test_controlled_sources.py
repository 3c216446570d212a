"""Controlled sources, the coupled-inductor Transformer and the Gyrator (MSL
Analog.Basic) against their algebraic laws and scipy's solve_ivp (Radau, rtol 1e-10) on
the hand-written transformer equations."""
import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import electrical as el

V, F = 2.0, 3.0                 # source amplitude [V] and frequency [Hz]


class ControlledSources(ac.Component):
    """One sine source controls a VCV and a VCC (port 1 across it) and, through a series
    resistor Rs, a CCV and a CCC (port 1 in series: an ammeter); each drives a load."""

    source = el.SineVoltage(V=V, f=F)
    ground = el.Ground()
    vcv = el.VCV(gain=3.0)
    vcc = el.VCC(transConductance=0.01)
    Rs = el.Resistor(R=50.0)
    ccv = el.CCV(transResistance=200.0)
    ccc = el.CCC(gain=4.0)
    R1 = el.Resistor(R=10.0)
    R2 = el.Resistor(R=100.0)
    R3 = el.Resistor(R=20.0)
    R4 = el.Resistor(R=30.0)

    def equations(self):
        g = self.ground.p
        return [ac.connect(self.source.p, self.vcv.p1, self.vcc.p1, self.Rs.p),
                ac.connect(self.source.n, self.vcv.n1, self.vcc.n1, g,
                           self.vcv.n2, self.vcc.n2, self.ccv.n2, self.ccc.n2,
                           self.R1.n, self.R2.n, self.R3.n, self.R4.n, self.ccc.n1),
                ac.connect(self.Rs.n, self.ccv.p1),
                ac.connect(self.ccv.n1, self.ccc.p1),
                ac.connect(self.vcv.p2, self.R1.p), ac.connect(self.vcc.p2, self.R2.p),
                ac.connect(self.ccv.p2, self.R3.p), ac.connect(self.ccc.p2, self.R4.p)]


def test_controlled_sources_laws():
    t = np.linspace(0, 0.5, 51)
    model = ControlledSources()
    res = ac.simulate(model, t_end=0.5, rtol=1e-10, atol=1e-12, t_eval=t)
    vs = V * np.sin(2 * np.pi * F * t)
    i1 = vs / 50.0                                     # the ammeter ports short Rs to ground
    # a load R across (p2, n2) carries -i2 from p2 to n2, so v_R = v2 = -R i2
    assert np.max(np.abs(res["R1.v"] - 3.0 * vs)) < 1e-10 * V
    assert np.max(np.abs(res["R2.v"] + 0.01 * vs * 100.0)) < 1e-10 * V
    assert np.max(np.abs(res["R3.v"] - 200.0 * i1)) < 1e-10 * V
    assert np.max(np.abs(res["R4.v"] + 4.0 * i1 * 30.0)) < 1e-10 * V
    assert np.max(np.abs(res["vcv.i1"])) < 1e-12 * V / 50.0
    assert np.max(np.abs(res["ccv.v1"])) < 1e-12 * V
    audit = energy_balance(res, model)
    assert not audit.violations


L1, L2, M, RL = 1.0, 0.5, 0.6, 4.0   # H, H, H (M^2 < L1 L2), load Ohm


class LoadedTransformer(ac.Component):
    source = el.SineVoltage(V=V, f=F)
    transformer = el.Transformer(L1=L1, L2=L2, M=M, i1={"start": 0.0, "fixed": True},
                                 i2={"start": 0.0, "fixed": True})
    load = el.Resistor(R=RL)
    ground = el.Ground()
    ground2 = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.transformer.p1),
                ac.connect(self.source.n, self.transformer.n1, self.ground.p),
                ac.connect(self.transformer.p2, self.load.p),
                ac.connect(self.transformer.n2, self.load.n, self.ground2.p)]


def test_transformer_against_solve_ivp():
    """[L1 M; M L2] d/dt (i1, i2) = (V sin(2 pi F t), -RL i2)."""
    Lm = np.array([[L1, M], [M, L2]])

    def rhs(t, y):
        return np.linalg.solve(Lm, [V * np.sin(2 * np.pi * F * t), -RL * y[1]])

    t = np.linspace(0, 1, 81)
    ref = solve_ivp(rhs, (0, 1), [0.0, 0.0], method="Radau", rtol=1e-10, atol=1e-12,
                    t_eval=t)
    model = LoadedTransformer()
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    scale = np.max(np.abs(ref.y))
    assert np.max(np.abs(res["transformer.i1"] - ref.y[0])) < 1e-7 * scale
    assert np.max(np.abs(res["transformer.i2"] - ref.y[1])) < 1e-7 * scale
    audit = energy_balance(res, model)
    assert not audit.violations and audit.relative_residual() < 1e-6


class GyratedCapacitor(ac.Component):
    """A gyrator (G1 = G2 = G) turns a capacitor into an inductor L = C / G^2: with a
    resistor across port 1 the current decays as i = i0 exp(-R t / L)."""

    gyrator = el.Gyrator(G1=0.1, G2=0.1)
    C = el.Capacitor(C=1e-2, v={"start": 0.5, "fixed": True})
    R = el.Resistor(R=2.0)
    ground = el.Ground()
    ground2 = el.Ground()

    def equations(self):
        return [ac.connect(self.gyrator.p1, self.R.p),
                ac.connect(self.gyrator.n1, self.R.n, self.ground.p),
                ac.connect(self.gyrator.p2, self.C.p),
                ac.connect(self.gyrator.n2, self.C.n, self.ground2.p)]


def test_gyrator_turns_a_capacitor_into_an_inductor():
    t = np.linspace(0, 1, 41)
    res = ac.simulate(GyratedCapacitor(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    L = 1e-2 / 0.1**2
    i0 = 0.1 * 0.5                                    # i1 = G2 v2 at t = 0
    assert np.max(np.abs(res["gyrator.i1"] - i0 * np.exp(-2.0 * t / L))) < 1e-8 * i0


class WaveSources(ac.Component):
    """A cosine and a damped-sine voltage, each across a resistor."""

    cosine = el.CosineVoltage(V=3.0, f=2.0, phase=0.4, offset=0.5)
    exp_sine = el.ExpSineVoltage(V=2.0, f=3.0, phase=0.2, damping=2.5, offset=-0.1,
                                 startTime=0.25)
    trapezoid = el.TrapezoidVoltage(V=4.0, rising=0.05, width=0.1, falling=0.15,
                                    period=0.4, startTime=0.1)
    R1 = el.Resistor(R=10.0)
    R2 = el.Resistor(R=20.0)
    R3 = el.Resistor(R=30.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.cosine.p, self.R1.p), ac.connect(self.exp_sine.p, self.R2.p),
                ac.connect(self.trapezoid.p, self.R3.p),
                ac.connect(self.cosine.n, self.exp_sine.n, self.trapezoid.n, self.R1.n,
                           self.R2.n, self.R3.n, self.ground.p)]


def test_cosine_exp_sine_and_trapezoid_voltages():
    t = np.linspace(0, 1, 41)
    res = ac.simulate(WaveSources(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    cos = 0.5 + 3.0 * np.cos(2 * np.pi * 2.0 * t + 0.4)
    tau = t - 0.25
    exp_sine = -0.1 + np.where(tau >= 0, 2.0 * np.exp(-2.5 * tau)
                               * np.sin(2 * np.pi * 3.0 * tau + 0.2), 0.0)
    assert np.max(np.abs(res["R1.v"] - cos)) < 1e-10 * 3.5
    assert np.max(np.abs(res["R2.v"] - exp_sine)) < 1e-10 * 2.1
    phase = np.mod(t - 0.1, 0.4)
    shape = np.select([phase < 0.05, phase < 0.15, phase < 0.3],
                      [4.0 * phase / 0.05, 4.0, 4.0 * (0.3 - phase) / 0.15], 0.0)
    assert np.max(np.abs(res["R3.v"] - np.where(t >= 0.1, shape, 0.0))) < 1e-10 * 4.0
