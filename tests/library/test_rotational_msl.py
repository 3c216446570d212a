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
