"""Basic elements and sources of Modelica.Electrical.Analog (MSL v4.0.0) against closed
forms: the saturating inductor's flux law, the temperature coefficients of the
resistive elements, the adaptors, the sources of variable frequency, the supply pair,
the trapezoid's number of periods and the pulse width in percent."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library import electrical as el
from acausal.library.blocks import Ramp


class DrivenSaturatingInductor(ac.Component):
    """A current ramp of 3 A/s through a SaturatingInductor (Lzer = 2, Lnom = 1 at
    Inom = 1 A, Linf = 0.5)."""

    src = el.RampCurrent(I=3.0, duration=1.0)
    L = el.SaturatingInductor(Lzer=2.0, Lnom=1.0, Inom=1.0, Linf=0.5)
    gnd = el.Ground()

    def equations(self):
        # the source's current flows from p to n through it: out of n, into L.p
        return [ac.connect(self.src.n, self.L.p), ac.connect(self.src.p, self.L.n, self.gnd.p)]


def test_saturating_inductor_flux_law_and_nominal_point():
    t = np.linspace(0.0, 0.99, 100)
    res = ac.simulate(DrivenSaturatingInductor(), t_end=1.0, rtol=1e-10, t_eval=t)
    i, psi, v = res["L.i"], res["L.Psi"], res["L.v"]
    Ipar = res["L.Ipar"][0]
    # Ipar solves (Lnom - Linf)/(Lzer - Linf) = Ipar/Inom (pi/2 - atan(Ipar/Inom))
    assert Ipar * (math.pi / 2 - math.atan(Ipar)) == pytest.approx(1 / 3, rel=1e-12)
    assert np.allclose(i, 3.0 * t, atol=1e-12)
    law = 0.5 * i + 1.5 * Ipar * np.arctan(i / Ipar)
    assert np.max(np.abs(psi - law)) < 1e-12 * law.max()
    # v = der(Psi) = (Linf + (Lzer - Linf)/(1 + (i/Ipar)^2)) di/dt
    assert np.allclose(v, (0.5 + 1.5 / (1 + (i / Ipar) ** 2)) * 3.0, rtol=1e-8)
    # at the nominal current the inductance Psi/i is Lnom, and Lact = Psi/i
    assert 0.5 + 1.5 * Ipar * math.atan(1.0 / Ipar) == pytest.approx(1.0, rel=1e-12)
    nz = i > 0
    assert np.allclose(res["L.Lact"][nz], psi[nz] / i[nz], rtol=1e-10)
    assert res["L.Lact"][0] == pytest.approx(2.0, rel=1e-12)           # Lzer at i = 0


def test_saturating_inductor_refuses_an_order_other_than_lzer_lnom_linf():
    class Bad(DrivenSaturatingInductor):
        L = el.SaturatingInductor(Lzer=0.9, Lnom=1.0, Linf=0.5)
    with pytest.raises(ac.InvalidValue, match="Lzer > Lnom > Linf"):
        ac.compile(Bad())


class HotResistors(ac.Component):
    """10 V across a VariableResistor (R = 5) and a VariableConductor (G = 0.2), at
    T = 350 K with alpha = 4e-3 1/K about T_ref = 300 K, and across a Resistor, a
    Conductor and a Potentiometer with the same alpha and T_ref (without a heat port:
    at T_ref)."""

    src = el.ConstantVoltage(V=10.0)
    R = el.Resistor(R=5.0, T_ref=300.0, alpha=4e-3)
    G = el.Conductor(G=0.2, T_ref=300.0, alpha=4e-3)
    VR = el.VariableResistor(T_ref=300.0, alpha=4e-3, T=350.0)
    VG = el.VariableConductor(T_ref=300.0, alpha=4e-3, T=350.0)
    pot = el.Potentiometer(R=5.0, T_ref=300.0, alpha=4e-3, rConstant=0.25)
    r = Ramp(offset=5.0, height=0.0)
    g = Ramp(offset=0.2, height=0.0)
    gnd = el.Ground()

    def equations(self):
        top, bottom = self.src.p, self.src.n
        return [ac.connect(top, self.R.p, self.G.p, self.VR.p, self.VG.p, self.pot.pin_p),
                ac.connect(bottom, self.R.n, self.G.n, self.VR.n, self.VG.n,
                           self.pot.pin_n, self.gnd.p),
                ac.connect(self.r.y, self.VR.R), ac.connect(self.g.y, self.VG.G)]


def test_temperature_coefficient_of_the_resistive_elements():
    res = ac.simulate(HotResistors(), t_end=1.0, rtol=1e-10, t_eval=[0.5])
    factor = 1 + 4e-3 * 50.0
    assert res["VR.i"][0] == pytest.approx(10.0 / (5.0 * factor), rel=1e-12)
    assert res["VR.R_actual"][0] == pytest.approx(5.0 * factor, rel=1e-12)
    assert res["VG.i"][0] == pytest.approx(0.2 / factor * 10.0, rel=1e-12)
    assert res["VR.LossPower"][0] == pytest.approx(100.0 / (5.0 * factor), rel=1e-12)
    # at their reference temperature: no change of resistance
    assert res["R.i"][0] == pytest.approx(2.0, rel=1e-12)
    assert res["G.i"][0] == pytest.approx(2.0, rel=1e-12)
    assert res["pot.pin_p.i"][0] == pytest.approx(2.0, rel=1e-12)
    with pytest.raises(ac.NotInModel):
        el.Resistor(T=350.0)           # no temperature of its own without the heat port


def test_resistor_accepts_a_negative_resistance_as_the_msl_does():
    el.Resistor(R=-1.0)
    el.Conductor(G=-1.0)
    el.Inductor(L=-1.0)
    with pytest.raises(ac.InvalidValue):
        el.Capacitor(C=-1.0)                 # SI.Capacitance has min = 0


class SweptSeries(ac.Component):
    """A sine and a cosine voltage of 1 V whose frequency ramps 0 -> 200 Hz in 1 s,
    each across 1 Ohm."""

    ramp = Ramp(height=200.0, duration=1.0)
    sv = el.SineVoltageVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                     phi={"fixed": True})
    cv = el.CosineCurrentVariableFrequencyAndAmplitude(useConstantFrequency=True,
                                                       constantFrequency=50.0,
                                                       phi={"fixed": True})
    amp = Ramp(height=2.0, duration=1.0, offset=1.0)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=1.0)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.ramp.y, self.sv.f), ac.connect(self.amp.y, self.cv.I),
                ac.connect(self.sv.p, self.R1.p), ac.connect(self.cv.n, self.R2.p),
                ac.connect(self.sv.n, self.R1.n, self.cv.p, self.R2.n, self.gnd.p)]


def test_variable_frequency_sources_integrate_their_phase():
    """phi = 2 pi int f dt: f = 200 t gives phi = 200 pi t^2; a constant 50 Hz with a
    ramping amplitude 1 + 2t gives i = (1 + 2t) cos(100 pi t)."""
    t = np.linspace(0.0, 0.99, 200)
    res = ac.simulate(SweptSeries(), t_end=1.0, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["sv.phi"] - 200 * math.pi * t**2)) < 1e-7 * 200 * math.pi
    assert np.max(np.abs(res["sv.v"] - np.sin(200 * math.pi * t**2))) < 1e-6
    assert np.max(np.abs(res["cv.i"] - (1 + 2 * t) * np.cos(100 * math.pi * t))) < 1e-6
    assert np.max(np.abs(res["R2.i"] - res["cv.i"])) < 1e-12


class Supplies(ac.Component):
    """A SupplyVoltage pair loaded by 1 kOhm on each side, its middle at 2 V."""

    sup = el.SupplyVoltage(Vps=12.0, Vns=-5.0)
    mid = el.ConstantVoltage(V=2.0)
    Rp = el.Resistor(R=1e3)
    Rn = el.Resistor(R=1e3)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.mid.p, self.sup.ground, self.Rp.n, self.Rn.p),
                ac.connect(self.sup.pin_p, self.Rp.p), ac.connect(self.sup.pin_n, self.Rn.n),
                ac.connect(self.mid.n, self.gnd.p)]


def test_supply_voltage_pair():
    res = ac.simulate(Supplies(), t_end=1.0, rtol=1e-10, t_eval=[0.5])
    assert res["sup.pin_p.v"][0] == pytest.approx(14.0, rel=1e-12)
    assert res["sup.pin_n.v"][0] == pytest.approx(-3.0, rel=1e-12)
    assert res["Rp.i"][0] == pytest.approx(12e-3, rel=1e-12)


class Trapezoids(ac.Component):
    """A TrapezoidCurrent of 2 periods and a PulseVoltage of 25 % width, into 1 Ohm."""

    tc = el.TrapezoidCurrent(I=2.0, rising=0.1, width=0.2, falling=0.1, period=0.5,
                             nperiod=2, startTime=0.1, offset=0.5)
    pv = el.PulseVoltage(V=3.0, width=25.0, period=0.4, startTime=0.0)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=1.0)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.tc.n, self.R1.p), ac.connect(self.pv.p, self.R2.p),
                ac.connect(self.tc.p, self.R1.n, self.pv.n, self.R2.n, self.gnd.p)]


def test_trapezoid_current_stops_after_nperiod_and_pulse_width_is_in_percent():
    t = np.array([0.05, 0.15, 0.3, 0.45, 0.55, 0.7, 0.85, 1.05, 1.25, 1.4, 1.85])
    res = ac.simulate(Trapezoids(), t_end=2.0, rtol=1e-10, t_eval=t)
    phase = (t - 0.1) % 0.5
    shape = np.where(phase < 0.1, 20.0 * phase, np.where(phase < 0.3, 2.0,
                     np.where(phase < 0.4, 2.0 * (0.4 - phase) / 0.1, 0.0)))
    expected = 0.5 + np.where((t >= 0.1) & (t < 0.1 + 2 * 0.5), shape, 0.0)
    assert np.allclose(res["tc.i"], expected, atol=1e-12)
    high = ((t % 0.4) < 0.1)
    assert np.allclose(res["pv.v"], np.where(high, 3.0, 0.0), atol=1e-12)


class AdaptedRC(ac.Component):
    """A current source into a capacitor C1, whose voltage drives, through two adaptors
    (voltage -> current -> voltage), a resistor into C2 -- and the same written
    directly."""

    src = el.SineCurrent(I=1e-3, f=5.0)
    C1 = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    probe = el.GeneralCurrentToVoltageAdaptor(use_pder=True, use_fder=False)
    drive = el.GeneralVoltageToCurrentAdaptor(use_pder=True, use_fder=True)
    R = el.Resistor(R=1e3)
    C2 = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    g1 = el.Ground()
    g2 = el.Ground()
    zero = Ramp(height=0.0)

    def equations(self):
        return [ac.connect(self.src.n, self.C1.p, self.probe.pin_p),
                ac.connect(self.src.p, self.C1.n, self.probe.pin_n, self.g1.p),
                ac.connect(self.zero.y, self.probe.f),
                ac.connect(self.probe.p, self.drive.p), ac.connect(self.probe.pder, self.drive.pder),
                ac.connect(self.drive.pin_p, self.R.p), ac.connect(self.R.n, self.C2.p),
                ac.connect(self.drive.pin_n, self.C2.n, self.g2.p)]


def test_adaptors_carry_voltage_current_and_their_derivatives():
    t = np.linspace(0.0, 0.4, 81)
    res = ac.simulate(AdaptedRC(), t_end=0.4, rtol=1e-10, t_eval=t)
    w = 2 * math.pi * 5.0
    v1 = 1e-3 / 1e-4 * (1 - np.cos(w * t)) / w                    # C1 integrates the source
    assert np.max(np.abs(res["C1.v"] - v1)) < 1e-8 * v1.max()
    assert np.max(np.abs(res["probe.pder"] - 10.0 * np.sin(w * t))) < 1e-7 * 10.0
    # the driven side: the adaptor imposes v1 on R + C2; its f output is the current
    # out of pin_p into R, and fder its derivative
    assert np.max(np.abs(res["drive.v"] - v1)) < 1e-8 * v1.max()
    assert np.max(np.abs(res["drive.f"] - res["R.i"])) < 1e-12 * np.max(np.abs(res["R.i"]))
    # R.i = (v1 - C2.v)/R, so der(R.i) = (der(v1) - R.i/C2)/R
    di = (res["probe.pder"] - res["R.i"] / 1e-4) / 1e3
    assert np.max(np.abs(res["drive.fder"] - di)) < 1e-8 * np.max(np.abs(di))
