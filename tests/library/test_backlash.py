"""Rigid gear with backlash (Egeland & Gravdahl 3.6.3, (3.120)-(3.124)) against an
independent event-driven closed-form solution: with piecewise-constant motor torque each
phase is a parabola, free flight (3.124) for each side on its own, contact (3.122)-(3.123)
for the reduced inertia (3.12), impacts solved by hand (plastic, angular momentum kept);
and, for a varying torque, against solve_ivp on the reduced model."""
import math

import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.rotational import GearWithBacklash, Inertia, TorqueStep, Torque
from acausal.library.rotational.examples.rigid_backlash import RigidBacklashDrive

J_A, J_B, N, DELTA = 0.01, 0.5, 5.0, 0.01
J_TOT = N**2 * J_A + J_B          # load-side inertia in contact (book: J_m + n_b^2 J_L)


def reference(switches, torques, t_end):
    """Closed-form motion of motor (a) and load (b), phi_rel = phi_b - phi_a/n.

    ``torques[k]`` acts from ``switches[k]`` (switches[0] = 0) on; starts at rest with
    phi_rel = 0.  Returns (segments, impacts): segments (t0, t1, pa, wa, aa, pb, wb, ab),
    impacts (t, wa-, wb-, wa+, wb+)."""
    t, pa, wa, pb, wb, mode = 0.0, 0.0, 0.0, 0.0, 0.0, 0
    segments, impacts = [], []
    bounds = list(switches[1:]) + [t_end]
    for T, t_next in zip(torques, bounds):
        while t < t_next:
            if mode and mode * N * T >= 0:     # contact torque J_b a_b must push in:
                mode = 0                       # tau >= 0 at -delta, tau <= 0 at +delta
            if mode:
                ab = N * T / J_TOT
                aa, tc = N * ab, t_next
            else:
                aa, ab = T / J_A, 0.0
                pr, wr, ar = pb - pa / N, wb - wa / N, -aa / N
                hits = []
                for edge in (-DELTA, DELTA):   # pr + wr s + ar s^2/2 = edge, first s > 0
                    disc = wr**2 - 2 * ar * (pr - edge)
                    if ar != 0 and disc >= 0:
                        roots = [(-wr + r * math.sqrt(disc)) / ar for r in (-1, 1)]
                        # outwards only (not the flank just left at a release)
                        hits += [s for s in roots if s > 0 and (wr + ar * s) * edge > 0]
                tc = min(t_next, t + min(hits)) if hits else t_next
            dt = tc - t
            segments.append((t, tc, pa, wa, aa, pb, wb, ab))
            pa, wa = pa + wa * dt + aa * dt**2 / 2, wa + aa * dt
            pb, wb = pb + wb * dt + ab * dt**2 / 2, wb + ab * dt
            t = tc
            if not mode and tc < t_next:       # plastic impact
                w = (N * J_A * wa + J_B * wb) / J_TOT
                impacts.append((t, wa, wb, N * w, w))
                wa, wb = N * w, w
                mode = 1 if pb - pa / N > 0 else -1
    return segments, impacts


def evaluate(segments, t):
    """phi_a, w_a, phi_b, w_b at times t (the later segment at a boundary)."""
    out = np.empty((4, len(t)))
    for k, tk in enumerate(t):
        t0, _, pa, wa, aa, pb, wb, ab = [s for s in segments if s[0] <= tk][-1]
        d = tk - t0
        out[:, k] = (pa + wa * d + aa * d**2 / 2, wa + aa * d, pb + wb * d + ab * d**2 / 2,
                     wb + ab * d)
    return out


class ReversingDrive(ac.Component):
    """T_m = +0.5 N m, reversed to -0.5 N m at t = 0.2 s."""

    motor = Inertia(J=J_A, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    gear = GearWithBacklash(n=N, delta=DELTA, J_a=J_A, J_b=J_B)
    load = Inertia(J=J_B, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    drive = TorqueStep(offsetTorque=0.5, stepTorque=-1.0, startTime=0.2)

    def equations(self):
        return [ac.connect(self.drive.flange, self.motor.flange_a),
                ac.connect(self.motor.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.load.flange_a)]


def _check_against_reference(res, segments, impacts, tol):
    t = res.t
    ref = evaluate(segments, t)
    # the output holds an impact instant twice (before, after): checked separately
    keep = np.all(np.abs(t[:, None] - np.array([i[0] for i in impacts])) > 1e-8, axis=1)
    for k, name in enumerate(["motor.phi", "motor.w", "load.phi", "load.w"]):
        err = np.max(np.abs(res[name] - ref[k])[keep])
        assert err < tol, (name, err)
    for t_i, *_ in impacts:
        assert np.min(np.abs(np.array(res.events) - t_i)) < 1e-8


def test_free_flight_impact_and_contact_against_closed_form():
    res = ac.simulate(ReversingDrive(), t_end=0.4, rtol=1e-10)
    assert res.success
    segments, impacts = reference([0.0, 0.2], [0.5, -0.5], 0.4)
    assert len(impacts) == 2            # -delta at sqrt(2 J_a n delta/T), then +delta
    t_first = math.sqrt(2 * J_A * N * DELTA / 0.5)
    assert abs(impacts[0][0] - t_first) < 1e-12 * t_first     # two roundings of one root
    _check_against_reference(res, segments, impacts, 1e-8)
    t, tau = res.t, res["gear.tau"]
    # contact (3.122)-(3.123): the load is driven by n T_m through J_b + n^2 J_a and
    # the gear carries J_b a_b; free (3.124): no torque at all
    first = (t > impacts[0][0] + 1e-6) & (t < 0.2)
    assert np.allclose(tau[first], J_B * N * 0.5 / J_TOT, rtol=1e-9, atol=0)
    free = (t > 0.2) & (t < impacts[1][0] - 1e-6)
    # tau is an unknown of the solver's linear systems, zero up to their rounding: judged
    # against the contact torque; under a constant torque the states are polynomials that
    # BDF integrates exactly, so the load keeps its speed to rounding of that speed
    tau_contact = J_B * N * 0.5 / J_TOT
    assert np.max(np.abs(tau[free])) < 1e-12 * tau_contact
    assert np.ptp(res["load.w"][free]) < 1e-12 * np.max(np.abs(res["load.w"][free]))
    second = t > impacts[1][0] + 1e-6
    assert np.allclose(tau[second], -J_B * N * 0.5 / J_TOT, rtol=1e-9, atol=0)
    # the release at t = 0.2 is the torque reversal itself
    assert np.min(np.abs(np.array(res.events) - 0.2)) < 2.5e-12 * 0.4   # of the 0.4 s run


def test_impacts_conserve_angular_momentum_and_stop_the_relative_motion():
    res = ac.simulate(ReversingDrive(), t_end=0.4, rtol=1e-10)
    _, impacts = reference([0.0, 0.2], [0.5, -0.5], 0.4)
    t, wa, wb, w_rel = res.t, res["motor.w"], res["load.w"], res["gear.w_rel"]
    L = N * J_A * wa + J_B * wb
    for t_i, wa_ref, wb_ref, wa_plus, wb_plus in impacts:
        at = np.flatnonzero(np.abs(t - t_i) < 1e-8)
        assert len(at) >= 2                                 # output before and after
        before, after = at[0], at[-1]
        # the impact is taken eps = 1e-10 rad before the flank (its band): eps/w_rel
        # earlier, 2e-10 s here, so the motor is 1e-8 rad/s slower than at the flank
        assert abs(wa[before] - wa_ref) < 3e-8 and abs(wb[before] - wb_ref) < 1e-8
        assert abs(w_rel[before]) > 0.1                      # they do hit
        assert abs(L[after] - L[before]) < 1e-13 * abs(L[before])
        assert abs(w_rel[after]) < 1e-12 * abs(w_rel[before])   # the reinit sets 0
        assert abs(wb[after] - wb_plus) < 1e-8 and abs(wa[after] - wa_plus) < 3e-8
        # the energy of the relative motion is what the plastic impact loses
        E = 0.5 * J_A * wa**2 + 0.5 * J_B * wb**2
        J_eff = N**2 * J_A * J_B / J_TOT
        lost = E[before] - E[after]         # a difference of energies of size E[before]
        assert abs(lost - 0.5 * J_eff * w_rel[before]**2) < 1e-12 * E[before]


def test_square_wave_drive_example_stays_in_the_dead_zone():
    res = ac.simulate(RigidBacklashDrive(), t_end=RigidBacklashDrive.stop_time, rtol=1e-10,
                      max_step=0.05)
    assert res.success
    switches = [0.2 * k for k in range(5)]
    segments, impacts = reference(switches, [0.5, -0.5, 0.5, -0.5, 0.5], 1.0)
    assert len(impacts) == 5
    _check_against_reference(res, segments, impacts, 1e-8)
    phi_rel = res["gear.phi_rel"]
    assert np.max(np.abs(phi_rel)) - DELTA < 1e-8
    # in contact the teeth sit at the flank: the impact's reinit puts them there and
    # a_rel = (tau - sa)/J_eff vanishes to rounding, far below the tolerance rtol delta
    contact = np.abs(res["gear.tau"]) > 0
    assert np.max(np.abs(np.abs(phi_rel[contact]) - DELTA)) < 1e-10 * DELTA


class WavyDrive(ac.Component):
    """T_m = 0.5 + 0.3 sin(2 pi 0.8 t) N m > 0: one impact at -delta, then contact."""

    motor = Inertia(J=J_A, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    gear = GearWithBacklash(n=N, delta=DELTA, J_a=J_A, J_b=J_B)
    load = Inertia(J=J_B, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    drive = Torque()
    wave = Sine(amplitude=0.3, f=0.8, offset=0.5)

    def equations(self):
        return [ac.connect(self.wave.y, self.drive.tau),
                ac.connect(self.drive.flange, self.motor.flange_a),
                ac.connect(self.motor.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.load.flange_a)]


def test_contact_follows_the_reduced_rigid_model_under_a_varying_torque():
    """After the impact, (J_b + n^2 J_a) w_b' = n T_m(t) (3.12), (3.123), by solve_ivp
    from the post-impact state the impact law gives."""
    rtol = 1e-10
    res = ac.simulate(WavyDrive(), t_end=1.0, rtol=rtol)
    assert res.success and len(res.events) == 1
    T = lambda t: 0.5 + 0.3 * np.sin(2 * np.pi * 0.8 * t)
    # free flight of the motor alone (load at rest) up to phi_a = n delta
    free = solve_ivp(lambda t, y: [y[1], T(t) / J_A], (0, 1), [0.0, 0.0], rtol=1e-12,
                     atol=1e-14, events=lambda t, y: y[0] - N * DELTA, dense_output=True)
    t_c, wa_c = free.t_events[0][0], free.y_events[0][0][1]
    assert abs(res.events[0] - t_c) < 1e-8
    w_plus = N * J_A * wa_c / J_TOT                          # momentum kept, w_rel = 0
    ref = solve_ivp(lambda t, y: [y[1], N * T(t) / J_TOT], (t_c, 1.0), [0.0, w_plus],
                    rtol=1e-12, atol=1e-14, dense_output=True)
    t = res.t
    after = t > t_c + 1e-6
    phi_b, w_b = ref.sol(t[after])
    # relative to each signal's size: BDF's global error is 10-100 x rtol (1e-10)
    close = lambda a, b: np.max(np.abs(a - b)) < 1e-8 * max(1.0, np.max(np.abs(b)))
    assert close(res["load.w"][after], w_b)
    assert close(res["load.phi"][after], phi_b)
    assert close(res["motor.w"][after], N * w_b)
    # at the flank as in the square-wave test: set there by the reinit, and a_rel stays
    # zero to rounding (not exactly: that depends on the pivoting of the linear solves)
    assert np.max(np.abs(res["gear.phi_rel"][after] + DELTA)) < 1e-10 * DELTA
    before = t < t_c - 1e-6
    assert np.max(np.abs(res["motor.w"][before] - free.sol(t[before])[1])) < 1e-8
    # the load is at rest: load.w = w_c + (n^2 J_a/J_tot) w_rel, the difference of two
    # states of equal size that the solver integrates separately, each to its Newton
    # tolerance (a fraction of rtol): zero to rtol on their scale, not to rounding
    # (observed: 2e-14 to 1.1e-13 rad/s, for states of 0.15 rad/s)
    scale = np.max(np.abs(res["gear.w_c"][before]))
    assert np.max(np.abs(res["load.w"][before])) < rtol * scale
