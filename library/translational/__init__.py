"""1-D translational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialRigid", "PartialCompliant",
           "PartialCompliantWithRelativeStates", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "PartialElementaryTwoFlangesAndSupport",
           "PartialFriction", "Fixed", "Mass", "Rod", "ElastoGap", "MassWithStop",
           "Spring", "Damper", "SpringDamper", "Brake", "SupportFriction",
           "MassWithStopAndFriction", "RollingResistance", "Vehicle",
           "GeneralForceToPositionAdaptor", "GeneralPositionToForceAdaptor",
           "ConstantForce", "ForceStep", "Force", "Force2",
           "LinearSpeedDependentForce", "QuadraticSpeedDependentForce", "SignForce",
           "EddyCurrentForce", "ConstantSpeed", "Speed", "Accelerate", "Position",
           "PositionSensor", "SpeedSensor", "AccSensor", "RelPositionSensor",
           "RelSpeedSensor", "RelAccSensor", "ForceSensor", "PowerSensor", "MultiSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".adaptors": ("GeneralForceToPositionAdaptor", "GeneralPositionToForceAdaptor"),
    ".components": ("Damper", "ElastoGap", "Fixed", "Mass", "MassWithStop", "Rod", "Spring",
                    "SpringDamper"),
    ".friction": ("Brake", "MassWithStopAndFriction", "PartialFriction", "SupportFriction"),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialCompliantWithRelativeStates",
                    "PartialElementaryOneFlange", "PartialElementaryOneFlangeAndSupport",
                    "PartialElementaryTwoFlangesAndSupport", "PartialRelativeSensor",
                    "PartialRigid", "PartialTwoFlanges"),
    ".sensors": ("AccSensor", "ForceSensor", "MultiSensor", "PositionSensor", "PowerSensor",
                 "RelAccSensor", "RelPositionSensor", "RelSpeedSensor", "SpeedSensor"),
    ".sources": ("Accelerate", "ConstantForce", "ConstantSpeed", "EddyCurrentForce", "Force",
                 "Force2", "ForceStep", "LinearSpeedDependentForce", "Position",
                 "QuadraticSpeedDependentForce", "SignForce", "Speed"),
    ".vehicle": ("RollingResistance", "Vehicle"),
})
