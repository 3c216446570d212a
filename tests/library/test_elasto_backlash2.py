"""ElastoBacklash2 (MSL Rotational.Components.ElastoBacklash2): an inertia rattling in
the backlash against scipy's DOP853 (rtol 1e-11) on the hand-written law, integrated
piecewise between the events at the ends of the backlash; the torque jump d w at the
start of contact (which ElastoBacklash does not have); the energy balance; and b = 0,
a spring-damper."""
import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import rotational as rot

J, C, D, B, W0 = 0.1, 1.0e3, 5.0, 0.1, 2.0


def rattle(element):
    class Rattle(ac.Component):
        """An inertia leaving the middle of the backlash at W0 towards the upper flank."""

        housing = rot.Fixed()
        backlash = element
        wheel = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True},
                            w={"start": W0, "fixed": True})
        E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="energy dissipated")

        def equations(self):
            return [ac.connect(self.housing.flange, self.backlash.flange_a),
                    ac.connect(self.backlash.flange_b, self.wheel.flange_a),
                    ac.Eq(ac.der(self.E_loss), self.backlash.lossPower)]

    return Rattle()


def contact_torque(phi, w, b=B):
    """The torque of the element on flange_b is -tau (written from the law)."""
    half = b / 2
    if phi > half:
        total = C * (phi - half) + D * w
        return max(total, 0.0)
    if phi < -half:
        total = C * (phi + half) + D * w
        return min(total, 0.0)
    return 0.0


def reference(t_end, t_eval):
    """Integrate piecewise: each piece stops where phi crosses +-b/2."""
    def rhs(t, y):
        return [y[1], -contact_torque(y[0], y[1]) / J]

    edges = [lambda t, y, s=s: y[0] - s * B / 2 for s in (1, -1)]
    for e in edges:
        e.terminal = True
    t0, y0, out_t, out_y = 0.0, [0.0, W0], [], []
    while t0 < t_end:
        sol = solve_ivp(rhs, (t0, t_end), y0, method="DOP853", rtol=1e-11, atol=1e-13,
                        events=edges, dense_output=True)
        t1 = sol.t[-1]
        mask = (t_eval >= t0) & (t_eval <= t1)
        out_t.append(t_eval[mask])
        out_y.append(sol.sol(t_eval[mask]))
        t0, y0 = t1, sol.y[:, -1] + np.array([np.sign(sol.y[1, -1]) * 1e-14, 0.0])
        if sol.status == 0:
            break
    return np.concatenate(out_t), np.concatenate(out_y, axis=1)


def test_elasto_backlash2_rattle_against_dop853_and_its_energy():
    t = np.linspace(0, 0.6, 121)
    model = rattle(rot.ElastoBacklash2(c=C, d=D, b=B))
    res = ac.simulate(model, t_end=0.6, rtol=1e-10, atol=1e-12, t_eval=t)
    tr, yr = reference(0.6, t)
    assert len(tr) == len(t)
    assert len(res.events) >= 4                     # at least two contacts, in and out
    assert np.max(np.abs(res["wheel.phi"] - yr[0])) < 1e-7 * B
    assert np.max(np.abs(res["wheel.w"] - yr[1])) < 1e-6 * W0
    tau, phi = res["backlash.tau"], res["backlash.phi_rel"]
    assert np.all(tau[phi > B / 2] >= 0) and np.all(tau[phi < -B / 2] <= 0)
    assert np.max(np.abs(tau[np.abs(phi) < B / 2 - 1e-9])) < 1e-12 * C * B
    half = B / 2
    spring = np.where(np.abs(phi) > half, C * (np.abs(phi) - half)**2 / 2, 0.0)
    E0 = J * W0**2 / 2
    E = J * res["wheel.w"]**2 / 2 + spring + res["E_loss"]
    assert np.max(np.abs(E - E0)) < 1e-7 * E0
    assert res["E_loss"][-1] > 0.05 * E0
    assert not energy_balance(res, model).violations


def test_the_contact_torque_jumps_by_d_w_at_the_flank_unlike_elasto_backlash():
    t_hit = (B / 2) / W0                            # free flight to the upper flank
    t = np.array([0.0, t_hit * (1 + 1e-6)])
    jump = {}
    for element in (rot.ElastoBacklash2(c=C, d=D, b=B), rot.ElastoBacklash(c=C, d=D, b=B)):
        res = ac.simulate(rattle(element), t_end=t[-1], rtol=1e-10, atol=1e-12, t_eval=t)
        jump[type(element).__name__] = res["backlash.tau"][-1]
    # just past the flank: d w (+ a spring torque ~ c W0 dt, negligible) against ~2 c W0 dt
    assert abs(jump["ElastoBacklash2"] - D * W0) < 1e-3 * D * W0
    assert abs(jump["ElastoBacklash"]) < 1e-3 * D * W0


def test_without_backlash_it_is_a_spring_damper():
    t = np.linspace(0, 0.3, 61)
    res = ac.simulate(rattle(rot.ElastoBacklash2(c=C, d=D, b=0.0)), t_end=0.3, rtol=1e-10,
                      atol=1e-12, t_eval=t)
    # J phi'' + D phi' + C phi = 0, phi(0) = 0, phi'(0) = W0: underdamped closed form
    sigma, wd = D / (2 * J), np.sqrt(C / J - (D / (2 * J))**2)
    phi = W0 / wd * np.exp(-sigma * t) * np.sin(wd * t)
    assert np.max(np.abs(res["wheel.phi"] - phi)) < 1e-7 * np.max(np.abs(phi))
