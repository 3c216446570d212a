"""1-D translational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialCompliantWithRelativeStates",
           "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "Fixed", "Mass", "MassWithStop",
           "Spring", "Damper", "SpringDamper", "ConstantForce", "StepForce", "Force",
           "ConstantSpeed", "Speed", "Position", "PositionSensor", "SpeedSensor", "RelPositionSensor",
           "ForceSensor", "PowerSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Damper", "Fixed", "Mass", "MassWithStop", "Spring", "SpringDamper"),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialCompliantWithRelativeStates",
                    "PartialElementaryOneFlange", "PartialElementaryOneFlangeAndSupport",
                    "PartialRelativeSensor",
                    "PartialTwoFlanges"),
    ".sensors": ("ForceSensor", "PositionSensor", "PowerSensor", "RelPositionSensor",
                 "SpeedSensor"),
    ".sources": ("ConstantForce", "ConstantSpeed", "Force", "Position", "Speed",
                 "StepForce"),
})
