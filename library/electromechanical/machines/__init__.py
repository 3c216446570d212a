"""Electric machines as the MSL builds them (Modelica.Electrical.Machines): the DC
machines with their losses and thermal ambients; ``quasi_static`` holds the quasi-static
variants under the MSL's names."""
from .... import _lazy_exports

__all__ = ["DC_PermanentMagnet", "DC_ElectricalExcited", "DC_SeriesExcited",
           "PartialBasicMachine", "PartialBasicDCMachine", "AirGapDC", "CompoundDCExcitation",
           "InductorDC", "Friction", "Brush", "Core", "StrayLoad", "FlangeSupport",
           "brushVoltageDrop", "FrictionParameters", "CoreParameters", "StrayLoadParameters",
           "BrushParameters", "ThermalAmbientDCPM", "ThermalAmbientDCEE",
           "ThermalAmbientDCSE", "convertAlpha", "convertResistance"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".dc_machines": ("DC_PermanentMagnet", "DC_ElectricalExcited", "DC_SeriesExcited",
                     "PartialBasicMachine", "PartialBasicDCMachine"),
    ".components": ("AirGapDC", "CompoundDCExcitation", "InductorDC"),
    ".losses": ("Friction", "Brush", "Core", "StrayLoad", "FlangeSupport",
                "brushVoltageDrop"),
    ".records": ("FrictionParameters", "CoreParameters", "StrayLoadParameters",
                 "BrushParameters"),
    ".thermal": ("ThermalAmbientDCPM", "ThermalAmbientDCEE", "ThermalAmbientDCSE",
                 "convertAlpha", "convertResistance"),
}, submodules=("quasi_static",))
