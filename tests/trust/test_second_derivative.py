"""der(der(x)) written in an equation: the nested derivative is the derivative of the
derivative variable, so x and der(x) become the states (Modelica allows it; tools
introduce the intermediate derivative as a variable).

The model is the undamped mass-spring m s'' = -k s, s(0) = 1, s'(0) = 0, whose exact
solution is s = cos(w t), w = sqrt(k/m).  It is written four ways: the second derivative
of a component's own variable; of its flange's position, which alias elimination merges
with the component's position (the path that used to leave der(der(flange.s)) undefined
and fail in code generation); of a variable that is the negative of the position (an
alias with a sign); and with an explicit velocity variable.  All four must give the
closed form on both backends, and the same trajectory as each other.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library.translational import Fixed, Spring
from acausal.library.translational.interfaces import PartialTwoFlanges

M, K = 2.0, 8.0
W = np.sqrt(K / M)
T_END = 5.0


class SecondOrder(ac.Component):
    """m der(der(s)) = -k s in one equation."""

    m = ac.Parameter(M, unit="kg")
    k = ac.Parameter(K, unit="N/m")
    s = ac.Variable(start=1.0, fixed=True, unit="m")

    def equations(self):
        return [ac.Eq(self.m * ac.der(ac.der(self.s)), -self.k * self.s)]


class FlangeMass(PartialTwoFlanges):
    """A sliding mass written with the second derivative of its flange's position, and
    its velocity v = der(s) as an output (s and flange_a.s are aliases, both
    differentiated, the alias twice)."""

    m = ac.Parameter(1.0, unit="kg")
    s = ac.Variable(start=1.0, fixed=True, unit="m")
    v = ac.Variable(unit="m/s")

    def equations(self):
        return [ac.Eq(self.s, self.flange_a.s), ac.Eq(self.s, self.flange_b.s),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.m * ac.der(ac.der(self.flange_a.s)),
                      self.flange_a.f + self.flange_b.f)]


class Oscillator(ac.Component):
    """Fixed -- spring -- mass."""

    fixed = Fixed()
    spring = Spring(c=K)
    mass = FlangeMass(m=M)

    def equations(self):
        return [ac.connect(self.fixed.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass.flange_a)]


class Mirrored(ac.Component):
    """q = -s, the second derivative written of q and the velocity of s."""

    m = ac.Parameter(M, unit="kg")
    k = ac.Parameter(K, unit="N/m")
    s = ac.Variable(start=1.0, fixed=True, unit="m")
    q = ac.Variable(unit="m")
    v = ac.Variable(unit="m/s")

    def equations(self):
        return [ac.Eq(self.q, -self.s), ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.m * ac.der(ac.der(self.q)), -self.k * self.q)]


class WithVelocity(ac.Component):
    """The same oscillator with v = der(s) written out."""

    m = ac.Parameter(M, unit="kg")
    k = ac.Parameter(K, unit="N/m")
    s = ac.Variable(start=1.0, fixed=True, unit="m")
    v = ac.Variable(start=0.0, fixed=True, unit="m/s")

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.s)), ac.Eq(self.m * ac.der(self.v), -self.k * self.s)]


CASES = [(SecondOrder, "s"), (Oscillator, "mass.s"), (Mirrored, "s"), (WithVelocity, "s")]
T = np.linspace(0.0, T_END, 201)


def _position(cls, name, backend):
    res = ac.simulate(cls(), T_END, t_eval=T, rtol=1e-9, backend=backend)
    assert res.success
    return res[name]


@pytest.mark.parametrize("backend", ["numpy", "c"])
@pytest.mark.parametrize("cls, name", CASES, ids=[c.__name__ for c, _ in CASES])
def test_mass_spring_matches_cosine(cls, name, backend):
    s = _position(cls, name, backend)
    # relative to the amplitude 1 of the signal, over 3 periods
    assert np.max(np.abs(s - np.cos(W * T))) < 1e-6


@pytest.mark.parametrize("cls, name", [(Oscillator, "mass.v"), (Mirrored, "v")])
def test_velocity_output_matches_sine(cls, name):
    res = ac.simulate(cls(), T_END, t_eval=T, rtol=1e-9, backend="numpy")
    # v = -w sin(w t), relative to its amplitude w
    assert np.max(np.abs(res[name] + W * np.sin(W * T))) < 1e-6 * W


def test_nested_derivative_and_velocity_form_agree():
    ref = _position(WithVelocity, "s", "numpy")
    for cls, name in CASES[:3]:
        assert np.max(np.abs(_position(cls, name, "numpy") - ref)) < 1e-6


@pytest.mark.parametrize("cls", [SecondOrder, Oscillator, Mirrored])
def test_position_and_velocity_are_the_states(cls):
    # two states: the position (or its alias) and its first derivative
    states = ac.compile(cls(), backend="numpy").states
    assert len(states) == 2, states
    assert sum(name.startswith("der(") for name in states) == 1, states


class FixedSecondDerivative(ac.Component):
    """A mass whose flange is held fixed: der(der(flange.s)) is the derivative of a
    constant, 0, so the fixed flange carries no force."""

    fixed = Fixed()
    mass = FlangeMass(m=M, s={"start": 0.0, "fixed": False})

    def equations(self):
        return [ac.connect(self.fixed.flange, self.mass.flange_a)]


def test_second_derivative_of_a_constant_is_zero():
    res = ac.simulate(FixedSecondDerivative(), 2.0, t_eval=np.linspace(0, 2, 21),
                      backend="numpy")
    # m * 0 = flange_a.f + flange_b.f with flange_b free (flange_b.f = 0)
    assert np.max(np.abs(res["mass.flange_a.f"])) < 1e-9


class PendulumSecondOrder(ac.Component):
    """The index-3 planar pendulum (DAE notes' Cartesian pendulum) with the second
    derivatives written directly: m x'' = -x lam, m y'' = -y lam - m g, x^2 + y^2 = L^2."""

    m = ac.Parameter(1.0, unit="kg")
    g = ac.Parameter(9.81, unit="m/s2")
    L = ac.Parameter(1.0, unit="m")
    x = ac.Variable(start=0.6, fixed=True, unit="m")
    y = ac.Variable(start=-0.8, unit="m")
    lam = ac.Variable(unit="N/m")

    def equations(self):
        return [ac.Eq(self.m * ac.der(ac.der(self.x)), -self.x * self.lam),
                ac.Eq(self.m * ac.der(ac.der(self.y)), -self.y * self.lam - self.m * self.g),
                ac.Eq(self.x**2 + self.y**2, self.L**2)]


@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_index_three_pendulum_written_with_second_derivatives(backend):
    from scipy.integrate import solve_ivp
    # the same pendulum in its angle, theta'' = -(g/L) sin(theta), released at rest
    # from theta0 = atan2(0.6, 0.8): x = L sin(theta), y = -L cos(theta)
    th0 = np.arctan2(0.6, 0.8)
    tt = np.linspace(0.0, 2.0, 41)
    ref = solve_ivp(lambda t, u: [u[1], -9.81 * np.sin(u[0])], (0.0, 2.0), [th0, 0.0],
                    method="DOP853", rtol=1e-11, atol=1e-12, t_eval=tt)
    res = ac.simulate(PendulumSecondOrder(), 2.0, t_eval=tt, rtol=1e-9, backend=backend)
    assert res.success
    assert np.max(np.abs(res["x"] - np.sin(ref.y[0]))) < 1e-6
    assert np.max(np.abs(res["y"] + np.cos(ref.y[0]))) < 1e-6
