"""Gas components (Egeland & Gravdahl 14.1.2, 14.4.5, 14.5.9) against closed forms,
hand linearizations and scipy's solve_ivp on the hand-written equations."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

import acausal as ac
from acausal.library.gas.examples import moore_greitzer as mg

H, W, PSI_C0, SIGMA, GAMMA_T, L_C = mg.H, mg.W, mg.PSI_C0, mg.SIGMA, mg.GAMMA_T, mg.L_C


# -- Moore-Greitzer (14.1)-(14.3), written by hand -------------------------------------------
def _mg3(t, x, B):
    Psi, Phi, J = x
    m = Phi / W - 1
    return [(Phi - GAMMA_T * np.sqrt(Psi)) / (4 * L_C * B**2),
            H / L_C * (-(Psi - PSI_C0) / H + 1 + 1.5 * m * (1 - J / 2) - 0.5 * m**3),
            J * (1 - m**2 - J / 4) * SIGMA]


def _mg3_jacobian(x, B):
    Psi, Phi, J = x
    m = Phi / W - 1
    return np.array([
        [-GAMMA_T / (2 * np.sqrt(Psi)) / (4 * L_C * B**2), 1 / (4 * L_C * B**2), 0],
        [-1 / L_C, H / L_C * (1.5 * (1 - J / 2) - 1.5 * m**2) / W, -H / L_C * 0.75 * m],
        [0, -2 * SIGMA * J * m / W, SIGMA * (1 - m**2 - J / 2)]])


def _stall_closed_form():
    """The stall equilibrium: J = 4 (1 - m^2) from (14.3), then (14.2) gives
    Psi = psi_c0 + H (1 - 3m/2 + 5m^3/2), and the throttle W (1 + m) = gamma_T sqrt(Psi):
    a cubic in m = Phi/W - 1, with one root in (-1, 1) for these data."""
    g2 = GAMMA_T**2
    roots = np.roots([2.5 * H * g2, -W**2, -(1.5 * H * g2 + 2 * W**2), g2 * (PSI_C0 + H) - W**2])
    m = [r.real for r in roots if abs(r.imag) < 1e-12 and -1 < r.real < 1]
    assert len(m) == 1
    m = m[0]
    return np.array([PSI_C0 + H * (1 - 1.5 * m + 2.5 * m**3), W * (1 + m), 4 * (1 - m**2)])


def test_stall_equilibrium_closed_form_and_root_finder_agree():
    closed = _stall_closed_form()
    sol = root(lambda x: _mg3(0.0, x, 0.1), [0.4, 0.3, 3.5], method="hybr", tol=1e-13)
    # a residual of the O(1) right-hand side: converged, with room for another BLAS
    assert sol.success and np.max(np.abs(_mg3(0.0, sol.x, 0.1))) < 1e-11
    assert np.allclose(sol.x, closed, rtol=1e-12, atol=0)
    # INVENTORY TF-08 (scipy LSODA, t = 500): Psi 0.4133, Phi 0.3215, J 3.673
    assert np.allclose(closed, [0.4133, 0.3215, 3.673], atol=6e-4)


@pytest.fixture(scope="module")
def stall():
    return ac.simulate(mg.RotatingStall(), t_end=mg.RotatingStall.stop_time, rtol=1e-8,
                       raise_on_failure=True)


def test_rotating_stall_settles_at_the_closed_form_equilibrium(stall):
    """B = 0.1: the component model falls into rotating stall, J > 0 (Figure 14.2)."""
    closed = _stall_closed_form()
    end = np.array([stall["plenum.psi"][-1], stall["compressor.phi"][-1],
                    stall["compressor.J"][-1]])
    assert np.allclose(end, closed, rtol=1e-6, atol=0)
    op = ac.steady_state(ac.compile(mg.RotatingStall()), guess={
        "plenum.psi": 0.4, "compressor.phi": 0.3, "compressor.J": 3.5})
    assert np.allclose([op["plenum.psi"], op["compressor.phi"], op["compressor.J"]], closed,
                       rtol=1e-9, atol=0)


def test_rotating_stall_transient_follows_dop853(stall):
    """The fall into stall (Figure 14.2) against DOP853 at rtol 1e-10 on (14.1)-(14.3)."""
    ref = solve_ivp(_mg3, (0.0, stall.t[-1]), [0.6, 0.6, 0.1], args=(0.1,), method="DOP853",
                    rtol=1e-10, atol=1e-12, t_eval=stall.t)
    for name, row in (("plenum.psi", 0), ("compressor.phi", 1), ("compressor.J", 2)):
        err = np.max(np.abs(stall[name] - ref.y[row]))
        assert err < 2e-6 * np.ptp(ref.y[row]), (name, err)


def test_rotating_stall_linearization_is_the_hand_jacobian():
    closed = _stall_closed_form()
    sys = ac.linearize(mg.RotatingStall(), at={"plenum.psi": closed[0],
                                               "compressor.phi": closed[1],
                                               "compressor.J": closed[2]})
    hand = np.linalg.eigvals(_mg3_jacobian(closed, 0.1))
    poles = sys.poles()
    assert len(poles) == 3
    assert max(np.min(np.abs(poles - lam)) for lam in hand) < 1e-8 * np.max(np.abs(hand))
    assert np.all(hand.real < 0)                # the stall point attracts


def _design_point():
    """The axisymmetric equilibrium, J = 0: W (1 + m) = gamma_T sqrt(psi_c(Phi, 0)), a
    cubic in m = Phi/W - 1 with one real root for these data."""
    g2 = GAMMA_T**2
    roots = np.roots([0.5 * H * g2, W**2, 2 * W**2 - 1.5 * H * g2, W**2 - g2 * (PSI_C0 + H)])
    m = [r.real for r in roots if abs(r.imag) < 1e-12]
    assert len(m) == 1
    m = m[0]
    return np.array([PSI_C0 + H * (1 + 1.5 * m - 0.5 * m**3), W * (1 + m), 0.0])


@pytest.mark.parametrize("model, B", [(mg.RotatingStall, 0.1), (mg.Surge, 1.0)])
def test_design_point_is_unstable_the_way_b_says(model, B):
    """Linearized at the J = 0 equilibrium (on the rising part of the characteristic):
    the stall mode sigma (1 - m^2) grows for either B; the surge mode (Psi, Phi) is
    damped for B = 0.1 and grows for B = 1 -- rotating stall and surge."""
    x = _design_point()
    assert max(abs(v) for v in _mg3(0.0, x, B)) < 1e-12          # an equilibrium (O(1) terms)
    sys = ac.linearize(model(), at={"plenum.psi": x[0], "compressor.phi": x[1],
                                    "compressor.J": 0.0})
    hand = np.linalg.eigvals(_mg3_jacobian(x, B))
    poles = sys.poles()
    assert len(poles) == 3
    assert max(np.min(np.abs(poles - lam)) for lam in hand) < 1e-8 * np.max(np.abs(hand))
    stall = SIGMA * (1 - (x[1] / W - 1)**2)
    assert np.min(np.abs(poles - stall)) < 1e-8 * stall
    surge_modes = poles[np.abs(poles.imag) > 0]
    assert len(surge_modes) == 2
    assert (surge_modes.real > 0).all() == (B == 1.0)
    assert (surge_modes.real < 0).all() == (B == 0.1)


@pytest.fixture(scope="module")
def surge():
    return ac.simulate(mg.Surge(), t_end=mg.Surge.stop_time, rtol=1e-10, n_points=6001,
                       raise_on_failure=True)


def test_surge_follows_dop853(surge):
    """B = 1 against DOP853 at rtol 1e-10 on (14.1)-(14.3), over the first four surge
    cycles (the phase error of any integrator grows along a limit cycle)."""
    t = surge.t[surge.t <= 130.0]
    ref = solve_ivp(_mg3, (0.0, t[-1]), [0.6, 0.6, 0.1], args=(1.0,), method="DOP853",
                    rtol=1e-10, atol=1e-12, t_eval=t)
    k = t.size
    for name, row in (("plenum.psi", 0), ("compressor.phi", 1)):
        err = np.max(np.abs(surge[name][:k] - ref.y[row]))
        assert err < 1e-6 * np.ptp(ref.y[row]), (name, err)
    J_err = np.max(np.abs(surge["compressor.J"][:k] - ref.y[2]))
    assert J_err < 1e-6 * np.max(ref.y[2])


def _upward_crossings(t, y):
    level = (y.max() + y.min()) / 2
    i = np.where((y[:-1] < level) & (y[1:] >= level))[0]
    return t[i] + (level - y[i]) / (y[i + 1] - y[i]) * (t[i + 1] - t[i])


def test_surge_is_a_limit_cycle_without_stall(surge):
    """B = 1 surges (Figure 14.3): late in the run Phi and Psi repeat with one period,
    the flow reverses, and the stall amplitude has died out."""
    late = surge.t >= 150.0
    t, phi, psi = surge.t[late], surge["compressor.phi"][late], surge["plenum.psi"][late]
    periods = np.diff(_upward_crossings(t, phi))
    assert len(periods) >= 3
    T = periods.mean()
    assert np.ptp(periods) < 1e-3 * T
    # one period later the state is where it was (interpolated on the output grid)
    for y in (phi, psi):
        again = np.interp(t[t < t[-1] - T] + T, t, y)
        assert np.max(np.abs(again - y[t < t[-1] - T])) < 5e-3 * np.ptp(y)
    # the period of the hand-written equations' cycle
    ref = solve_ivp(_mg3, (0.0, 300.0), [0.6, 0.6, 0.1], args=(1.0,), method="DOP853",
                    rtol=1e-10, atol=1e-12, dense_output=True)
    tr = np.linspace(150.0, 300.0, 15001)
    T_ref = np.diff(_upward_crossings(tr, ref.sol(tr)[1])).mean()
    assert T == pytest.approx(T_ref, rel=1e-4)
    assert phi.min() < -0.15 and phi.max() > 0.7         # deep surge, reverse flow
    assert 0.15 < psi.min() and psi.max() < 0.75
    assert np.max(np.abs(surge["compressor.J"][late])) < 1e-12


def test_energy_audit_refuses_gas_ports():
    """p m_flow (or psi phi) is not a power: the audit says so instead of booking it."""
    model = mg.Surge()
    res = ac.simulate(model, t_end=1.0)
    with pytest.raises(ValueError, match="not a power"):
        ac.energy_balance(res, model)


# -- the pneumatic spring (14.97)-(14.107), (14.144)-(14.150) --------------------------------
from acausal.library.gas.examples import pneumatic_spring as ps  # noqa: E402


@pytest.mark.parametrize("x_star", [0.5, 1.0, 2.0])
def test_pneumatic_spring_frequency_is_14_104(x_star):
    """The chamber at p = p_0 x*^-kappa (the isentrope of (14.98)): with the pressure a
    state the Jacobian is [[0, 1, 0], [0, 0, A/m], [0, -kappa p/x, 0]] at v = 0, whose
    eigenvalues are 0 (the gas mass) and +-j omega_0, omega_0^2 = g kappa x*^-(kappa+1)
    (14.104): 8.60, 3.74, 1.63 rad/s; the printed table (14.105) has 4.3, 3.7, 3.3, of
    which only 3.7 agrees with (14.104) (INVENTORY 0.4)."""
    sys = ac.linearize(ps.PneumaticSpring(), at={
        "load.s": x_star, "load.v": 0.0, "cylinder.p": ps.P_0 * x_star**-ps.KAPPA})
    omega_0 = np.sqrt(ps.G * ps.KAPPA * x_star**-(ps.KAPPA + 1))
    poles = sys.poles()
    assert len(poles) == 3
    assert np.sort(np.abs(poles.imag))[-1] == pytest.approx(omega_0, rel=1e-9)
    assert np.max(np.abs(poles.real)) < 1e-9 * omega_0
    assert np.min(np.abs(poles)) < 1e-9 * omega_0
    if x_star == 1.0:
        assert round(omega_0, 1) == 3.7


def test_two_mass_pneumatic_spring_eigenvalues():
    """(14.149)-(14.150): +-j3.7 and +-j1000 at x_1* = 1, x_2* = 1 - m_2 g/K (printed
    "1 - m_2/K", INVENTORY 0.4), against the hand linearization of the five states
    (x_1, v_1, x_2, v_2, p) and the 4x4 one of (14.146) with p eliminated."""
    x2_star = 1 - ps.M_2 * ps.G / ps.K
    sys = ac.linearize(ps.TwoMassPneumaticSpring(), at={
        "mass_1.s": 1.0, "mass_1.v": 0.0, "mass_2.s": x2_star, "mass_2.v": 0.0,
        "cylinder.p": ps.P_0})
    m1, m2, K, A, p0, kappa = ps.M_1, ps.M_2, ps.K, ps.A, ps.P_0, ps.KAPPA
    hand = np.array([[0, 1, 0, 0, 0],
                     [-K / m1, 0, K / m1, 0, A / m1],
                     [0, 0, 0, 1, 0],
                     [K / m2, 0, -K / m2, 0, 0],
                     [0, -kappa * p0 / 1.0, 0, 0, 0]])
    lam_hand = np.linalg.eigvals(hand)
    poles = sys.poles()
    scale = ps.OMEGA_2
    assert len(poles) == 5
    # every hand eigenvalue has a pole next to it (sort_complex orders by the real
    # parts, which are round-off here)
    assert max(np.min(np.abs(poles - lam))
               for lam in lam_hand) < 1e-9 * scale
    # (14.146) with x_1^-kappa: stiffness g (m/m_1) kappa + K/m_1 on x_1
    stiffness = np.array([[(ps.G * kappa * ps.M + K) / m1, -K / m1], [-K / m2, K / m2]])
    omegas = np.sort(np.sqrt(np.linalg.eigvals(stiffness).real))
    fast_and_slow = np.sort(np.abs(poles.imag))[[1, 3]]
    assert np.allclose(fast_and_slow, omegas, rtol=1e-9)
    assert round(omegas[0], 1) == 3.7 and abs(omegas[1] - 1000.0) < 0.5


def test_pneumatic_spring_follows_14_100_and_keeps_its_energy():
    """The component model against DOP853 on x'' = -g (1 - x^-kappa) (14.100); along the
    run the closed chamber stays on its isentrope p = p_0 x^-kappa (14.98), and the
    energy p V/(kappa - 1) + m g x + m v^2/2 (14.106) is kept."""
    res = ac.simulate(ps.PneumaticSpring(), t_end=ps.PneumaticSpring.stop_time, rtol=1e-11,
                      n_points=501, raise_on_failure=True)
    ref = solve_ivp(lambda t, s: [s[1], -ps.G * (1 - s[0]**-ps.KAPPA)], (0.0, res.t[-1]),
                    [ps.X_START, 0.0], method="DOP853", rtol=1e-11, atol=1e-13, t_eval=res.t)
    x, v, p = res["load.s"], res["load.v"], res["cylinder.p"]
    assert np.max(np.abs(x - ref.y[0])) < 1e-6 * np.ptp(ref.y[0])
    assert np.max(np.abs(p - ps.P_0 * x**-ps.KAPPA)) < 1e-7 * np.ptp(p)
    E = p * ps.A * x / (ps.KAPPA - 1) + ps.M * ps.G * x + ps.M * v**2 / 2
    E_min = ps.P_0 * ps.A / (ps.KAPPA - 1) + ps.M * ps.G
    assert E_min == pytest.approx(7000.0, rel=1e-12)       # (14.107)
    assert np.max(np.abs(E - E[0])) < 1e-6 * (E[0] - E_min)


def test_two_mass_pneumatic_spring_follows_14_144():
    res = ac.simulate(ps.TwoMassPneumaticSpring(), t_end=0.1, rtol=1e-9, n_points=201,
                      raise_on_failure=True)
    g, k, m1, m2 = ps.G, ps.K, ps.M_1, ps.M_2

    def rhs(t, s):
        x1, v1, x2, v2 = s
        return [v1, -g * (1 - ps.M / m1 * x1**-ps.KAPPA) - k / m1 * (x1 - x2),
                v2, -g - k / m2 * (x2 - x1)]
    x2_0 = ps.X_START - m2 * g / k + 1e-4
    ref = solve_ivp(rhs, (0.0, 0.1), [ps.X_START, 0.0, x2_0, 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-14, t_eval=res.t)
    assert np.max(np.abs(res["mass_1.s"] - ref.y[0])) < 1e-6 * np.ptp(ref.y[0])
    stretch, stretch_ref = res["mass_1.s"] - res["mass_2.s"], ref.y[0] - ref.y[2]
    assert np.max(np.abs(stretch - stretch_ref)) < 1e-3 * np.ptp(stretch_ref)


# -- volumes, throttles and sources against closed forms -------------------------------------
from acausal.library import gas  # noqa: E402

R_T = 1e5 / 1.2          # p_0/rho_0 of the default polytrope: R T of the isothermal gas


class _Filling(ac.Component):
    """An adiabatic receiver filled at a constant mass flow."""

    source = gas.ConstantMassFlow(m_flow=2e-3)
    tank = gas.GasVolume(V=1e-2, n=1.4, p={"start": 1e5, "fixed": True})

    def equations(self):
        return [ac.connect(self.source.port, self.tank.port)]


def test_adiabatic_filling_follows_the_isentrope():
    """Mass balance m = m_0 + m_flow t and p = p_0 (m/(rho_0 V))^kappa (14.98)."""
    res = ac.simulate(_Filling(), t_end=5.0, rtol=1e-10, n_points=101, raise_on_failure=True)
    m = 1.2 * 1e-2 + 2e-3 * res.t
    p = 1e5 * (m / (1.2 * 1e-2))**1.4
    assert np.max(np.abs(res["tank.p"] - p)) < 1e-8 * np.ptp(p)
    assert np.max(np.abs(res["tank.m"] - m)) < 1e-8 * np.ptp(m)


class _Charging(ac.Component):
    """An isothermal receiver charged from a supply through a throttle."""

    supply = gas.FixedPressure(p=6e5)
    valve = gas.Throttle(A=1e-6, rho=6.0)
    tank = gas.GasVolume(V=1e-3, n=1.0, p={"start": 1e5, "fixed": True})

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.tank.port)]


def test_isothermal_charging_through_a_throttle():
    """u = p_s - p obeys u' = -k sqrt(u), k = R T C_d A sqrt(2 rho)/V, so
    sqrt(u) = sqrt(u_0) - k t/2 until the tank is full."""
    k = R_T * 0.6 * 1e-6 * np.sqrt(2 * 6.0) / 1e-3
    t_full = 2 * np.sqrt(5e5) / k
    res = ac.simulate(_Charging(), t_end=0.8 * t_full, rtol=1e-10, n_points=101,
                      raise_on_failure=True)
    u = (np.sqrt(5e5) - k * res.t / 2)**2
    assert np.max(np.abs(6e5 - res["tank.p"] - u)) < 1e-7 * 5e5


class _Equalizing(ac.Component):
    """Two isothermal volumes joined by a laminar restriction."""

    a = gas.GasVolume(V=1e-3, n=1.0, p={"start": 3e5, "fixed": True})
    link = gas.LaminarThrottle(G=1e-9)
    b = gas.GasVolume(V=3e-3, n=1.0, p={"start": 1e5, "fixed": True})

    def equations(self):
        return [ac.connect(self.a.port, self.link.port_a),
                ac.connect(self.link.port_b, self.b.port)]


def test_laminar_equalization_conserves_mass():
    """p_a - p_b decays at the rate R T G (1/V_a + 1/V_b); the gas mass is conserved."""
    res = ac.simulate(_Equalizing(), t_end=20.0, rtol=1e-10, n_points=101,
                      raise_on_failure=True)
    rate = R_T * 1e-9 * (1 / 1e-3 + 1 / 3e-3)
    dp = res["a.p"] - res["b.p"]
    assert np.max(np.abs(dp - 2e5 * np.exp(-rate * res.t))) < 1e-8 * 2e5
    mass = res["a.m"] + res["b.m"]
    assert np.max(np.abs(mass - mass[0])) < 1e-10 * mass[0]


def test_pneumatic_lift_follows_the_hand_written_equations():
    """Throttle, isothermal cylinder, mass and spring against DOP853 on
    p' = (p/(rho V)) (m_flow - rho A v), m v' = A (p - p_amb) - m g - c (x - x_0),
    m_flow = C_d A_t sqrt(2 rho_t (p_s - p)), rho = rho_0 p/p_0."""
    from acausal.library.gas.examples import pneumatic_lift as pl
    res = ac.simulate(pl.PneumaticLift(), t_end=pl.PneumaticLift.stop_time, rtol=1e-10,
                      n_points=301, raise_on_failure=True)

    def rhs(t, y):
        p, x, v = y
        rho, V = pl.RHO_REF * p / pl.P_REF, pl.V_0 + pl.A * x
        m_flow = pl.C_D * pl.A_T * np.sqrt(2 * pl.RHO_T * (pl.P_S - p))
        return [p / (rho * V) * (m_flow - rho * pl.A * v), v,
                (pl.A * (p - pl.P_AMB) - pl.M * pl.G - pl.C * (x - pl.X_0)) / pl.M]
    ref = solve_ivp(rhs, (0.0, res.t[-1]), [pl.P_START, pl.X_0, 0.0], method="DOP853",
                    rtol=1e-11, atol=1e-13, t_eval=res.t)
    for name, row in (("cylinder.p", 0), ("load.s", 1), ("load.v", 2)):
        err = np.max(np.abs(res[name] - ref.y[row]))
        assert err < 1e-6 * np.ptp(ref.y[row]), (name, err)
    # the gas mass grows by what the throttle passes
    m_in = np.concatenate([[0.0], np.cumsum(np.diff(res.t) * (res["valve.m_flow"][1:]
                                                              + res["valve.m_flow"][:-1]) / 2)])
    m_gas = res["cylinder.m"] - res["cylinder.m"][0]
    assert np.max(np.abs(m_gas - m_in)) < 1e-3 * m_gas[-1]      # trapezoid on the grid


# -- the compressible (choking) throttle ------------------------------------------------------
KAPPA, R_AIR, T_AIR = 1.4, 287.0, 293.15
R_CRIT = (2 / (KAPPA + 1))**(KAPPA / (KAPPA - 1))


def _nozzle_flow(p_u, p_d, A):
    """The Saint-Venant-Wantzel law, by hand."""
    r = max(p_d / p_u, R_CRIT)
    return (0.6 * A * p_u * np.sqrt(2 * KAPPA / ((KAPPA - 1) * R_AIR * T_AIR))
            * r**(1 / KAPPA) * np.sqrt(1 - r**((KAPPA - 1) / KAPPA)))


class _Discharge(ac.Component):
    """An isothermal tank at 8 bar blowing off to the atmosphere."""

    tank = gas.GasVolume(V=1e-2, n=1.0, p_0=1e5, rho_0=1e5 / (R_AIR * T_AIR),
                         p={"start": 8e5, "fixed": True})
    valve = gas.CompressibleThrottle(A=4e-6, C_d=0.6)
    atmosphere = gas.FixedPressure(p=1e5)

    def equations(self):
        return [ac.connect(self.tank.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.atmosphere.port)]


def test_tank_discharge_choked_then_subsonic():
    """Choked, the mass flow is proportional to the tank pressure, and the isothermal
    tank empties exponentially, p = p_0 exp(-t/tau), tau = V/(R T k A C_d p-coefficient),
    until p_amb/p reaches r_c = 0.528 at t = tau ln(p_0 r_c/p_amb); the whole run,
    choked and subsonic, against DOP853 on the hand-written law."""
    res = ac.simulate(_Discharge(), t_end=45.0, rtol=1e-10, n_points=451,
                      raise_on_failure=True)
    p = res["tank.p"]
    k = 0.6 * 4e-6 * np.sqrt(KAPPA / (R_AIR * T_AIR)) * (2 / (KAPPA + 1))**(
        (KAPPA + 1) / (2 * (KAPPA - 1)))
    tau = 1e-2 / (R_AIR * T_AIR * k)
    choked = p > 1e5 / R_CRIT
    assert np.max(np.abs(p[choked] - 8e5 * np.exp(-res.t[choked] / tau))) < 1e-8 * 7e5
    t_choke = tau * np.log(8e5 * R_CRIT / 1e5)
    assert abs(res.t[choked][-1] - t_choke) <= res.t[1] - res.t[0]
    ref = solve_ivp(lambda t, y: [-R_AIR * T_AIR / 1e-2 * _nozzle_flow(y[0], 1e5, 4e-6)],
                    (0.0, 45.0), [8e5], method="DOP853", rtol=1e-12, atol=1e-6, t_eval=res.t)
    assert np.max(np.abs(p - ref.y[0])) < 1e-8 * 7e5
    assert p[-1] > 1e5                                   # still subsonic outflow at 45 s


class _Nozzle(ac.Component):
    """The throttle between two fixed pressures."""

    a = gas.FixedPressure(p=3e5)
    valve = gas.CompressibleThrottle(A=1e-6, C_d=0.6)
    b = gas.FixedPressure(p=2e5)

    def equations(self):
        return [ac.connect(self.a.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.b.port)]


def _static_flow(compiled, p_a, p_b):
    """The flow between fixed pressures (a model without states: read at t = 0)."""
    compiled.set_parameters({"a.p": p_a, "b.p": p_b})
    return ac.simulate(compiled, t_end=1.0, n_points=2)["valve.m_flow"][0]


def test_compressible_throttle_law_both_ways_and_its_incompressible_limit():
    compiled = ac.compile(_Nozzle())
    for p_a, p_b in ((3e5, 2e5), (5e5, 1e5), (2e5, 3e5), (1e5, 5e5)):
        m = _static_flow(compiled, p_a, p_b)
        hand = _nozzle_flow(max(p_a, p_b), min(p_a, p_b), 1e-6) * np.sign(p_a - p_b)
        assert m == pytest.approx(hand, rel=1e-12)
    # choked: the flow does not depend on the downstream pressure
    assert _static_flow(compiled, 5e5, 1e5) == pytest.approx(_static_flow(compiled, 5e5, 2e5),
                                                            rel=1e-12)
    # a small drop: m_flow -> C_d A sqrt(2 rho_u dp), to first order in dp/p
    for dp in (1e2, 1e3):
        m = _static_flow(compiled, 1e5 + dp, 1e5)
        rho_u = (1e5 + dp) / (R_AIR * T_AIR)
        incompressible = 0.6 * 1e-6 * np.sqrt(2 * rho_u * dp)
        assert abs(m / incompressible - 1) < dp / 1e5
