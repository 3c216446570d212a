"""Rotational components after the MSL (Modelica.Mechanics.Rotational v4.0.0)."""
import pytest

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr


def test_phi_nominal_and_s_nominal_scale_the_relative_position():
    assert rot.SpringDamper().variable_attributes("phi_rel").nominal == 1e-4
    assert rot.SpringDamper(phi_nominal=1.0).variable_attributes("phi_rel").nominal == 1.0
    assert rot.ElastoBacklash(phi_nominal=0.5).variable_attributes("phi_rel").nominal == 0.5
    # below machine epsilon the nominal is 1, as in the MSL
    assert rot.Damper(phi_nominal=0.0).variable_attributes("phi_rel").nominal == 1.0
    assert tr.ElastoGap(s_nominal=1e-3).variable_attributes("s_rel").nominal == 1e-3
    # an explicit nominal of the variable takes precedence (applied when bound in a model)
    sd = rot.SpringDamper(phi_nominal=1.0, phi_rel={"nominal": 2.0})
    sd._bind()
    assert sd.variable_attributes("phi_rel").nominal == 2.0
    with pytest.raises(ac.InvalidValue, match="phi_nominal"):
        rot.SpringDamper(phi_nominal=-1.0)


def test_a_brake_on_a_free_housing_conserves_the_angular_momentum_of_the_pair():
    import numpy as np
    J1, J2, W0, FN = 1.0, 3.0, 4.0, 2.0
    from acausal.library.blocks import Constant

    class Pair(ac.Component):
        shaft = rot.Inertia(J=J1, phi={"start": 0.0, "fixed": True},
                            w={"start": W0, "fixed": True})
        brake = rot.Brake(fn_max=FN, useSupport=True, w={"start": W0})
        housing = rot.Inertia(J=J2, phi={"start": 0.0, "fixed": True},
                              w={"start": 0.0, "fixed": True})
        press = Constant(k=1.0)

        def equations(self):
            return [ac.connect(self.shaft.flange_b, self.brake.flange_a),
                    ac.connect(self.brake.support, self.housing.flange_a),
                    ac.connect(self.press.y, self.brake.f_normalized)]

    t = np.linspace(0, 4, 41)
    res = ac.simulate(Pair(), t_end=4.0, rtol=1e-10, atol=1e-12, t_eval=t)
    L = J1 * res["shaft.w"] + J2 * res["housing.w"]
    assert np.max(np.abs(L - J1 * W0)) < 1e-9 * J1 * W0
    # sliding: the brake torque mu fn = 0.5 FN slows the shaft and spins the housing
    # until the relative speed is zero at t* = W0 / (0.5 FN (1/J1 + 1/J2)); then locked
    t_star = W0 / (0.5 * FN * (1 / J1 + 1 / J2))
    w_common = J1 * W0 / (J1 + J2)
    w_shaft = np.where(t < t_star, W0 - 0.5 * FN / J1 * t, w_common)
    assert np.max(np.abs(res["shaft.w"] - w_shaft)) < 1e-8 * W0
    assert np.max(np.abs(res["brake.w"] - (res["shaft.w"] - res["housing.w"]))) < 1e-9 * W0


def _braked(source, w0, J=2.0):
    class Braked(ac.Component):
        wheel = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True},
                            w={"start": w0, "fixed": True})
        brake = source

        def equations(self):
            return [ac.connect(self.brake.flange, self.wheel.flange_a)]

    return Braked()


def test_an_eddy_current_brake_follows_its_invariant_and_its_loss_is_the_kinetic_energy():
    import numpy as np
    from acausal.analysis import energy_balance
    J, W0, TN, WN, A20, T, TREF = 2.0, 20.0, 100.0, 10.0, 0.0039, 353.15, 293.15
    model = _braked(rot.EddyCurrentTorque(tau_nominal=TN, w_nominal=WN, alpha20=A20, T=T,
                                          TRef=TREF), W0, J)
    t = np.linspace(0, 1, 51)
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    # J w' = -2 TN (w/wn)/(1 + (w/wn)^2), wn = WN (1 + alpha (T - TRef)):
    # ln w + w^2/(2 wn^2) + 2 TN t/(J wn) is constant
    alpha = A20 / (1 + A20 * (TREF - 293.15))
    wn = WN * (1 + alpha * (T - TREF))
    w = res["wheel.w"]
    inv = np.log(w) + w**2 / (2 * wn**2) + 2 * TN * t / (J * wn)
    assert np.max(np.abs(inv - inv[0])) < 1e-8 * abs(inv[0])
    assert w[-1] < 0.2 * W0
    assert not energy_balance(res, model).violations


def test_a_sign_torque_with_linear_regularization_brakes_linearly_then_exponentially():
    import numpy as np
    J, W0, T0, WR = 2.0, 3.0, 4.0, 0.5
    model = _braked(rot.SignTorque(tau_nominal=-T0, w0=WR, reg="Linear"), W0, J)
    t = np.linspace(0, 2, 81)
    res = ac.simulate(model, t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    t1 = (W0 - WR) * J / T0                       # constant torque down to w0
    w = np.where(t < t1, W0 - T0 / J * t, WR * np.exp(-T0 * (t - t1) / (J * WR)))
    assert np.max(np.abs(res["wheel.w"] - w)) < 1e-8 * W0
    with pytest.raises(ac.ModelError, match="reg must be one of"):
        rot.SignTorque(reg="Cubic")
