"""MB-14: quaternion kinematics with normalization (Egeland & Gravdahl, 001 §6.9.5-6.9.6).

    der(Q) = 1/2 G(Q)^T w + lam/2 (1 - Q^T Q) Q                                  (6.336)

Since Q^T G(Q)^T w = 0 for every Q, e = 1 - Q^T Q obeys der(e) = -lam e (1 - e), which
the book linearizes to der(e) = -lam e, time constant 1/lam ("lam = 100 gives 0.01 s").
The exact solution of the logistic form is

    e / (1 - e) = e0 / (1 - e0) exp(-lam t).

acausal's Spherical and FreeMotion joints carry (6.336) (``library/multibody3d/joints``).
Checked on the free tennis racket of ``library/multibody3d/examples/tops.py`` (it tumbles
with w = (0.01, 1, 0.01) rad/s, so the G^T w term is at work), started with a quaternion
whose norm is off, Q^T Q = 1.02 (e0 = -0.02), at a rotation of 0.7 rad about (1, 2, 2)/3:
e(t) follows the closed form to 1e-6 of |e0| for lam = 100 (the book's 0.01 s) and
lam = 10 (measured 3.2e-8 for both), and the rotation matrix stays orthogonal meanwhile
(R(Q) is divided by Q^T Q).  The projection alternative p := p / |p| (6.338) is not
offered by the library.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library.multibody3d import Body, FreeMotion, World
from acausal.library.multibody3d.examples.tops import RACKET

E0 = -0.02
_PHI, _N = 0.7, np.array([1.0, 2.0, 2.0]) / 3.0
Q0 = np.sqrt(1.0 - E0) * np.append(np.sin(_PHI / 2) * _N, np.cos(_PHI / 2))


def _fixed(value):
    return {"start": value, "fixed": True}


class OffNormRacket(ac.Component):
    """The free tennis racket, its Euler parameters started off the unit sphere."""

    world = World(g=0.0)
    # the four Euler parameters fixed off the unit sphere, so not Q^T Q = 1 at the start
    joint = FreeMotion(Q=_fixed(list(Q0)), Q_2={"fixed": False},
                       w_rel_b=_fixed(list(RACKET["w"])), r_rel_a=_fixed(0.0),
                       v_rel_a=_fixed(0.0))
    body = Body(m=1.0, I_11=RACKET["I_1"], I_22=RACKET["I_2"], I_33=RACKET["I_3"])

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.body.frame_a)]


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(OffNormRacket())


@pytest.mark.parametrize("lam", [100.0, 10.0])
def test_norm_error_decays_with_time_constant_one_over_lambda(compiled, lam):
    t_end = 8.0 / lam
    t = np.linspace(0.0, t_end, 161)
    res = ac.simulate(compiled, t_end=t_end, rtol=1e-10, atol=1e-12, t_eval=t,
                      parameters={"joint.lam": lam})
    Q = np.asarray(res["joint.Q"]).T
    e = 1.0 - np.sum(Q**2, axis=0)
    assert e[0] == pytest.approx(E0, rel=1e-12)
    k = E0 / (1.0 - E0) * np.exp(-lam * t)
    e_exact = k / (1.0 + k)
    assert np.max(np.abs(e - e_exact)) < 1e-6 * abs(E0)
    # the orientation itself stays a rotation while |Q| is off
    R = np.array([[res[f"body.frame_a.R{i}{j}"] for j in (1, 2, 3)] for i in (1, 2, 3)])
    RRt = np.einsum("ikn,jkn->ijn", R, R)
    assert np.max(np.abs(RRt - np.eye(3)[:, :, None])) < 1e-10
