"""1-D rotational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialCompliantWithRelativeStates",
           "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "PartialElementaryTwoFlangesAndSupport",
           "PartialElementaryRotationalToTranslational", "Fixed", "Inertia", "Disc", "Spring",
           "Damper", "SpringDamper", "IdealGear", "IdealPlanetary", "IdealGearR2T",
           "IdealRollingWheel",
           "RackAndPinion", "ElastoBacklash", "ElastoBacklash2", "ElasticGearWithDeadzone",
           "GearWithBacklash",
           "Clutch", "Brake", "OneWayClutch", "BearingFriction", "PartialFriction",
           "ConstantTorque",
           "TorqueStep", "Torque", "Torque2", "LinearSpeedDependentTorque",
           "QuadraticSpeedDependentTorque", "ConstantSpeed", "Speed", "Accelerate", "Position",
           "AngleSensor", "SpeedSensor", "AccSensor", "RelAngleSensor", "RelSpeedSensor",
           "RelAccSensor", "TorqueSensor", "PowerSensor", "MultiSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".clutches": ("BearingFriction", "Brake", "Clutch", "OneWayClutch"),
    ".backlash": ("ElastoBacklash", "ElastoBacklash2", "ElasticGearWithDeadzone",
                  "GearWithBacklash"),
    ".components": ("Damper", "Disc", "Fixed", "IdealGear", "IdealGearR2T", "IdealPlanetary",
                    "IdealRollingWheel", "Inertia", "RackAndPinion", "Spring", "SpringDamper"),
    ".friction_modes": ("PartialFriction",),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialCompliantWithRelativeStates",
                    "PartialElementaryOneFlange",
                    "PartialElementaryOneFlangeAndSupport",
                    "PartialElementaryRotationalToTranslational",
                    "PartialElementaryTwoFlangesAndSupport", "PartialRelativeSensor",
                    "PartialTwoFlanges"),
    ".sensors": ("AccSensor", "AngleSensor", "MultiSensor", "PowerSensor", "RelAccSensor",
                 "RelAngleSensor", "RelSpeedSensor", "SpeedSensor", "TorqueSensor"),
    ".sources": ("Accelerate", "ConstantSpeed", "ConstantTorque",
                 "LinearSpeedDependentTorque", "Position", "QuadraticSpeedDependentTorque",
                 "Speed", "TorqueStep", "Torque", "Torque2"),
})
