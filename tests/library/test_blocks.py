"""Signal blocks against closed forms and scipy.signal.

Dynamic results are compared at rtol = 1e-10, where the integrator's global error is
10-100 rtol (it converges: 2.6e-7, 3.1e-9, 6.8e-11 at rtol 1e-8, 1e-10, 1e-12 for the
third-order transfer function below), hence bounds of 1e-7 on O(1) signals; algebraic
relations are checked to rounding.
"""
import numpy as np
import pytest
import scipy.signal as sig

import acausal as ac
from acausal.library import blocks as bl


def _chain(*blocks, **named):
    """A model of blocks connected in series, y of each to u of the next."""

    class Chain(ac.Component):
        def equations(self):
            return [ac.connect(a.y, b.u) for a, b in zip(self.stages, self.stages[1:])]

    model = Chain()
    model.stages = list(blocks)
    for name, comp in named.items():
        setattr(model, name, comp)
    return model


def test_sources_step_ramp_sine():
    class Sources(ac.Component):
        step = bl.Step(height=2.0, offset=-1.0, startTime=0.3)
        ramp = bl.Ramp(height=3.0, duration=0.4, offset=1.0, startTime=0.2)
        sine = bl.Sine(amplitude=1.5, f=2.0, phase=0.3, offset=0.5, startTime=0.1)
        const = bl.Constant(k=4.0)

    t = np.linspace(0, 1, 101)
    res = ac.simulate(Sources(), t_end=1, rtol=1e-10, t_eval=t)
    assert np.allclose(res["step.y.signal"], np.where(t >= 0.3, 1.0, -1.0), atol=1e-12)
    ramp = 1.0 + 3.0 * np.clip((t - 0.2) / 0.4, 0, 1)
    assert np.allclose(res["ramp.y.signal"], ramp, atol=1e-12)
    sine = 0.5 + np.where(t >= 0.1, 1.5 * np.sin(4 * np.pi * (t - 0.1) + 0.3), 0)
    assert np.allclose(res["sine.y.signal"], sine, atol=1e-12)
    assert np.all(res["const.y.signal"] == 4.0)      # the parameter's value, assigned


class Pulses(ac.Component):
    pulse = bl.Pulse(amplitude=2.0, width=30.0, period=0.25, offset=0.5, startTime=0.1)
    integral = bl.Integrator()

    def equations(self):
        return [ac.connect(self.pulse.y, self.integral.u)]


# high during [0.1, 0.175), [0.35, 0.425), [0.6, 0.675), [0.85, 0.925) within [0, 1]
PULSE_INTEGRAL = 0.5 * 1.0 + 2.0 * 4 * 0.075


def test_pulse_values_and_edges():
    res = ac.simulate(Pulses(), t_end=1.0, rtol=1e-10, t_eval=np.linspace(0, 1, 401))
    phase = np.mod(res.t - 0.1, 0.25) / 0.25
    away = np.minimum(np.abs(phase - 0.3), np.minimum(phase, 1 - phase)) > 1e-6
    high = (res.t >= 0.1) & (phase < 0.3)
    y = res["pulse.y.signal"]
    # exact away from the edges: offset + amplitude = 2.5 is representable, and the
    # output is an explicit function of time, not a solver unknown
    assert np.all(y[away & high] == 2.5) and np.all(y[away & ~high] == 0.5)
    assert res["integral.y.signal"][-1] == pytest.approx(PULSE_INTEGRAL, abs=1e-9)
    assert len(res.events) == 8


def test_pulse_without_max_step():
    """Relations of time alone are time events found before integrating, so a long
    step cannot jump over a whole pulse."""
    res = ac.simulate(Pulses(), t_end=1.0, rtol=1e-10, t_eval=np.linspace(0, 1, 401))
    assert res["integral.y.signal"][-1] == pytest.approx(PULSE_INTEGRAL, abs=1e-9)


def test_math_blocks():
    class Arithmetic(ac.Component):
        a = bl.Sine(amplitude=1.0, f=1.0)
        b = bl.Ramp(height=2.0, duration=1.0)
        add = bl.Add(k1=2.0, k2=-3.0)
        product = bl.Product()
        feedback = bl.Feedback()
        gain = bl.Gain(k=0.5)

        def equations(self):
            return [ac.connect(self.a.y, self.add.u1, self.product.u1, self.feedback.u1),
                    ac.connect(self.b.y, self.add.u2, self.product.u2, self.feedback.u2),
                    ac.connect(self.product.y, self.gain.u)]

    t = np.linspace(0, 1, 51)
    res = ac.simulate(Arithmetic(), t_end=1, rtol=1e-8, t_eval=t)
    a, b = np.sin(2 * np.pi * t), 2.0 * t
    assert np.allclose(res["add.y.signal"], 2 * a - 3 * b, atol=1e-12)
    assert np.allclose(res["feedback.y.signal"], a - b, atol=1e-12)
    assert np.allclose(res["gain.y.signal"], 0.5 * a * b, atol=1e-12)


def test_integrator_derivative_first_order():
    """Ramp u = t: Integrator t^2/2, Derivative k (1 - exp(-t/T)), FirstOrder lag."""

    class Linear(ac.Component):
        u = bl.Ramp(height=1.0, duration=10.0)
        integ = bl.Integrator(k=2.0, x=1.0)
        deriv = bl.Derivative(k=3.0, T=0.05)
        lag = bl.FirstOrder(k=2.0, T=0.3)

        def equations(self):
            return [ac.connect(self.u.y, self.integ.u, self.deriv.u, self.lag.u)]

    t = np.linspace(0, 2, 81)
    res = ac.simulate(Linear(), t_end=2, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["integ.y.signal"] - (1.0 + t**2 * 0.1))) < 1e-7
    assert np.max(np.abs(res["deriv.y.signal"] - 0.3 * (1 - np.exp(-t / 0.05)))) < 1e-7
    lag = 2.0 * 0.1 * (t - 0.3 * (1 - np.exp(-t / 0.3)))
    assert np.max(np.abs(res["lag.y.signal"] - lag)) < 1e-7


@pytest.mark.parametrize("num, den", [([1.0], [0.5, 1.0]),
                                      ([2.0, 1.0], [1.0, 0.8, 4.0]),
                                      ([0.5, 0.0, 1.0, 3.0], [1.0, 2.0, 3.0, 1.5])])
def test_transfer_function_step_matches_scipy(num, den):
    model = _chain(bl.Step(height=1.0), bl.TransferFunction(b=num, a=den))
    t = np.linspace(0, 5, 101)
    res = ac.simulate(model, t_end=5, rtol=1e-10, t_eval=t)
    _, expected = sig.step(sig.lti(num, den), T=t)
    assert np.max(np.abs(res["stages[1].y.signal"] - expected)) < 1e-7


def test_second_order_matches_transfer_function():
    model = _chain(bl.Step(height=1.0), bl.SecondOrder(k=2.0, w=3.0, D=0.2))
    t = np.linspace(0, 5, 101)
    res = ac.simulate(model, t_end=5, rtol=1e-10, t_eval=t)
    _, expected = sig.step(sig.lti([2.0 * 9.0], [1.0, 2 * 0.2 * 3.0, 9.0]), T=t)
    assert np.max(np.abs(res["stages[1].y.signal"] - expected)) < 1e-7


class LoopWithPID(ac.Component):
    """Unit step reference, PID on the plant 1/(s (0.5 s + 1))."""

    reference = bl.Step(height=1.0)
    error = bl.Feedback()
    controller = bl.PID(k=2.0, Ti=1.5, Td=0.2, Nd=8.0)
    plant = bl.TransferFunction(b=[1.0], a=[0.5, 1.0, 0.0])

    def equations(self):
        return [ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.plant.y, self.error.u2),
                ac.connect(self.error.y, self.controller.u),
                ac.connect(self.controller.y, self.plant.u)]


def test_pid_closed_loop_matches_scipy():
    k, Ti, Td, Nd = 2.0, 1.5, 0.2, 8.0
    tf = Td / Nd
    # C(s) = k (1 + 1/(Ti s) + Td s/(1 + tf s)) over the common denominator Ti s (1 + tf s)
    c_num = k * np.polyadd(np.polymul([Ti, 0.0], [tf, 1.0]),
                           np.polyadd([tf, 1.0], [Ti * Td, 0.0, 0.0]))
    c_den = np.polymul([Ti, 0.0], [tf, 1.0])
    open_num, open_den = c_num, np.polymul(c_den, [0.5, 1.0, 0.0])
    closed = sig.lti(open_num, np.polyadd(open_den, open_num))
    t = np.linspace(0, 8, 161)
    _, expected = sig.step(closed, T=t)
    res = ac.simulate(LoopWithPID(), t_end=8, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["plant.y.signal"] - expected)) < 1e-7


class WindUp(ac.Component):
    """A PI with a constant error 1 and output limit 2 (k = 1, Ti = 1)."""

    error = bl.Constant(k=1.0)
    pi = bl.PI(k=1.0, Ti=1.0, yMax=2.0, yMin=-2.0, Tt=0.5)
    free = bl.PI(k=1.0, Ti=1.0, yMax=2.0, yMin=-2.0, Tt=float("inf"))

    def equations(self):
        return [ac.connect(self.error.y, self.pi.u, self.free.u)]


def test_pi_output_limit_and_anti_windup():
    """v = 1 + t until the limit at t = 1, then dv/dt = 1 + (2 - v)/Tt: v -> 2 + Tt."""
    t = np.linspace(0, 4, 81)
    res = ac.simulate(WindUp(), t_end=4, rtol=1e-10, t_eval=t)
    v = np.where(t < 1, 1 + t, 2.5 - 0.5 * np.exp(-(t - 1) / 0.5))
    assert np.max(np.abs(res["pi.v"] - v)) < 1e-7
    assert np.allclose(res["pi.y.signal"], np.minimum(1 + t, 2.0), atol=1e-7)
    # without tracking (Tt = inf) the integral winds up without bound
    assert np.max(np.abs(res["free.v"] - (1 + t))) < 1e-7


def test_limiter_saturation_dead_zone():
    class Shapes(ac.Component):
        u = bl.Sine(amplitude=2.0, f=1.0)
        limiter = bl.Limiter(uMax=1.5, uMin=-0.5)
        saturation = bl.Saturation(limit=0.8)
        dead = bl.DeadZone(uMax=0.4, uMin=-1.0)

        def equations(self):
            return [ac.connect(self.u.y, self.limiter.u, self.saturation.u, self.dead.u)]

    t = np.linspace(0, 1, 201)
    res = ac.simulate(Shapes(), t_end=1, rtol=1e-8, t_eval=t)
    u = 2.0 * np.sin(2 * np.pi * t)
    assert np.allclose(res["limiter.y.signal"], np.clip(u, -0.5, 1.5), atol=1e-12)
    assert np.allclose(res["saturation.y.signal"], np.clip(u, -0.8, 0.8), atol=1e-12)
    dead = np.where(u > 0.4, u - 0.4, np.where(u < -1.0, u + 1.0, 0.0))
    assert np.allclose(res["dead.y.signal"], dead, atol=1e-12)
