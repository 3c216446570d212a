"""Media properties (Modelica.Thermal.FluidHeatFlow.Media, MSL v4.0.0): constant
density, heat capacities, thermal conductivity and kinematic viscosity of a coolant.

A medium is a record: a component with parameters only.  A component of the package
takes its medium where it is made, ``Pipe(medium=Water())`` (the MSL's
``medium=FluidHeatFlow.Media.Water()``), and keeps its own copy as its sub-component
``medium``, whose parameters its equations read (``self.medium.rho``) and which can be
modified like any other (``Pipe(medium=Water(rho=1000.0))``).  The MSL's ``lambda`` is
``lambda_`` here (``lambda`` is a Python keyword).
"""
import acausal as ac

__all__ = ["Medium", "Water", "Water_10degC", "Water_90degC", "Air_30degC", "Air_70degC",
           "Gylcol20_20degC", "Gylcol50_20degC", "MineralOil"]


class Medium(ac.Component):
    """Record of a medium's properties (Modelica.Thermal.FluidHeatFlow.Media.Medium);
    the defaults (all 1) are the MSL's."""

    rho = ac.Parameter(1.0, unit="kg/m3", description="density")
    cp = ac.Parameter(1.0, unit="J/(kg.K)",
                      description="specific heat capacity at constant pressure")
    cv = ac.Parameter(1.0, unit="J/(kg.K)",
                      description="specific heat capacity at constant volume")
    lambda_ = ac.Parameter(1.0, unit="W/(m.K)", description="thermal conductivity")
    nu = ac.Parameter(1.0, unit="m2/s", description="kinematic viscosity")


def _medium(name: str, doc: str, rho, cp, cv, lambda_, nu) -> type:
    """A Medium with other defaults (the MSL's ``extends Medium(rho=..., ...)``)."""
    values = dict(rho=rho, cp=cp, cv=cv, lambda_=lambda_, nu=nu)
    body = {"__doc__": doc, "__module__": __name__}
    for key, value in values.items():
        base = vars(Medium)[key]
        body[key] = ac.Parameter(value, unit=base.unit, description=base.description)
    return type(name, (Medium,), body)


Water = _medium("Water", "Water at 30 degC and 1 bar (Media.Water).",
                995.6, 4177.0, 4177.0, 0.615, 0.8e-6)
Water_10degC = _medium("Water_10degC", "Water at 10 degC and 1 bar (Media.Water_10degC).",
                       999.7, 4192.0, 4192.0, 0.588, 1.307e-6)
Water_90degC = _medium("Water_90degC", "Water at 90 degC and 1 bar (Media.Water_90degC).",
                       965.3, 4205.0, 4205.0, 0.676, 0.347e-6)
Air_30degC = _medium("Air_30degC", "Air at 30 degC and 1 bar (Media.Air_30degC).",
                     1.149, 1007.0, 720.0, 0.0264, 16.3e-6)
Air_70degC = _medium("Air_70degC", "Air at 70 degC and 1 bar (Media.Air_70degC).",
                     1.015, 1010.0, 723.0, 0.0293, 20.3e-6)
Gylcol20_20degC = _medium("Gylcol20_20degC", "Glycol:water 20:80 at 20 degC and 1 bar "
                          "(Media.Gylcol20_20degC, the MSL's spelling).",
                          1028.0, 3910.0, 3910.0, 0.523, 1.69e-6)
Gylcol50_20degC = _medium("Gylcol50_20degC", "Glycol:water 50:50 at 20 degC and 1 bar "
                          "(Media.Gylcol50_20degC, the MSL's spelling).",
                          1078.0, 3300.0, 3300.0, 0.405, 3.98e-6)
MineralOil = _medium("MineralOil", "Mineral oil at 60 degC and 1 bar (Media.MineralOil).",
                     868.0, 2010.0, 2010.0, 0.14, 81.8e-6)
