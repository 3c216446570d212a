"""Equilibria and linearization points satisfy the modes they are computed in
(analysis/modes.py): a heater behind a Limiter and a spinner on Stribeck friction."""
import numpy as np
import pytest
from scipy.optimize import brentq

import acausal as ac
from acausal.analysis import OperatingPoint, linearize, steady_state
from acausal.library import rotational as rot
from acausal.library.friction.rotational import StribeckFriction

from ..heater import C_TH, G, K_P, Q_MAX, T_AMB, LimitedHeater, heater_equilibrium
from acausal.errors import ModeWarning, OperatingPointError, SteadyStateError

# start saturated high / unsaturated / far above; equilibria unsaturated / high / low
@pytest.mark.parametrize("t_set, t_start", [(323.15, T_AMB), (420.0, 415.0),
                                            (280.0, 400.0), (323.15, 500.0)])
def test_heater_equilibrium_is_in_the_limiter_mode_it_satisfies(t_set, t_start):
    model = LimitedHeater(set_point={"k": t_set}, body={"T": {"start": t_start}})
    op = steady_state(model)
    T, Q = heater_equilibrium(t_set)
    assert op["body.T"] == pytest.approx(T, rel=1e-12)
    assert op["limit.y.signal"] == pytest.approx(Q, rel=1e-10, abs=1e-12 * Q_MAX)
    assert op["limit.y.signal"] == pytest.approx(
        float(np.clip(op["limit.u.signal"], 0.0, Q_MAX)), rel=1e-10, abs=1e-12 * Q_MAX)
    assert abs(op["der(body.T)"]) < 1e-12 * Q_MAX / C_TH
    modes = list(op.modes.values())
    assert modes == [Q == Q_MAX, Q == 0.0]          # u > uMax, u < uMin


def test_heater_linearized_in_each_mode():
    """Unsaturated: T' = -(G + K_p)/C T + (K_p/C) T_set; saturated: -G/C and no input."""
    sys = linearize(LimitedHeater(), ["set_point.k"], ["body.T"], at="steady")
    assert sys.A[0, 0] == pytest.approx(-(G + K_P) / C_TH, rel=1e-9)
    assert sys.B[0, 0] == pytest.approx(K_P / C_TH, rel=1e-9)
    assert list(sys.modes.values()) == [False, False]
    hot = linearize(LimitedHeater(set_point={"k": 420.0}), ["set_point.k"], ["body.T"], at="steady")
    assert hot.A[0, 0] == pytest.approx(-G / C_TH, rel=1e-9)
    assert abs(hot.B[0, 0]) < 1e-12 * K_P / C_TH
    assert list(hot.modes.values()) == [True, False]


def test_linearization_at_the_limit_says_which_side_it_took():
    """At K_p (T_set - T) = Q_max exactly the model has a kink: the warning names the
    relation and the side, and A is that side's."""
    at_limit = 323.15 - Q_MAX / K_P
    with pytest.warns(ModeWarning, match=r"gain\.y\.signal > limit\.uMax.*taken as"):
        sys = linearize(LimitedHeater(), ["set_point.k"], ["body.T"], at={"body.T": at_limit})
    saturated = [v for k, v in sys.modes.items() if "uMax" in k.split(" in ")[0]][0]
    expected = -G / C_TH if saturated else -(G + K_P) / C_TH
    assert sys.A[0, 0] == pytest.approx(expected, rel=1e-9)


def test_a_point_that_contradicts_its_modes_is_refused():
    op = steady_state(LimitedHeater())                        # unsaturated, T = 320.4 K
    wrong = OperatingPoint(op.plant, op.t, op.z, m=np.array([1.0, 0.0]))
    with pytest.raises(OperatingPointError, match=r"limit\.uMax") as err:
        linearize(op.compiled, ["set_point.k"], ["body.T"], at=wrong)
    assert len(err.value.relations) == 1


def test_linearization_along_a_run_uses_the_modes_of_the_run():
    model = LimitedHeater()
    res = ac.simulate(model, t_end=2000.0, rtol=1e-8, n_points=201)
    early = linearize(res.compiled, ["set_point.k"], ["body.T"], at=(res, 10.0))
    late = linearize(res.compiled, ["set_point.k"], ["body.T"], at=(res, 2000.0))
    assert res.at("limit.u.signal", 10.0) > Q_MAX > res.at("limit.u.signal", 2000.0) > 0
    assert early.A[0, 0] == pytest.approx(-G / C_TH, rel=1e-9)
    assert late.A[0, 0] == pytest.approx(-(G + K_P) / C_TH, rel=1e-9)


# J w' = tau_0 - tau_f(w) - d w with tau_f the Stribeck map (Egeland & Gravdahl (5.13))
F_C, F_S, V_S, F_V, D, J, TAU = 1.0, 1.5, 0.1, 0.05, 0.2, 0.02, 2.0


def stribeck(w):
    return (F_C + (F_S - F_C) * np.exp(-(w / V_S) ** 2)) * np.sign(w) + F_V * w


class Spinner(ac.Component):
    housing = rot.Fixed()
    friction = StribeckFriction(F_c=F_C, F_s=F_S, v_s=V_S, F_v=F_V)
    damper = rot.Damper(d=D)
    wheel = rot.Inertia(J=J)
    drive = rot.ConstantTorque(tau_constant=TAU)

    def equations(self):
        return [ac.connect(self.housing.flange, self.friction.flange_a, self.damper.flange_a),
                ac.connect(self.friction.flange_b, self.damper.flange_b, self.wheel.flange_a),
                ac.connect(self.wheel.flange_b, self.drive.flange)]


@pytest.mark.parametrize("tau_0", [TAU, -TAU, 1.6])
@pytest.mark.parametrize("w_guess", [0.0, -3.0, 3.0, 40.0])
def test_stribeck_equilibrium_speed(tau_0, w_guess):
    """|tau_0| > F_s: the speed solves tau_0 = tau_f(w) + d w on the side of tau_0 (one
    root: the curve is below |tau_0| at w = 0+ and stays so until the viscous term wins), from
    a guess at rest (sgn = 0), on the wrong side, or beyond."""
    model = Spinner(drive={"tau_constant": tau_0})
    op = steady_state(model, hold=["wheel.phi"], guess={"wheel.w": w_guess})
    sign = np.sign(tau_0)
    w_star = sign * brentq(lambda w: stribeck(w) + D * w - abs(tau_0), 1e-12, 100.0,
                           xtol=1e-15, rtol=1e-15)
    assert op["wheel.w"] == pytest.approx(w_star, rel=1e-10)
    assert op["friction.tau"] + op["damper.tau"] == pytest.approx(tau_0, rel=1e-10)
    assert op["friction.tau"] == pytest.approx(stribeck(w_star), rel=1e-10)
    assert abs(op["der(wheel.w)"]) < 1e-10 * abs(tau_0) / J


def test_no_equilibrium_of_the_stribeck_map_names_its_relations():
    """|tau_0| < F_c: a static Stribeck map with sgn(0) = 0 has no equilibrium (the body
    would stick, which the map cannot do); the error says which relations failed."""
    model = Spinner(drive={"tau_constant": 0.5 * F_C})
    with pytest.raises(SteadyStateError, match=r"friction\.w [<>] 0") as err:
        steady_state(model, hold=["wheel.phi"])
    assert any("friction.w" in text for text in err.value.relations)
