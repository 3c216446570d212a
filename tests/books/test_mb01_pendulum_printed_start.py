"""MB-01: the Cartesian pendulum from the DTU notes' printed start (000 §3.5, Figs. 3.5/3.6).

The notes start (x, y, p_x, p_y) = (0.34, 0.94, 0.94, -0.34) with y and gravity pointing
down (their p_y' = m g); m, l, g are not printed, the start implies l ~ 1 (INVENTORY
MB-01).  In ``library/examples/pendulum.Pendulum`` (y up, m = l = 1, g = 9.81) that is
x = 0.34, y = -0.94, v = (0.94, 0.34).  Their hand-reduced form divides by x and could not
pass x = 0 with the trapezoidal rule and fixed-point iteration, and needed h = 1e-4 ...
1e-5 near it with Newton; here the index-3 DAE is reduced by Pantelides and dummy
derivatives, with x and v_x fixed at the start (|r| = 0.9996 as printed, so y and v_y
are the ones made consistent).

Checked at rtol 1e-9 over 10 s (about 5 periods, 10 passes through x = 0): the start is
made consistent (y = -sqrt(1 - 0.34^2), x v_x + y v_y = 0), |r| = 1 to 1e-8 (measured
1.1e-10) and the energy to 5e-7 relative (measured 5e-8) along the run, and the angle
(amplitude 0.47 rad) agrees with DOP853 at rtol 1e-11 on theta'' = -g sin(theta) to
1e-6 rad (measured 2.9e-8).
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.examples.pendulum import Pendulum

G = 9.81
X0, VX0 = 0.34, 0.94                     # the printed x and p_x (m = 1)


@pytest.fixture(scope="module")
def run():
    model = Pendulum(x={"start": X0, "fixed": True}, y={"start": -0.94},
                     vx={"start": VX0, "fixed": True}, vy={"start": 0.34})
    t = np.linspace(0.0, 10.0, 1001)
    return ac.simulate(model, t_end=10.0, rtol=1e-9, atol=1e-9, t_eval=t)


def test_printed_start_is_made_consistent(run):
    y0 = -np.sqrt(1.0 - X0**2)
    assert run["x"][0] == pytest.approx(X0, rel=1e-12)
    assert run["y"][0] == pytest.approx(y0, rel=1e-10)
    assert run["vx"][0] == pytest.approx(VX0, rel=1e-12)
    assert run["vy"][0] == pytest.approx(-X0 * VX0 / y0, rel=1e-10)


def test_passes_the_vertical_keeping_length_and_energy(run):
    x, y, vx, vy = run["x"], run["y"], run["vx"], run["vy"]
    assert np.sum(np.diff(np.sign(x)) != 0) >= 9         # x = 0 passed again and again
    assert np.max(np.abs(x**2 + y**2 - 1.0)) < 1e-8
    energy = 0.5 * (vx**2 + vy**2) + G * (y + 1.0)          # relative to the lowest point
    assert np.max(np.abs(energy - energy[0])) < 5e-7 * energy[0]


def test_angle_matches_the_angle_ode(run):
    x, y = run["x"], run["y"]
    y0 = -np.sqrt(1.0 - X0**2)                              # the consistent start
    theta0 = np.arctan2(X0, -y0)
    omega0 = -y0 * VX0 + X0 * (-X0 * VX0 / y0)             # (r x v)_z / l^2
    ode = solve_ivp(lambda _, s: [s[1], -G * np.sin(s[0])], (0.0, 10.0), [theta0, omega0],
                    method="DOP853", rtol=1e-11, atol=1e-12, t_eval=run.t)
    assert np.max(np.abs(np.arctan2(x, -y) - ode.y[0])) < 1e-6
