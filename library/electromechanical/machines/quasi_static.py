"""Quasi-static DC machines (Modelica.Electrical.Machines.BasicMachines.
QuasiStaticDCMachines, MSL v4.0.0): the DC machines without electrical transients (the
armature inductance and the excitation's induced voltage are left out, quasiStatic =
true); the mechanical ones remain.  The classes keep the MSL's names, so they are used
through the module, as the MSL's package: ``quasi_static.DC_PermanentMagnet()``.
"""
from . import dc_machines

__all__ = ["DC_PermanentMagnet", "DC_ElectricalExcited", "DC_SeriesExcited"]


class DC_PermanentMagnet(dc_machines.DC_PermanentMagnet):
    """Quasi-static permanent magnet DC machine (QuasiStaticDCMachines.DC_PermanentMagnet)."""

    quasiStatic = True


class DC_ElectricalExcited(dc_machines.DC_ElectricalExcited):
    """Quasi-static electrically excited DC machine (QuasiStaticDCMachines.
    DC_ElectricalExcited)."""

    quasiStatic = True


class DC_SeriesExcited(dc_machines.DC_SeriesExcited):
    """Quasi-static series excited DC machine (QuasiStaticDCMachines.DC_SeriesExcited)."""

    quasiStatic = True
