"""Clutch, Brake and OneWayClutch (MSL semantics) against independent references.

CoupledClutches (J1 -- clutch1 -- J2 -- clutch2 -- J3 -- brake, engaged and released by
time tables) against a mode-by-mode integration of the hand-written equations by
solve_ivp DOP853 at rtol 1e-10 with its own lock-up and break-away event functions
(``_clutch_reference``): the speeds, every lock-up and break-away time, the stick
intervals and the angular momentum of each group that locks.  A one-way clutch used as
a pure freewheel against its closed form.  Bad input raises InvalidValue.
"""
import math

import numpy as np
import pytest
from scipy.optimize import brentq

import acausal as ac
from acausal.library.blocks import Constant, Sine
from acausal.library.rotational import Inertia, Torque
from acausal.library.rotational.clutches import BearingFriction, Brake, Clutch, OneWayClutch
from acausal.library.rotational.examples.coupled_clutches import CoupledClutches, ENGAGEMENT

from ._clutch_reference import Chain, _groups, simulate_chain, speeds

J = (1.0, 0.6, 0.35)
FN = (20.0, 15.0, 30.0)
MU, PEAK = 0.5, 1.1
T_END = CoupledClutches.stop_time
TABLE_TIMES = sorted({t for span in ENGAGEMENT.values() for t in span if t is not None})


@pytest.fixture(scope="module")
def coupled():
    chain = Chain(J=J, fn=FN, on=tuple([span] for span in ENGAGEMENT.values()),
                  mu=MU, peak=PEAK, amplitude=30.0, f=3.0, w0=(6.0, 0.0, 0.0))
    segments, switches = simulate_chain(chain, T_END)
    res = ac.simulate(CoupledClutches(), t_end=T_END, rtol=1e-8)
    assert res.success, res.message
    return chain, segments, switches, res


def _w(res):
    return np.vstack([res["J1.w"], res["J2.w"], res["J3.w"]])


def test_reference_shows_every_mode(coupled):
    """The run is worth comparing: lock-ups and break-aways of both clutches and the
    brake, sliding both ways (guards the scenario, not the library)."""
    _, segments, switches, _ = coupled
    state = [s for s in switches if s[0] not in TABLE_TIMES]
    locks = {k for _, k, _, new, _, _ in state if new == "stuck"}
    breaks = {k for _, k, old, _, _, _ in state if old == "stuck"}
    assert locks == {0, 1, 2} and breaks >= {0}
    modes = {m for seg in segments for m in seg[3]}
    assert modes == {"open", 1, -1, "stuck"}


def test_speeds_against_mode_by_mode_reference(coupled):
    _, segments, _, res = coupled
    W, R = _w(res), speeds(segments, res.t)
    scale = np.abs(R).max()
    # measured 1.9e-7 of the largest speed at rtol 1e-8 (BDF's global error)
    assert np.abs(W - R).max() < 2e-6 * scale


def test_lock_up_and_break_away_times(coupled):
    """Every state event of the reference has an event of the run within 1e-6 s
    (measured: 1.1e-7 s at most), and the run has no state event the reference lacks
    (times apart by more than that)."""
    _, _, switches, res = coupled
    ref = np.array([s[0] for s in switches if s[0] not in TABLE_TIMES])
    state = [e for e in res.events if e.kind == "relation"]
    run = np.array([e.time for e in state])
    assert np.abs(run[:, None] - ref[None, :]).min(axis=0).max() < 1e-6
    names = list(ENGAGEMENT)
    for e in state:
        if np.abs(ref - e.time).min() > 1e-6 and min(abs(e.time - s) for s in TABLE_TIMES) > 1e-6:
            # only an open element's speeds may cross (an event of its relations, no switch)
            assert all(not _pressed(names.index(c), e.time) for c in e.components), e


def _pressed(k, t):
    on, off = list(ENGAGEMENT.values())[k]
    return on <= t and (off is None or t < off)


def test_stick_intervals_hold_and_slide_intervals_carry_coulomb_torque(coupled):
    _, segments, _, res = coupled
    t = res.t
    w = _w(res)
    w_rel = [w[1] - w[0], w[2] - w[1], w[2]]
    tau = [res["clutch1.tau"], res["clutch2.tau"], res["brake.tau"]]
    stuck_seen = 0
    for t0, t1, _, mode in segments:
        inside = (t > t0 + 1e-6) & (t < t1 - 1e-6)
        for k, m in enumerate(mode):
            if m == "stuck":
                stuck_seen += 1
                assert np.abs(w_rel[k][inside]).max() < 1e-9 * 10.0
                assert np.abs(tau[k][inside]).max() <= PEAK * MU * FN[k] * (1 + 1e-9)
            elif m in (1, -1):
                assert np.allclose(tau[k][inside], m * MU * FN[k], rtol=1e-12, atol=0)
            else:
                assert np.abs(tau[k][inside]).max() == 0.0
    assert stuck_seen >= 6


def test_angular_momentum_of_each_locking_group(coupled):
    """A lock-up joins inertias into a group: its sum J_i w_i is the same just before
    and just after the event (the lock-up is continuous under finite friction), and
    equal to the reference's, whose group is merged at its momentum."""
    chain, _, switches, res = coupled
    t, w = res.t, _w(res)
    scale = np.abs(w).max() * sum(J)
    checked = 0
    for te, k, _, new, before, after in switches:
        if new != "stuck" or before is None:
            continue
        assert before == pytest.approx(after, abs=1e-12 * scale)      # the reference's
        at = np.flatnonzero(np.abs(t - te) < 1e-6)
        assert at.size >= 2, f"no points at the lock-up near t = {te}"
        label = _groups(chain, _modes_after(switches, te))
        for g, L_ref in after.items():
            members = [i for i in range(len(J)) if label[i] == g]
            L = sum(J[i] * w[i, at] for i in members)
            assert np.ptp(L) < 1e-9 * scale
            if g == label[k]:
                assert abs(L[0] - L_ref) < 2e-6 * scale
        checked += 1
    assert checked >= 5


def _modes_after(switches, te):
    mode = ["open"] * 3
    for t, k, _, new, _, _ in switches:
        if t <= te:
            mode[k] = new
    return mode


def test_friction_never_delivers_power(coupled):
    _, _, _, res = coupled
    for name, w in (("clutch1", res["J2.w"] - res["J1.w"]),
                    ("clutch2", res["J3.w"] - res["J2.w"]), ("brake", res["J3.w"])):
        assert (res[f"{name}.tau"] * w).min() > -1e-9


def test_energy_balance_books_the_elements_as_dissipation(coupled):
    """dE/dt of the inertias = drive power - friction losses (measured to 3e-11 of the
    power scale), and no element ever delivers power."""
    from acausal.analysis import energy_balance
    _, _, _, res = coupled
    audit = energy_balance(res, CoupledClutches())
    assert {audit.roles[k] for k in ("clutch1", "clutch2", "brake")} == {"dissipation"}
    assert audit.ok, audit.summary()
    for k in ("clutch1", "clutch2", "brake"):
        assert np.min(audit.dissipated[k]) >= -1e-9 * audit.power_scale


def test_report_shows_structure_of_every_mode():
    report = ac.compile(CoupledClutches()).report
    modes = {c["component"]: c for c in report.as_dict()["modes"]}
    assert set(modes) == {"clutch1", "clutch2", "brake"}
    locked = {m["mode"]: m for m in modes["clutch1"]["modes"]}["locked"]
    assert "0 = clutch1.a_rel" in locked["structure"]
    assert "clutch1.tau = clutch1.sa" in locked["structure"]
    assert "not an independent state" in locked["structure"]
    text = str(report)
    assert "modes of brake (Brake)" in text and text.count("locked") >= 3


def test_one_way_clutch_has_no_free_or_backward_mode():
    report = ac.compile(Freewheel()).report
    (wheel,) = report.as_dict()["modes"]
    assert [m["mode"] for m in wheel["modes"]] == ["forward", "start forward", "locked"]


# -- one-way clutch: a freewheel (fn = 0) between a driven and a free inertia -------------
J_A, J_B, T0, AMP = 1.0, 0.5, 2.0, 10.0


class Freewheel(ac.Component):
    """T = 2 + 10 sin(2 pi t) on J_a; a one-way clutch (fn = 0) drives J_b."""

    a = Inertia(J=J_A, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    b = Inertia(J=J_B, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    wheel = OneWayClutch(fn_max=1.0)
    open_ = Constant(k=0.0)
    drive = Torque()
    sine = Sine(amplitude=AMP, f=1.0, offset=T0)

    def equations(self):
        return [ac.connect(self.sine.y, self.drive.tau),
                ac.connect(self.drive.flange, self.a.flange_a),
                ac.connect(self.a.flange_b, self.wheel.flange_a),
                ac.connect(self.wheel.flange_b, self.b.flange_a),
                ac.connect(self.open_.y, self.wheel.f_normalized)]


def _torque_integral(t0, t1):
    c = AMP / (2 * math.pi)
    return T0 * (t1 - t0) + c * (math.cos(2 * math.pi * t0) - math.cos(2 * math.pi * t1))


def test_one_way_clutch_as_freewheel_against_closed_form():
    """Locked while T >= 0 (the group J_a + J_b accelerates: w = int T / (J_a + J_b));
    once T < 0 (beyond the tiny break-away floor) J_b coasts and J_a runs on its own
    until it catches up with J_b (int T = 0 from the release), which locks again."""
    res = ac.simulate(Freewheel(), t_end=1.45, rtol=1e-9)
    assert res.success, res.message
    floor = 1e-4 * 0.5 * 1.0                          # eps0 mu0 cgeo fn_max
    # release: the freewheel torque tau = -J_b T / (J_a + J_b) exceeds the floor
    T = lambda t: T0 + AMP * math.sin(2 * math.pi * t)       # noqa: E731
    t_rel = brentq(lambda t: -J_B * T(t) / (J_A + J_B) - floor, 0.5, 0.6)
    w_b = _torque_integral(0.0, t_rel) / (J_A + J_B)
    t_lock = brentq(lambda t: _torque_integral(t_rel, t), 0.97, 1.7)
    t, wa, wb = res.t, res["a.w"], res["b.w"]

    def exact(tt):
        if tt <= t_rel:
            v = _torque_integral(0.0, tt) / (J_A + J_B)
            return v, v
        if tt <= t_lock:
            return w_b + _torque_integral(t_rel, tt) / J_A, w_b
        v = w_b + _torque_integral(t_lock, tt) / (J_A + J_B)
        return v, v

    ref = np.array([exact(tt) for tt in t]).T
    scale = np.abs(ref).max()
    err = max(np.abs(wa - ref[0]).max(), np.abs(wb - ref[1]).max())
    assert err < 1e-7 * scale                          # measured 2.8e-9 at rtol 1e-9
    ev = np.array([e.time for e in res.events if e.kind == "relation"])
    # measured 1e-11 s and 1.4e-9 s
    assert np.abs(ev - t_rel).min() < 1e-7 and np.abs(ev - t_lock).min() < 1e-7
    assert (wb - wa).min() > -1e-9 * scale             # never backwards


# -- bad input -------------------------------------------------------------------------
def _chain_with(element):
    class M(ac.Component):
        a = Inertia(J=1.0, w={"start": 1.0, "fixed": True})
        b = Inertia(J=1.0)
        c = element
        f = Constant(k=1.0)

        def equations(self):
            return [ac.connect(self.a.flange_b, self.c.flange_a),
                    ac.connect(self.c.flange_b, self.b.flange_a),
                    ac.connect(self.f.y, self.c.f_normalized)]
    return M()


@pytest.mark.parametrize("fn_max", [0.0, -1.0])
def test_non_positive_normal_force_is_refused(fn_max):
    with pytest.raises(ac.InvalidValue, match="fn_max"):
        ac.compile(_chain_with(Clutch(fn_max=fn_max)))


@pytest.mark.parametrize("table, words", [
    ([[0.0, 0.5], [1.0, 0.4], [0.5, 0.3]], "increasing"),
    ([[0.0, 0.5], [0.0, 0.4]], "increasing"),
    ([[-1.0, 0.5], [1.0, 0.4]], "w_rel >= 0"),
    ([[0.0, -0.1]], "mu = -0.1"),
    ([[0.0, 0.5, 1.0]], "n x 2"),
    ("not a table", "mu_pos"),
])
def test_bad_friction_table_is_refused(table, words):
    with pytest.raises(ac.InvalidValue, match=words):
        Clutch(mu_pos=table)


def test_peak_below_one_is_refused():
    with pytest.raises(ac.InvalidValue, match="peak"):
        ac.compile(_chain_with(Brake(peak=0.9, fn_max=1.0)))


# -- a friction table: a brake stops a flywheel -----------------------------------------
MU_POS = [[0.0, 0.5], [1.0, 0.4], [3.0, 0.3]]


class Flywheel(ac.Component):
    """J = 0.2 kg.m2 at 5 rad/s braked by fn = 2 N with mu(w) from MU_POS (extrapolated
    linearly above 3 rad/s, as the MSL's LastTwoPoints)."""

    J = Inertia(J=0.2, phi={"start": 0.0, "fixed": True}, w={"start": 5.0, "fixed": True})
    brake = Brake(mu_pos=MU_POS, fn_max=2.0, peak=1.2)
    press = Constant(k=1.0)

    def equations(self):
        return [ac.connect(self.J.flange_b, self.brake.flange_a),
                ac.connect(self.press.y, self.brake.f_normalized)]


def _mu(w):
    x, y = np.array(MU_POS).T
    if w > x[-1]:
        return y[-1] + (y[-1] - y[-2]) / (x[-1] - x[-2]) * (w - x[-1])
    return float(np.interp(w, x, y))


def test_brake_with_friction_table_stops_a_flywheel():
    """J w' = -fn mu(w) until w = 0 (solve_ivp DOP853, rtol 1e-10, event w = 0), then the
    brake holds it at rest with no torque (nothing else acts)."""
    from scipy.integrate import solve_ivp
    stop = lambda t, y: y[0]                      # noqa: E731
    stop.terminal, stop.direction = True, -1
    ref = solve_ivp(lambda t, y: [-2.0 * _mu(y[0]) / 0.2], (0, 10), [5.0], method="DOP853",
                    rtol=1e-10, atol=1e-12, events=stop, dense_output=True)
    t_stop = ref.t_events[0][0]
    res = ac.simulate(Flywheel(), t_end=t_stop + 0.5, rtol=1e-9)
    assert res.success, res.message
    sliding = res.t < t_stop
    w_ref = ref.sol(res.t[sliding])[0]
    # measured 7.8e-9 of the initial speed, and the stop 7.8e-9 s off, at rtol 1e-9
    assert np.abs(res["J.w"][sliding] - w_ref).max() < 1e-7 * 5.0
    ev = np.array([e.time for e in res.events if e.kind == "relation"])
    assert np.abs(ev - t_stop).min() < 1e-7
    after = res.t > t_stop + 1e-6
    assert np.abs(res["J.w"][after]).max() < 1e-9 and np.abs(res["brake.tau"][after]).max() < 1e-9


# -- bearing friction: stick-slip of a shaft driven by a sine torque -----------------------
TAU_POS, PEAK_B, J_S = [[0.0, 1.0], [2.0, 1.5]], 1.3, 0.1


class Shaft(ac.Component):
    """J = 0.1 kg.m2 at rest on a bearing (tau_pos rises from 1 to 1.5 N.m over 2 rad/s,
    peak 1.3), driven by 2 sin(2 pi t) N.m."""

    J = Inertia(J=J_S, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    bearing = BearingFriction(tau_pos=TAU_POS, peak=PEAK_B)
    drive = Torque()
    sine = Sine(amplitude=2.0, f=1.0)

    def equations(self):
        return [ac.connect(self.sine.y, self.drive.tau),
                ac.connect(self.drive.flange, self.J.flange_a),
                ac.connect(self.J.flange_b, self.bearing.flange_a)]


def _shaft_reference(t_end):
    """Mode by mode (solve_ivp DOP853, rtol 1e-10): stuck while |T| <= peak tau(0),
    J w' = T - tau(|w|) sgn(w) while sliding, stuck again where w reaches 0 with
    |T| <= peak tau(0), else sliding on the other way.  Returns (pieces, switch times)."""
    from scipy.integrate import solve_ivp
    (w0, t0_), (w1, t1_) = TAU_POS
    tau = lambda w: t0_ + (t1_ - t0_) / (w1 - w0) * w            # noqa: E731
    T = lambda t: 2.0 * math.sin(2 * math.pi * t)                # noqa: E731
    hold = PEAK_B * t0_
    t, w, pieces, switches, mode = 0.0, 0.0, [], [], 0
    while t < t_end:
        if mode == 0:
            # next time |T| exceeds hold after t (T is smooth: scan, then brentq)
            grid = np.linspace(t, t_end, 4001)
            over = np.flatnonzero(np.abs([T(s) for s in grid]) > hold)
            if not over.size:
                pieces.append((t, t_end, lambda s: 0.0))
                break
            i = over[0]
            te = brentq(lambda s: abs(T(s)) - hold, grid[max(i - 1, 0)], grid[i])
            pieces.append((t, te, lambda s: 0.0))
            switches.append(te)
            t, mode = te, (1 if T(te) > 0 else -1)
            continue
        s_ = mode
        stop = lambda tt, y: y[0]                                # noqa: E731
        stop.terminal, stop.direction = True, -s_
        sol = solve_ivp(lambda tt, y: [(T(tt) - s_ * tau(s_ * y[0])) / J_S], (t, t_end),
                        [w], method="DOP853", rtol=1e-10, atol=1e-12, events=stop,
                        dense_output=True)
        te = sol.t_events[0][0] if sol.t_events[0].size else t_end
        pieces.append((t, te, lambda s, f=sol.sol: f(s)[0]))
        if te >= t_end:
            break
        switches.append(te)
        t, w = te, 0.0
        mode = 0 if abs(T(te)) <= hold else (1 if T(te) > 0 else -1)
    return pieces, switches


def test_bearing_friction_stick_slip_against_mode_by_mode_reference():
    res = ac.simulate(Shaft(), t_end=2.0, rtol=1e-9)
    assert res.success, res.message
    pieces, switches = _shaft_reference(2.0)
    assert len(switches) >= 4                       # breaks away and sticks twice
    ref = np.array([next(f(tt) for a, b, f in pieces if a <= tt <= b) for tt in res.t])
    scale = np.abs(ref).max()
    # measured 8.4e-9 of the largest speed and 5.7e-10 s at rtol 1e-9
    assert np.abs(res["J.w"] - ref).max() < 1e-7 * scale
    ev = np.array([e.time for e in res.events if e.kind == "relation"])
    assert max(np.abs(ev - s).min() for s in switches) < 1e-7
