"""Conditional connectors (``ac.Conditional``): a port that exists only with its structural
flag, the component's equations giving the internal default without it; the heat ports
of the MSL's ConditionalHeatPort against a closed form, the Boolean-controlled switch and
brake against closed forms."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library import electrical as el
from acausal.library import rotational as rot
from acausal.library.blocks import BooleanStep
from acausal.library.electrical.interfaces import ConditionalHeatPort, OnePort
from acausal.library.thermal import FixedHeatFlow, HeatCapacitor, PartialConditionalHeatPort
from acausal.ports import HeatPort, RotationalFlange


class HeatedResistor(ConditionalHeatPort, OnePort):
    """v = R (1 + alpha (T_heatPort - T_ref)) i,  LossPower = v i (MSL Resistor's form)."""

    R = ac.Parameter(2.0, unit="Ohm")
    T_ref = ac.Parameter(300.0, unit="K")
    alpha = ac.Parameter(0.0, unit="1/K")

    def equations(self):
        R = self.R * (1 + self.alpha * (self.T_heatPort - self.T_ref))
        return [ac.Eq(self.v, R * self.i), ac.Eq(self.LossPower, self.v * self.i)]


class Heater(ac.Component):
    """10 V on the resistor; its heat into a capacitor of 5 J/K from 300 K."""

    source = el.ConstantVoltage(V=10.0)
    r = HeatedResistor(useHeatPort=True)
    c = HeatCapacitor(C=5.0, T={"start": 300.0, "fixed": True})
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.r.p), ac.connect(self.r.n, self.source.n,
                                                                   self.ground.p),
                ac.connect(self.r.heatPort, self.c.port)]


def test_a_heat_port_carries_the_loss_into_what_it_is_connected_to():
    t = np.linspace(0.0, 2.0, 21)
    res = ac.simulate(Heater(), t_end=2.0, t_eval=t, rtol=1e-10)
    # C dT/dt = V^2/R: T = 300 + 50 t / 5
    assert np.max(np.abs(res["c.T"] - (300.0 + 10.0 * t))) < 1e-8 * 320
    assert np.allclose(res["r.heatPort.Q_flow"], -50.0, rtol=1e-12)


def test_a_heat_port_with_temperature_dependent_resistance_follows_its_closed_form():
    # R(T) = R0 (1 + a (T - 300)), C dT/dt = V^2/R(T): (1 + a u) du = V^2/(R0 C) dt with
    # u = T - 300, so u + a u^2/2 = 10 t
    model = Heater(r={"alpha": 0.01})
    t = np.linspace(0.0, 2.0, 21)
    res = ac.simulate(model, t_end=2.0, t_eval=t, rtol=1e-10)
    a = 0.01
    u = (-1 + np.sqrt(1 + 2 * a * 10.0 * t)) / a
    assert np.max(np.abs(res["c.T"] - (300.0 + u))) < 1e-7 * 320


def test_without_its_heat_port_the_device_is_at_its_fixed_temperature():
    class Divider(ac.Component):
        source = el.ConstantVoltage(V=10.0)
        r = HeatedResistor(alpha=0.01, T=350.0)
        ground = el.Ground()

        def equations(self):
            return [ac.connect(self.source.p, self.r.p),
                    ac.connect(self.r.n, self.source.n, self.ground.p)]
    res = ac.simulate(Divider(), t_end=1.0, n_points=3)
    assert np.allclose(res["r.T_heatPort"], 350.0)
    assert np.allclose(res["r.i"], 10.0 / (2.0 * 1.5), rtol=1e-12)   # R(350) = 3 Ohm
    with pytest.raises(ac.AbsentComponent, match=r"HeatedResistor.heatPort exists only "
                                                 r"with useHeatPort=True"):
        HeatedResistor().heatPort


class Block(PartialConditionalHeatPort):
    """A part that dissipates 20 W into the internal heat port."""

    loss = FixedHeatFlow(Q_flow=20.0)

    def equations(self):
        return [ac.connect(self.loss.port, self.internalHeatPort)]


def test_a_composite_conditional_heat_port_takes_a_fixed_temperature_without_it():
    plain = Block(T=310.0)
    with pytest.raises(ac.AbsentComponent, match="heatPort exists only with useHeatPort=True"):
        plain.heatPort
    with pytest.raises(ac.AbsentComponent, match="fixedTemperature exists only with "
                                                 "useHeatPort=False"):
        Block(useHeatPort=True).fixedTemperature
    res = ac.simulate(plain, t_end=1.0, n_points=3)
    assert np.allclose(res["internalHeatPort.T"], 310.0)
    assert np.allclose(res["fixedTemperature.port.Q_flow"], 20.0)   # the loss, absorbed

    class Warmed(ac.Component):
        block = Block(useHeatPort=True)
        c = HeatCapacitor(C=4.0, T={"start": 300.0, "fixed": True})

        def equations(self):
            return [ac.connect(self.block.heatPort, self.c.port)]
    t = np.linspace(0.0, 1.0, 11)
    res = ac.simulate(Warmed(), t_end=1.0, t_eval=t, rtol=1e-10)
    assert np.max(np.abs(res["c.T"] - (300.0 + 5.0 * t))) < 1e-9 * 305.0


def test_the_flag_of_a_conditional_is_a_structural_boolean_parameter():
    with pytest.raises(ac.InvalidValue, match="structural Boolean parameter"):
        class Bad(ac.Component):
            use = ac.Parameter(0.0)
            port = ac.Conditional(HeatPort(), "use")
    with pytest.raises(ac.InvalidValue, match="useSupport must be True or False"):
        rot.Torque(useSupport=1)


class SwitchedRC(ac.Component):
    """10 V through a switch closing at 0.2 s into 1 kOhm and 100 uF."""

    source = el.ConstantVoltage(V=10.0)
    switch = el.IdealClosingSwitch(booleanControl=True, Ron=1e-5)
    step = BooleanStep(startTime=0.2)
    R = el.Resistor(R=1000.0)
    C = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.step.y, self.switch.control),
                ac.connect(self.source.p, self.switch.p), ac.connect(self.switch.n, self.R.p),
                ac.connect(self.R.n, self.C.p),
                ac.connect(self.C.n, self.source.n, self.ground.p)]


def test_a_boolean_controlled_switch_charges_the_capacitor_from_its_closing():
    t = np.linspace(0.0, 0.6, 61)
    res = ac.simulate(SwitchedRC(), t_end=0.6, t_eval=t, rtol=1e-10)
    tau = (1000.0 + 1e-5) * 1e-4
    # open: the capacitor charges through Goff = 1e-5 S, 1e5 Ohm in series (tau_off = 10 s)
    tau_off = (1e5 + 1000.0) * 1e-4
    v_open = 10.0 * (1 - np.exp(-np.minimum(t, 0.2) / tau_off))
    v = np.where(t < 0.2, v_open, 10.0 - (10.0 - v_open) * np.exp(-(t - 0.2) / tau))
    assert np.max(np.abs(res["C.v"] - v)) < 1e-7 * 10.0


def test_a_boolean_engaged_brake_stops_a_spinning_inertia_at_the_closed_form_time():
    class Braked(ac.Component):
        inertia = rot.Inertia(J=2.0, w={"start": 10.0, "fixed": True},
                              phi={"start": 0.0, "fixed": True})
        brake = rot.Brake(booleanControl=True, fn_max=100.0, cgeo=0.1, mu_pos=[[0, 0.5]])
        step = BooleanStep(startTime=1.0)

        def equations(self):
            return [ac.connect(self.inertia.flange_b, self.brake.flange_a),
                    ac.connect(self.step.y, self.brake.engaged)]
    tau = 0.5 * 0.1 * 100.0                      # 5 N.m
    t_stop = 1.0 + 2.0 * 10.0 / tau              # 5 s
    t = np.linspace(0.0, 7.0, 71)
    res = ac.simulate(Braked(), t_end=7.0, t_eval=t, rtol=1e-9)
    w = np.where(t < 1.0, 10.0, np.maximum(10.0 - tau / 2.0 * (t - 1.0), 0.0))
    assert np.max(np.abs(res["inertia.w"] - w)) < 1e-6 * 10.0
    with pytest.raises(ac.AbsentComponent, match="f_normalized exists only with "
                                                 "booleanControl=False"):
        rot.Brake(booleanControl=True).f_normalized
