"""The wheelset of the DAE notes, chapter 5 (INVENTORY MB-16), in its linearized
lateral/yaw form: the contact geometry against a Newton solution of the notes' contact
constraints (5.4.1), the stability statements of section 5.9 (V = 100 m/s, k_s = 1.823
MN/m: delta = 0.05 stable, 0.08 unstable; V = 20 m/s unsuspended, delta = 0.05:
unstable but flange-limited) by the eigenvalues of ac.linearize and a simulation, and
Klingel's kinematic wavelength in the creep-free limit; then the notes' own index-3
contact DAE (WheelsetDAE): its index, its consistent initialization against a Newton
solution of (5.4.1), and its linearization against the small-motion model.
"""
import types

import numpy as np
import pytest
from scipy.signal import find_peaks

import acausal as ac
from acausal.library.multibody3d.examples.wheelset import (SuspendedWheelset,
                                                          UnsuspendedWheelset,
                                                          UnsuspendedWheelsetDAE)
from acausal.library.multibody3d.wheelset import Wheelset
from acausal.library.multibody3d.wheelset_dae import WheelsetDAE


def _parameters(**values):
    """The declared parameters of Wheelset evaluated in numbers, derived ones too."""
    ns = types.SimpleNamespace()
    for name, decl in vars(Wheelset).items():
        if isinstance(decl, ac.Parameter):
            value = values.get(name, decl.value)
            setattr(ns, name, float(value(ns) if callable(value) else value))
    return ns


def _contact(delta, y):
    """z, phi, s11, s21, s12, s32 from C(q, s) = 0 (5.4.1), the profiles of section
    5.2, by Newton from the notes' guess (section 5.7)."""
    p = _parameters(delta=delta)
    t, R = np.tan(delta), p.R

    def C(x):
        z, phi, s11, s21, s12, s32 = x
        A = np.array([[np.cos(phi), -np.sin(phi)], [np.sin(phi), np.cos(phi)]])
        R1 = np.array([y, p.r_0 + z])
        u11, u12 = np.array([p.y_0 + s11, -p.r_0 + s11 * t]), \
            np.array([-p.y_0 + s12, -p.r_0 - s12 * t])
        u21 = np.array([p.y_rail - R * np.sin(s21), R * (np.cos(s21) - 1)])
        u32 = np.array([-p.y_rail - R * np.sin(s32), R * (np.cos(s32) - 1)])
        t11, t12 = np.array([1.0, t]), np.array([1.0, -t])
        n21 = np.array([np.sin(s21), -np.cos(s21)])       # normal of the rail profiles
        n32 = np.array([np.sin(s32), -np.cos(s32)])
        return [*(R1 + A @ u11 - u21), *(R1 + A @ u12 - u32), n21 @ A @ t11, n32 @ A @ t12]

    guess = [0.0, 0.0, (p.y_rail - p.y_0) - R * np.sin(delta), delta,
             (-p.y_rail + p.y_0) + R * np.sin(delta), -delta]
    x = np.array(guess)
    for _ in range(8):                                     # Newton, as in section 5.7
        J = np.column_stack([(np.subtract(C(x + dx), C(x - dx))) / 2e-7
                             for dx in np.eye(6) * 1e-7])
        x = x - np.linalg.solve(J, C(x))
    assert np.abs(C(x)).max() < 1e-11     # converged (metres and cosines of order 1)
    return x, p


@pytest.mark.parametrize("delta", [0.05, 0.08])
def test_linear_contact_geometry_against_the_constraints_5_4_1(delta):
    (_, phi0, s11, s21, s12, s32), p = _contact(delta, 0.0)
    assert phi0 == pytest.approx(0.0, abs=1e-12)
    assert s11 == pytest.approx(p.s_0, rel=1e-10) and s12 == pytest.approx(-p.s_0, rel=1e-10)
    assert s21 == pytest.approx(delta, rel=1e-10)          # s21 = delta + phi (section 5.9)
    h = 1e-5
    (_, phi_p, s11_p, _, s12_p, _), _ = _contact(delta, h)
    (_, phi_m, s11_m, _, s12_m, _), _ = _contact(delta, -h)
    assert (phi_p - phi_m) / (2 * h) == pytest.approx(p.sigma, rel=1e-7)
    # rolling radii r_l = r_0 - s11 tan(delta), r_r = r_0 + s12 tan(delta)
    t = np.tan(delta)
    r_diff = lambda s11, s12: (-s11 * t) - (s12 * t)               # noqa: E731
    slope = (r_diff(s11_p, s12_p) - r_diff(s11_m, s12_m)) / (2 * h)
    assert slope / 2 == pytest.approx(p.lambda_e, rel=1e-7)


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(Wheelset())


@pytest.mark.parametrize("delta, V, k_s, stable", [
    (0.05, 100.0, 1.823e6, True),        # Figure 5.4
    (0.08, 100.0, 1.823e6, False),       # Figure 5.5
    (0.05, 20.0, 1.0, False),            # Figure 5.3 (unsuspended: k_s -> 0)
])
def test_stability_statements_of_section_5_9(compiled, delta, V, k_s, stable):
    poles = ac.linearize(compiled, at={"delta": delta, "V": V, "k_s": k_s}).poles()
    hunting = poles[np.argmax(poles.real)]
    assert abs(hunting.imag) > 1.0                        # the oscillation is the hunting
    assert (hunting.real < 0) == stable
    assert abs(hunting.real) > 1e-3 * abs(hunting)         # not a marginal call


def _peak_rate(t, y):
    """The growth rate of |y| from its successive peaks (median over the peaks)."""
    peaks, _ = find_peaks(np.abs(y))
    return np.median(np.diff(np.log(np.abs(y[peaks]))) / np.diff(t[peaks]))


def test_unsuspended_hunting_is_limited_by_the_flange(compiled):
    """V = 20 m/s, k_s = 0, delta = 0.05 (Figure 5.3): the oscillation grows at the
    rate of the linearization until the flange (dead band y_f) holds it on a limit
    cycle just past y_f."""
    growth = ac.linearize(compiled, at={"V": 20.0, "k_s": 1.0}).poles().real.max()
    res = ac.simulate(UnsuspendedWheelset(), UnsuspendedWheelset.stop_time, rtol=1e-8)
    assert res.success
    y, t, y_f = res["wheelset.y"], res.t, _parameters().y_f
    free = (t > 1.0) & (t < 7.0)                           # |y| < y_f: linear
    assert np.abs(y[free]).max() < y_f
    assert _peak_rate(t[free], y[free]) == pytest.approx(growth, rel=0.02)
    late = t > 14.0
    amplitude = np.abs(y[late]).max()
    assert y_f < amplitude < 1.1 * y_f
    assert np.abs(res["wheelset.F_flange"][late]).max() > 0


def test_suspended_wheelset_returns_at_the_rate_of_its_linearization():
    """V = 100 m/s, k_s = 1.823 MN/m, delta = 0.05 (Figure 5.4): the hunting decays,
    never reaching the flange, at the rate of the least damped eigenvalue."""
    model = SuspendedWheelset()
    decay = ac.linearize(model).poles().real.max()
    res = ac.simulate(model, SuspendedWheelset.stop_time, rtol=1e-9, n_points=4001)
    y, t = res["wheelset.y"], res.t
    assert np.abs(y).max() < _parameters().y_f
    tail = t > 0.5                                         # the fast mode has died out
    assert _peak_rate(t[tail], y[tail]) == pytest.approx(decay, rel=0.02)


def test_klingel_wavelength_in_the_creep_free_limit():
    """Creep coefficients 1e6 times larger, no suspension, no spin creep, knife-edge
    geometry (lambda_e = conicity, no roll): the hunting is Klingel's kinematic sine of
    wavelength L = 2 pi sqrt(r_0 e / lambda), neither growing nor decaying."""
    V, lam, e, r_0 = 20.0, 0.05, 0.75, 0.46
    model = Wheelset(V=V, k_s=0.0, sigma=0.0, lambda_e=lam, e=e, C_23=0.0, G=8.27e16)
    poles = ac.linearize(model).poles()
    slow = poles[np.argmin(np.abs(poles))]
    assert 2 * np.pi * V / abs(slow.imag) == pytest.approx(
        2 * np.pi * np.sqrt(r_0 * e / lam), rel=1e-9)
    assert abs(slow.real) < 1e-6 * abs(slow.imag)


def test_kinematic_limit_with_the_notes_geometry():
    """The same limit with the roll and effective conicity of the notes' profiles:
    y' (1 + r_0 sigma) = V psi, psi' = -V lambda_e y / (e r_0)."""
    V, delta = 20.0, 0.05
    p = _parameters(delta=delta)
    model = Wheelset(V=V, delta=delta, k_s=0.0, C_23=0.0, G=8.27e16)
    poles = ac.linearize(model).poles()
    slow = poles[np.argmin(np.abs(poles))]
    omega = V * np.sqrt(p.lambda_e / (p.e * p.r_0 * (1 + p.r_0 * p.sigma)))
    assert abs(slow.imag) == pytest.approx(omega, rel=1e-8)


# -- the notes' own formulation: the index-3 contact DAE ---------------------------------
def _centred(delta, V):
    """The centred running state: s12 = -s_0, and the spin perturbation beta that
    cancels the longitudinal creepage s_0 tan(delta) / r_0 of both wheels."""
    p = _parameters(delta=delta)
    t = np.tan(delta)
    return {"s[2]": -p.s_0, "dq[0]": 0.0,
            "beta": V * p.s_0 * t / (p.r_0 * (p.r_0 - p.s_0 * t))}


@pytest.fixture(scope="module")
def dae():
    return ac.compile(WheelsetDAE())


def test_the_contact_dae_is_index_3_as_the_notes_state(dae):
    assert dae.report.differential_index == 3               # section 5.5


def test_consistent_initialization_solves_the_contact_constraints(dae):
    """From y = 1 mm and the start guesses, the compiled model's initialization finds
    z, phi and s on the constraint manifold (5.4.1), as the notes' Newton does (5.7)."""
    res = ac.simulate(dae, 0.2, rtol=1e-8)
    assert res.success
    (z, phi, s11, s21, s12, s32), _ = _contact(0.05, 0.001)
    got = [res[n][0] for n in ("q[1]", "q[2]", "s[0]", "s[1]", "s[2]", "s[3]")]
    np.testing.assert_allclose(got, [z, phi, s11, s21, s12, s32], rtol=1e-9, atol=1e-12)
    # and the constraints hold along the run (no drift of the index reduction)
    for k in (len(res.t) // 2, -1):
        exact, _ = _contact(0.05, res["q[0]"][k])
        got = [res[n][k] for n in ("q[1]", "q[2]", "s[0]", "s[1]", "s[2]", "s[3]")]
        np.testing.assert_allclose(got, exact, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("delta, V, k_s, stable", [
    (0.05, 100.0, 1.823e6, True), (0.08, 100.0, 1.823e6, False), (0.05, 20.0, 1.0, False)])
def test_contact_dae_linearized_agrees_with_the_small_motion_model(dae, delta, V, k_s,
                                                                  stable):
    """The notes' statements again, now from their own DAE (index reduced by the
    compiler, nonlinear creep law), and its hunting frequency against the linear
    model's: they differ by the second-order terms the latter leaves out (the creep
    law's slope at the spin creepage of the centred state, load transfer), measured
    below 1 % in frequency."""
    at = {**_centred(delta, V), "delta": delta, "V": V, "k_s": k_s}
    poles = ac.linearize(dae, at=at).poles()
    hunting = poles[np.argmax(poles.real)]
    assert (hunting.real < 0) == stable and abs(hunting.imag) > 1.0
    small = ac.linearize(Wheelset(delta=delta, V=V, k_s=k_s)).poles()
    assert abs(hunting.imag) == pytest.approx(np.abs(small.imag[np.argmax(small.real)]),
                                              rel=0.02)


def test_contact_dae_hunting_is_limited_by_the_flange():
    """Figure 5.3 in the notes' own formulation: the unsuspended wheelset at 20 m/s
    hunts onto the flange; its limit cycle has the small-motion model's amplitude
    (the same flange and clearance; measured 9.429 against 9.437 mm)."""
    res = ac.simulate(UnsuspendedWheelsetDAE(), UnsuspendedWheelsetDAE.stop_time,
                      rtol=1e-6)
    assert res.success
    small = ac.simulate(UnsuspendedWheelset(), UnsuspendedWheelset.stop_time, rtol=1e-8)
    y_f = _parameters().y_f
    amplitude = np.abs(res["wheelset.q[0]"][res.t > 10.0]).max()
    assert y_f < amplitude < 1.1 * y_f
    assert amplitude == pytest.approx(np.abs(small["wheelset.y"][small.t > 14.0]).max(),
                                      rel=0.01)
