"""Utilities of the translational examples (Modelica.Mechanics.Translational.Examples
.Utilities, MSL v4.0.0)."""
import numpy as np

__all__ = ["GenerateStribeckFrictionTable"]


def GenerateStribeckFrictionTable(F_prop, F_Coulomb, F_Stribeck, fexp, v_max, nTable=100):
    """The Stribeck friction curve as a table for ``SupportFriction`` (MSL
    Examples.Utilities.GenerateStribeckFrictionTable): nTable rows [v, f], v from 0 to
    v_max evenly, f = F_Coulomb + F_prop v + F_Stribeck exp(-fexp v)."""
    if int(nTable) != nTable or nTable < 2:
        raise ValueError(f"GenerateStribeckFrictionTable: nTable must be an integer >= 2, "
                         f"not {nTable!r}")
    v = v_max * np.arange(int(nTable)) / (int(nTable) - 1)
    return np.column_stack([v, F_Coulomb + F_prop * v + F_Stribeck * np.exp(-fexp * v)])
