"""The MSL's initialization choices (``initType``: NoInit, SteadyState, InitialState,
InitialOutput) of the continuous blocks, and the ``steady`` attribute of a variable on
mechanical and thermal components, each against a closed form."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import thermal as th
from acausal.library.blocks import (PI, Constant, FirstOrder, Integrator, SecondOrder,
                                    TransferFunction)

T_END = 3.0
t = np.linspace(0.0, T_END, 31)


def _driven(block, u=1.0):
    class Driven(ac.Component):
        source = Constant(k=u)
        b = block

        def equations(self):
            return [ac.connect(self.source.y, self.b.u)]
    return ac.simulate(Driven(), t_end=T_END, t_eval=t, rtol=1e-10)


@pytest.mark.parametrize("init, y0", [("NoInit", 0.0), ("SteadyState", 2.0),
                                      ("InitialState", 0.5), ("InitialOutput", 0.5)])
def test_first_order_starts_as_its_init_type_says(init, y0):
    res = _driven(FirstOrder(k=2.0, T=0.5, initType=init, y_start=0.5))
    assert np.max(np.abs(res["b.y"] - (2.0 + (y0 - 2.0) * np.exp(-t / 0.5)))) < 1e-8


def test_integrator_initial_state_and_steady_state():
    res = _driven(Integrator(k=2.0, initType="InitialState", y_start=3.0))
    assert np.max(np.abs(res["b.y"] - (3.0 + 2.0 * t))) < 1e-8
    with pytest.raises(ac.InitializationFailed, match=r"der\(b.x\) = 0"):   # k u = 2
        _driven(Integrator(k=2.0, initType="SteadyState"))


def test_second_order_initial_output_holds_its_derivative_at_zero():
    k, w, D = 1.5, 2.0, 0.5
    res = _driven(SecondOrder(k=k, w=w, D=D, initType="InitialOutput", y_start=0.2))
    # y'' + 2 D w y' + w^2 y = w^2 k, y(0) = 0.2, y'(0) = 0
    wd = w * math.sqrt(1 - D**2)
    c1 = 0.2 - k
    c2 = D * w * c1 / wd
    exact = k + np.exp(-D * w * t) * (c1 * np.cos(wd * t) + c2 * np.sin(wd * t))
    assert np.max(np.abs(res["b.y"] - exact)) < 1e-8
    steady = _driven(SecondOrder(k=k, w=w, D=D, initType="SteadyState"))
    assert np.max(np.abs(steady["b.y"] - k)) < 1e-9


def test_transfer_function_steady_state_and_initial_output():
    # 1/(s^2 + 3 s + 2), u = 1: steady y = 1/2
    steady = _driven(TransferFunction(b=[1.0], a=[1.0, 3.0, 2.0], initType="SteadyState"))
    assert np.max(np.abs(steady["b.y"] - 0.5)) < 1e-9
    # InitialOutput: y(0) = 1 and the upper state's derivative 0: y'(0) = -1/3, so
    # y = 1/2 + (2/3) e^-t - (1/6) e^-2t
    res = _driven(TransferFunction(b=[1.0], a=[1.0, 3.0, 2.0], initType="InitialOutput",
                                   y_start=1.0))
    exact = 0.5 + 2 / 3 * np.exp(-t) - 1 / 6 * np.exp(-2 * t)
    assert np.max(np.abs(res["b.y"] - exact)) < 1e-8
    state = _driven(TransferFunction(b=[1.0], a=[1.0, 3.0, 2.0], initType="InitialState",
                                     x_start=(1.0, 0.0)))
    # y(0) = 1, y'(0) = 0: y = 1/2 + e^-t - (1/2) e^-2t
    assert np.max(np.abs(state["b.y"] - (0.5 + np.exp(-t) - 0.5 * np.exp(-2 * t)))) < 1e-8


def test_pi_initial_output():
    # v = k u + x_i, der(x_i) = k/Ti u: with u = 1, y(0) = 1 gives x_i(0) = 1 - k
    res = _driven(PI(k=0.5, Ti=2.0, initType="InitialOutput", y_start=1.0))
    assert np.max(np.abs(res["b.y"] - (1.0 + 0.5 / 2.0 * t))) < 1e-8


def test_an_unknown_init_type_is_named():
    with pytest.raises(ac.InvalidValue, match=r"'Steady' is not one of 'NoInit', "
                                              r"'SteadyState'"):
        FirstOrder(initType="Steady")


def test_steady_state_of_an_inertia_and_a_heat_capacitor():
    class Spinning(ac.Component):
        """2 N.m into an inertia against a damper of 0.5 N.m.s: steady at 4 rad/s."""

        torque = rot.ConstantTorque(tau_constant=2.0)
        inertia = rot.Inertia(J=1.0, w={"steady": True})
        damper = rot.Damper(d=0.5)
        fixed = rot.Fixed()

        def equations(self):
            return [ac.connect(self.torque.flange, self.inertia.flange_a),
                    ac.connect(self.inertia.flange_b, self.damper.flange_a),
                    ac.connect(self.damper.flange_b, self.fixed.flange)]
    res = ac.simulate(Spinning(), t_end=T_END, t_eval=t, rtol=1e-10)
    assert np.max(np.abs(res["inertia.w"] - 4.0)) < 1e-9

    class Warm(ac.Component):
        """10 W into a capacity held by 2 W/K to 300 K: steady at 305 K."""

        heater = th.FixedHeatFlow(Q_flow=10.0)
        c = th.HeatCapacitor(C=50.0, T={"steady": True})
        wall = th.ThermalConductor(G=2.0)
        ambient = th.FixedTemperature(T=300.0)

        def equations(self):
            return [ac.connect(self.heater.port, self.c.port),
                    ac.connect(self.c.port, self.wall.port_a),
                    ac.connect(self.wall.port_b, self.ambient.port)]
    res = ac.simulate(Warm(), t_end=T_END, t_eval=t, rtol=1e-10)
    assert np.max(np.abs(res["c.T"] - 305.0)) < 1e-9
