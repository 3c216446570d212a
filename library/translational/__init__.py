"""1-D translational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialRigid", "PartialCompliant",
           "PartialCompliantWithRelativeStates", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "PartialElementaryTwoFlangesAndSupport",
           "PartialFriction", "Fixed", "Mass", "Rod", "ElastoGap", "MassWithStop",
           "Spring", "Damper", "SpringDamper", "Brake", "SupportFriction",
           "MassWithStopAndFriction", "ConstantForce", "ForceStep", "Force", "Force2",
           "LinearSpeedDependentForce", "QuadraticSpeedDependentForce", "SignForce", "EddyCurrentForce", "ConstantSpeed",
           "Speed", "Accelerate", "Position", "PositionSensor", "SpeedSensor", "AccSensor",
           "RelPositionSensor", "RelSpeedSensor", "RelAccSensor", "ForceSensor", "PowerSensor",
           "MultiSensor", "RollingResistance", "Vehicle"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Damper", "ElastoGap", "Fixed", "Mass", "MassWithStop", "Rod", "Spring",
                    "SpringDamper"),
    ".friction": ("Brake", "MassWithStopAndFriction", "PartialFriction", "SupportFriction"),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialCompliantWithRelativeStates",
                    "PartialElementaryOneFlange", "PartialElementaryOneFlangeAndSupport",
                    "PartialElementaryTwoFlangesAndSupport", "PartialRelativeSensor",
                    "PartialRigid", "PartialTwoFlanges"),
    ".vehicle": ("RollingResistance", "Vehicle"),
    ".sensors": ("AccSensor", "ForceSensor", "MultiSensor", "PositionSensor", "PowerSensor",
                 "RelAccSensor", "RelPositionSensor", "RelSpeedSensor", "SpeedSensor"),
    ".sources": ("Accelerate", "SignForce", "EddyCurrentForce", "ConstantForce", "ConstantSpeed", "Force", "Force2",
                 "LinearSpeedDependentForce", "Position", "QuadraticSpeedDependentForce",
                 "Speed", "ForceStep"),
})
