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
