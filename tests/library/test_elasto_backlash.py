"""ElastoBacklash (MSL Rotational.Components.ElastoBacklash): an inertia rattling in
the backlash against scipy's DOP853 (rtol 1e-11) on the hand-written law, integrated
piecewise between the events at the ends of the backlash; and its energy balance."""
import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import rotational as rot

J, C, D, B, W0 = 0.1, 1.0e3, 5.0, 0.1, 2.0


class Rattle(ac.Component):
    """An inertia leaving the middle of the backlash at W0 towards the upper flank."""

    housing = rot.Fixed()
    backlash = rot.ElastoBacklash(c=C, d=D, b=B)
    wheel = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True}, w={"start": W0, "fixed": True})
    E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="energy dissipated")

    def equations(self):
        return [ac.connect(self.housing.flange, self.backlash.flange_a),
                ac.connect(self.backlash.flange_b, self.wheel.flange_a),
                ac.Eq(ac.der(self.E_loss), self.backlash.lossPower)]


def contact_torque(phi, w):
    """The torque of the element on flange_b is -tau (written from the law)."""
    half = B / 2
    if phi > half:
        tc, td = C * (phi - half), D * w
        return 0.0 if tc + td <= 0 else tc + min(tc, td)
    if phi < -half:
        tc, td = C * (phi + half), D * w
        return 0.0 if tc + td >= 0 else tc + max(tc, td)
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
        # restart just past the edge so the event does not fire again at once
        t0, y0 = t1, sol.y[:, -1] + np.array([np.sign(sol.y[1, -1]) * 1e-14, 0.0])
        if sol.status == 0:
            break
    return np.concatenate(out_t), np.concatenate(out_y, axis=1)


def test_elasto_backlash_rattle_against_dop853():
    t = np.linspace(0, 0.6, 121)
    model = Rattle()
    res = ac.simulate(model, t_end=0.6, rtol=1e-10, atol=1e-12, t_eval=t)
    tr, yr = reference(0.6, t)
    assert len(tr) == len(t)
    assert len(res.events) >= 4                     # at least two contacts, in and out
    assert np.max(np.abs(res["wheel.phi"] - yr[0])) < 1e-7 * B
    assert np.max(np.abs(res["wheel.w"] - yr[1])) < 1e-6 * W0
    # the contact torque never pulls, and is 0 in the backlash
    tau = res["backlash.tau"]
    phi = res["backlash.phi_rel"]
    assert np.all(tau[phi > B / 2] >= 0) and np.all(tau[phi < -B / 2] <= 0)
    assert np.max(np.abs(tau[np.abs(phi) < B / 2 - 1e-9])) < 1e-12 * C * B
    # kinetic + spring energy + what lossPower took = the initial kinetic energy
    half = B / 2
    spring = np.where(np.abs(phi) > half, C * (np.abs(phi) - half)**2 / 2, 0.0)
    E0 = J * W0**2 / 2
    E = J * res["wheel.w"]**2 / 2 + spring + res["E_loss"]
    assert np.max(np.abs(E - E0)) < 1e-7 * E0
    assert res["E_loss"][-1] > 0.05 * E0
    assert not energy_balance(res, model).violations
