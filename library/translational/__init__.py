"""1-D translational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialCompliantWithRelativeStates",
           "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "Fixed", "Mass", "Rod", "MassWithStop",
           "Spring", "Damper", "SpringDamper", "ConstantForce", "ForceStep", "Force", "Force2",
           "LinearSpeedDependentForce", "QuadraticSpeedDependentForce", "ConstantSpeed",
           "Speed", "Accelerate", "Position", "PositionSensor", "SpeedSensor", "AccSensor",
           "RelPositionSensor", "RelSpeedSensor", "RelAccSensor", "ForceSensor", "PowerSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Damper", "Fixed", "Mass", "MassWithStop", "Rod", "Spring",
                    "SpringDamper"),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialCompliantWithRelativeStates",
                    "PartialElementaryOneFlange", "PartialElementaryOneFlangeAndSupport",
                    "PartialRelativeSensor",
                    "PartialTwoFlanges"),
    ".sensors": ("AccSensor", "ForceSensor", "PositionSensor", "PowerSensor", "RelAccSensor",
                 "RelPositionSensor", "RelSpeedSensor", "SpeedSensor"),
    ".sources": ("Accelerate", "ConstantForce", "ConstantSpeed", "Force", "Force2",
                 "LinearSpeedDependentForce", "Position", "QuadraticSpeedDependentForce",
                 "Speed", "ForceStep"),
})
