"""Delays: PadeDelay against the closed-form Padé polynomials and the Lambert-W roots
of the delayed feedback loop's characteristic equation.

References: the [m/n] Padé approximant of exp(-z) and its error constant (Baker &
Graves-Morris, *Padé Approximants*, 2nd ed. 1996, sec. 1.2); the characteristic
equation s + a exp(-sT) = 0 of x' = -a x(t - T), whose roots are s = W_k(-aT)/T
(Asl & Ulsoy 2003, J. Dyn. Sys. Meas. Control 125: 215-223).
"""
from functools import lru_cache
from math import factorial

import numpy as np
import pytest
from scipy.special import lambertw

import acausal as ac
from acausal.library import blocks as bl
from acausal.library.blocks.delays import pade_coefficients
from acausal.ports import RealInput


class OpenPade(ac.Component):
    """A PadeDelay driven by a top-level input (for its transfer function)."""

    u = RealInput()

    def __init__(self, n, m=None, T=0.5, **mods):
        super().__init__(**mods)
        self.pade = bl.PadeDelay(n=n, m=m, delayTime=T)

    def equations(self):
        return [ac.connect(self.u, self.pade.u)]


class PadeLoop(ac.Component):
    """x' = -a y,  y = PadeDelay(x): the delayed loop x' = -a x(t - T), approximated."""

    def __init__(self, n, a=1.0, T=1.0, **mods):
        super().__init__(**mods)
        self.integ = bl.Integrator(k=-a, x={"start": 1.0})
        self.pade = bl.PadeDelay(n=n, delayTime=T)

    def equations(self):
        return [ac.connect(self.integ.y, self.pade.u), ac.connect(self.pade.y, self.integ.u)]


@lru_cache(maxsize=None)
def _pade_system(n, m, T=0.5):
    """The linearization of a PadeDelay from u to y (shared by the tests below)."""
    return ac.linearize(OpenPade(n, m, T), ["u"], ["pade.y.signal"])


def _roots(coeffs_low_first, T):
    return np.sort_complex(np.roots([float(c) for c in coeffs_low_first[::-1]]) / T)


def _match(a, b):
    """Largest distance from a root in a to its nearest in b, relative to max |b|."""
    return max(np.min(np.abs(b - x)) for x in a) / np.max(np.abs(b))


@pytest.mark.parametrize("n,m", [(1, 1), (2, 2), (4, 4), (8, 8), (10, 10), (4, 3), (5, 2)])
def test_pade_poles_and_zeros_are_the_pade_polynomial_roots(n, m):
    T = 0.5
    sys = _pade_system(n, m, T)
    p, q = pade_coefficients(n, m)
    assert sys.n_states == n
    assert _match(sys.poles(), _roots(q, T)) < 1e-10
    assert _match(_roots(q, T), sys.poles()) < 1e-10
    # numpy.roots of the numerator is itself ill-conditioned at high order (~1e-11)
    assert _match(sys.zeros(), _roots(p, T)) < 1e-9
    assert _match(_roots(p, T), sys.zeros()) < 1e-9
    # the gain at s = 0 is exp(0) = 1
    assert sys.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("n,wT", [(1, 0.1), (2, 0.2), (4, 1.0), (8, None)])
def test_pade_nn_is_all_pass_with_the_delay_phase(n, wT):
    """|G(jw)| = 1 at all frequencies; the phase error against -wT at low frequency is
    the Padé error constant, (n!)^2 / ((2n)! (2n+1)!) (wT)^(2n+1), to a relative
    O((wT)^2) (the next term of the series: 0.15 (wT)^2 for n = 1, less for larger n;
    wT is chosen per n to keep the error far above round-off)."""
    T = 0.5
    sys = _pade_system(n, n, T)
    w = np.logspace(-2, 3, 60) / T
    assert np.max(np.abs(np.abs(sys.freqresp(w)) - 1.0)) < 1e-12
    if wT is None:                   # n = 8: the error is below round-off for wT <~ 2
        return
    H = sys.freqresp([wT / T])[0]
    err = abs(np.angle(H * np.exp(1j * wT)))     # phase of G relative to exp(-j w T)
    c = factorial(n) ** 2 / (factorial(2 * n) * factorial(2 * n + 1))
    assert err == pytest.approx(c * wT ** (2 * n + 1), rel=0.2 * wT ** 2)


def test_pade_loop_poles_converge_to_lambert_w_root():
    """The rightmost root of s + a exp(-sT) = 0 is W_0(-aT)/T; the PadeDelay loop's
    nearest pole converges to it as n grows (super-geometrically: the Padé error is
    O(z^(2n+1)) with factorially small constants)."""
    a, T = 1.0, 1.0
    s0 = complex(lambertw(-a * T, 0)) / T
    errors = []
    for n in (1, 2, 3, 4, 6):
        poles = ac.linearize(PadeLoop(n, a, T), [], ["integ.y.signal"]).poles()
        errors.append(np.min(np.abs(poles - s0)) / abs(s0))
    assert all(e1 < 0.1 * e0 for e0, e1 in zip(errors, errors[1:]))
    assert errors[0] > 0.05 and errors[-1] < 1e-10
    # and the loop is stable as the true delayed loop is (aT < pi/2)
    assert s0.real < 0


def test_pade_delay_rejects_bad_orders():
    with pytest.raises(ac.ModelError, match="numerator order m"):
        bl.PadeDelay(n=2, m=3)
    with pytest.raises(ac.ModelError, match="order n"):
        bl.PadeDelay(n=0)
    with pytest.raises(ac.ModelError, match="integer"):
        bl.PadeDelay(n=2.5)


# -- FixedDelay and ac.delay ----------------------------------------------------------------
class DelayedDecay(ac.Component):
    """x' = -a x(t - T), x = 1 for t <= 0 (Modelica: the history is x(t0))."""

    a = ac.Parameter(1.0, unit="1/s")
    T = ac.Parameter(1.0, unit="s")
    x = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -self.a * ac.delay(self.x, self.T))]


def method_of_steps(a, T, n_pieces):
    """The exact solution of x' = -a x(t - T), x = 1 on [-T, 0], as polynomials: on
    [kT, (k+1)T], x_k(t) = x_{k-1}(kT) - a int_{kT}^t x_{k-1}(s - T) ds."""
    P = np.polynomial.Polynomial
    prev = P([1.0])                          # the history, on [-T, 0]
    pieces = []
    for k in range(n_pieces):
        shifted = prev(P([-T, 1.0]))         # s -> x_{k-1}(s - T), a composition
        piece = prev(k * T) - a * shifted.integ(lbnd=k * T)
        pieces.append(piece)
        prev = piece
    return pieces


def _exact_pieces(t, pieces, T):
    k = np.minimum((t // T).astype(int), len(pieces) - 1)
    return np.array([pieces[i](ti) for i, ti in zip(k, t)])


@pytest.mark.parametrize("a,T", [(1.0, 1.0), (2.0, 0.5), (0.5, 2.0), (3.0, 0.3)])
def test_delayed_decay_matches_method_of_steps(a, T):
    res = ac.simulate(DelayedDecay(a=a, T=T), t_end=5 * T, rtol=1e-9)
    assert res.success
    exact = _exact_pieces(res.t, method_of_steps(a, T, 5), T)
    assert np.max(np.abs(res["x"] - exact)) < 1e-7 * np.max(np.abs(exact))
    # the discontinuities of the derivatives come back at kT: each is a time event
    breaks = [e for e in res.event_times if e < 5 * T * (1 - 1e-12)]
    assert np.allclose(breaks, T * np.arange(1, len(breaks) + 1), rtol=1e-12)
    assert len(breaks) == 4


@pytest.mark.parametrize("a,T,window", [(1.0, 1.0, (15.0, 25.0)), (1.0, 0.2, (3.0, 8.0))])
def test_delayed_decay_rate_is_the_lambert_w_root(a, T, window):
    """Late in the run x(t) ~ Re(C e^(s0 t)), s0 = W_0(-aT)/T the rightmost root of
    s + a e^(-sT) = 0 (the next root decays faster: by e^(-1.2 t) at aT = 1, e^(-11 t) at
    aT = 0.2).  aT = 1: complex roots; uniform samples of a damped oscillation obey
    x[k+1] = c1 x[k] + c2 x[k-1] exactly, with z^2 - c1 z - c2 = 0 at z = e^(s dt), so
    least squares gives s (Prony's method).  aT = 0.2 < 1/e: s0 is real, the slope of
    log x."""
    s0 = complex(lambertw(-a * T, 0)) / T
    t = np.linspace(*window, 301)
    res = ac.simulate(DelayedDecay(a=a, T=T), t_end=window[1], rtol=1e-10, atol=1e-14,
                      t_eval=t)
    x = res["x"]
    if s0.imag == 0:
        s_fit = np.polyfit(t, np.log(x), 1)[0]
    else:
        dt = t[1] - t[0]
        M = np.column_stack([x[1:-1], x[:-2]])
        c1, c2 = np.linalg.lstsq(M, x[2:], rcond=None)[0]
        s = np.log(np.roots([1.0, -c1, -c2]).astype(complex)) / dt
        s_fit = s[np.argmax(s.imag)]
    assert abs(s_fit - s0) < 1e-7 * abs(s0)      # measured: 4e-10 and 1.4e-9


def test_nested_delays_add_up():
    """delay(delay(x, 0.3), 0.2) is x(t - 0.5): the outer delay's history is sampled
    from the inner delayed value; the method of steps with T = 0.5 is the reference."""
    class Nested(ac.Component):
        x = ac.Variable(start=1.0, fixed=True)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -ac.delay(ac.delay(self.x, 0.3), 0.2))]

    res = ac.simulate(Nested(), t_end=2.5, rtol=1e-9)
    exact = _exact_pieces(res.t, method_of_steps(1.0, 0.5, 5), 0.5)
    assert np.max(np.abs(res["x"] - exact)) < 1e-7 * np.max(np.abs(exact))


class FixedDelayLoop(ac.Component):
    """The same loop from blocks: an Integrator (gain -a) fed through a FixedDelay."""

    integ = bl.Integrator(k=-2.0, x={"start": 1.0, "fixed": True})
    delay = bl.FixedDelay(delayTime=0.5)

    def equations(self):
        return [ac.connect(self.integ.y, self.delay.u), ac.connect(self.delay.y, self.integ.u)]


def test_fixed_delay_loop_matches_method_of_steps():
    res = ac.simulate(FixedDelayLoop(), t_end=3.0, rtol=1e-9)
    exact = _exact_pieces(res.t, method_of_steps(2.0, 0.5, 6), 0.5)
    assert np.max(np.abs(res["integ.x"] - exact)) < 1e-7 * np.max(np.abs(exact))
    # the delay's output is the state half a second earlier
    late = res.t >= 0.5
    shifted = _exact_pieces(res.t[late] - 0.5, method_of_steps(2.0, 0.5, 6), 0.5)
    assert np.max(np.abs(res["delay.y.signal"][late] - shifted)) < 1e-7


class DelayedSine(ac.Component):
    """A sine through a FixedDelay, integrated (so the model has a state)."""

    sine = bl.Sine(amplitude=2.0, f=1.5, phase=0.7)
    delay = bl.FixedDelay(delayTime=0.25)
    integ = bl.Integrator()

    def equations(self):
        return [ac.connect(self.sine.y, self.delay.u), ac.connect(self.delay.y, self.integ.u)]


def _shifted_sine(t, T=0.25, A=2.0, f=1.5, phase=0.7):
    return A * np.sin(2 * np.pi * f * np.maximum(t - T, 0.0) + phase)


@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_sine_through_fixed_delay_is_the_shifted_sine(backend):
    if backend == "c":
        from acausal.compiler.backends.cbackend import compiler_available
        if compiler_available() is None:
            pytest.skip("no C compiler")
    t = np.linspace(0.0, 2.0, 401)
    res = ac.simulate(DelayedSine(), t_end=2.0, rtol=1e-9, t_eval=t, backend=backend)
    assert res.compiled.backend == backend
    y = res["delay.y.signal"]
    # the history's pieces are refined to 0.1 rtol of the signal's scale
    assert np.max(np.abs(y - _shifted_sine(t))) < 1e-9 * 2.0
    # the integral: u(t0) T0-long, then the shifted sine's integral
    w, T, A, ph = 2 * np.pi * 1.5, 0.25, 2.0, 0.7
    exact = np.where(t <= T, A * np.sin(ph) * t,
                     A * np.sin(ph) * T + A / w * (np.cos(ph) - np.cos(w * (t - T) + ph)))
    assert np.max(np.abs(res["integ.x"] - exact)) < 1e-7 * np.max(np.abs(exact))
    assert 0.25 in res.event_times        # the history's kink at t0 + T is an event


def test_discontinuities_are_followed_further_only_in_a_loop():
    """The compiler tells a loop through a delay (x' = -a x(t - T)) from a delay whose
    output never reaches its input (a sine delayed and integrated): in the loop the
    kink at t0 comes back at T, 2T, ...; without one only at T."""
    loop = ac.simulate(DelayedDecay(T=0.5), t_end=3.2)
    assert loop.compiled.model_code.delays.feedback
    assert np.allclose(loop.event_times, 0.5 * np.arange(1, 7), rtol=1e-12)
    chain = ac.simulate(DelayedSine(), t_end=1.0)
    assert not chain.compiled.model_code.delays.feedback
    assert np.allclose(chain.event_times, [0.25], rtol=1e-12)


def test_sine_through_fixed_delay_without_states():
    class Shift(ac.Component):
        sine = bl.Sine(amplitude=2.0, f=1.5, phase=0.7)
        delay = bl.FixedDelay(delayTime=0.25)

        def equations(self):
            return [ac.connect(self.sine.y, self.delay.u)]

    t = np.linspace(0.0, 2.0, 201)
    res = ac.simulate(Shift(), t_end=2.0, t_eval=t)
    assert np.max(np.abs(res["delay.y.signal"] - _shifted_sine(t))) < 1e-12 * 2.0


class DelayedStep(ac.Component):
    step = bl.Step(height=3.0, startTime=0.3)
    delay = bl.FixedDelay(delayTime=0.5)
    integ = bl.Integrator()

    def equations(self):
        return [ac.connect(self.step.y, self.delay.u), ac.connect(self.delay.y, self.integ.u)]


def test_step_through_fixed_delay_jumps_at_t1_plus_T():
    res = ac.simulate(DelayedStep(), t_end=1.5, rtol=1e-8)
    assert any(e == pytest.approx(0.8, rel=1e-14) for e in res.event_times)
    y, t = res["delay.y.signal"], res.t
    k = int(np.flatnonzero(np.isclose(t, 0.8, rtol=1e-14, atol=0.0))[0])
    assert np.all(y[: k + 1][t[: k + 1] < 0.8] == 0.0) and y[k] == 0.0   # before the event
    assert np.all(y[t > 0.8] == pytest.approx(3.0, rel=1e-12))
    assert y[k + 1] == pytest.approx(3.0, rel=1e-12) and t[k + 1] == t[k]   # after it
    # the integral of the delayed step is a ramp from 0.8 exactly
    assert np.max(np.abs(res["integ.x"] - 3.0 * np.maximum(t - 0.8, 0.0))) < 1e-9 * 3.0


class LoopAtStart(ac.Component):
    """v = k delay(v, T) + 1 + x, x' = 0.1 - x: the history v(t0) depends on itself."""

    k = ac.Parameter(0.7)
    T = ac.Parameter(0.4, unit="s")
    x = ac.Variable(start=0.0, fixed=True)
    v = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(self.v, self.k * ac.delay(self.v, self.T) + 1 + self.x),
                ac.Eq(ac.der(self.x), 0.1 - self.x)]


@pytest.mark.parametrize("k", [0.7, -3.0])
def test_history_at_start_solves_a_loop_through_the_delay(k):
    """v(t0) = k v(t0) + 1 (Modelica's rule, x(0) = 0): v(t0) = 1/(1 - k), even where the
    plain iteration v <- k v + 1 diverges (k = -3); then, by the method of steps,
    v = k v(t0) + 1 + x(t) on [0, T] and v = k (k v(t0) + 1 + x(t - T)) + 1 + x(t) on
    [T, 2T], with x = 0.1 (1 - exp(-t))."""
    T = 0.4
    t = np.linspace(0.0, 2 * T, 81)
    res = ac.simulate(LoopAtStart(k=k), t_end=2 * T, rtol=1e-10, t_eval=t)
    v0 = 1.0 / (1.0 - k)
    x = lambda s: 0.1 * (1.0 - np.exp(-s))          # noqa: E731
    exact = np.where(t <= T, k * v0 + 1 + x(t), k * (k * v0 + 1 + x(t - T)) + 1 + x(t))
    assert res["v"][0] == pytest.approx(v0, rel=1e-10)
    assert np.max(np.abs(res["v"] - exact)) < 1e-8 * np.max(np.abs(exact))


class DelayedRelay(ac.Component):
    """x' = -1 if x(t - T) > 0 else +1: a relation on a delayed value (state events)."""

    T = ac.Parameter(0.3, unit="s")
    x = ac.Variable(start=0.5, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), ac.if_else(ac.delay(self.x, self.T) > 0, -1.0, 1.0))]


def test_relay_on_a_delayed_value_is_the_exact_triangle_wave():
    """From x = 0.5 (and that history) x falls until T after it crosses 0 (t = 0.8,
    x = -T), then x is a triangle wave of amplitude T and period 4T: each switch comes T
    after a zero crossing.  Piecewise linear, so exact up to the event location."""
    res = ac.simulate(DelayedRelay(), t_end=4.0, rtol=1e-8)
    assert res.success
    T, t = 0.3, res.t
    tau = np.mod(t - 0.8, 4 * T)
    exact = np.where(t <= 0.8, 0.5 - t, np.where(tau <= 2 * T, -T + tau, 3 * T - tau))
    assert np.max(np.abs(res["x"] - exact)) < 1e-9 * T
    # a switch may fall on a discontinuity scheduled one delay after an event (a time
    # event) or be located as a crossing: count the events that changed the relation
    switches = [e.time for e in res.events if e.changes]
    assert np.allclose(switches, 0.8 + 2 * T * np.arange(len(switches)), rtol=1e-10)
    assert len(switches) == 6


def test_long_run_trims_the_history_and_records_the_delayed_values():
    """T = 0.05 over 20 s: the history keeps only the pieces of about two delays (plus
    a batch of 256 older ones, trimmed together), and the result, evaluated after the
    run, uses the values recorded at its points."""
    c = ac.compile(DelayedSine(delay={"delayTime": 0.05}))
    t = np.linspace(0.0, 20.0, 1001)
    res = ac.simulate(c, t_end=20.0, rtol=1e-6, t_eval=t)
    assert c.delays._kept_from > 10.0 and len(c.delays._starts) < 600
    exact = _shifted_sine(t, T=0.05)
    assert np.max(np.abs(res["delay.y.signal"] - exact)) < 1e-7 * 2.0


# -- typed errors -----------------------------------------------------------------------------
def test_negative_delay_time_is_refused():
    with pytest.raises(ac.InvalidEquation, match="delay time must be a positive"):
        ac.delay(ac.time, -1.0)
    with pytest.raises(ac.ModelError, match=r"delay\(x, T\).*positive"):
        ac.compile(DelayedDecay(T=-0.5), cache=False)
    compiled = ac.compile(DelayedDecay(), cache=False)
    compiled.set_parameters({"T": 0.0})
    with pytest.raises(ac.ModelError, match=r"delay\(x, T\).*must be positive"):
        ac.simulate(compiled, t_end=1.0)


def test_delay_time_must_be_a_parameter():
    class VariableDelay(ac.Component):
        x = ac.Variable(start=1.0, fixed=True)
        tau = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(self.tau, 1 + ac.time),
                    ac.Eq(ac.der(self.x), -ac.delay(self.x, self.tau))]

    with pytest.raises(ac.ModelError, match=r"delay\(x, tau\).*expression of parameters.*tau"):
        ac.compile(VariableDelay(), cache=False)


def test_differentiated_delay_is_refused():
    class ImposedPosition(ac.Component):
        """A delayed position imposed on a state: index reduction differentiates it."""
        x = ac.Variable(start=0.0)
        v = ac.Variable(start=0.0)

        def equations(self):
            return [ac.Eq(self.x, ac.delay(ac.sin(ac.time), 0.1)),
                    ac.Eq(ac.der(self.x), self.v)]

    with pytest.raises(ac.ModelError, match="index reduction must differentiate"):
        ac.compile(ImposedPosition(), cache=False)


def test_linearization_steady_state_sensitivities_energy_and_fmu_refuse_delays(tmp_path):
    with pytest.raises(ac.ModelError, match=r"no finite-dimensional linearization.*delay\("):
        ac.linearize(DelayedDecay(), [], ["x"])
    with pytest.raises(ac.ModelError, match=r"steady_state does not solve.*delay\(x, T\)"):
        ac.steady_state(DelayedDecay())
    from acausal.analysis.sensitivity import simulate_sensitivities
    compiled = ac.compile(DelayedDecay())
    with pytest.raises(ac.ModelError, match=r"sensitivities do not follow delay\(\).*delay\(x"):
        simulate_sensitivities(compiled, [compiled.param_names.index("a")], [0.0, 1.0])
    model = DelayedStep()
    with pytest.raises(ac.ModelError, match=r"energy audit does not evaluate delay\(\)"):
        ac.energy_balance(ac.simulate(model, t_end=1.0), model)
    pytest.importorskip("fmpy")
    from acausal.compiler.backends.cbackend import compiler_available
    if compiler_available() is None:
        pytest.skip("no C compiler")
    with pytest.raises(ac.ModelError, match=r"delay\(delay.u.signal, delay.delayTime\) in "
                                            r"delay \(FixedDelay\)"):
        ac.export_fmu(DelayedStep(), str(tmp_path / "m.fmu"))
