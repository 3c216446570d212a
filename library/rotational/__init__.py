"""1-D rotational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialCompliantWithRelativeStates",
           "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "PartialElementaryTwoFlangesAndSupport",
           "PartialElementaryRotationalToTranslational", "Fixed", "Inertia", "Spring",
           "Damper", "SpringDamper", "IdealGear", "IdealGearR2T", "IdealRollingWheel",
           "RackAndPinion", "ElasticGearWithDeadzone", "GearWithBacklash", "ConstantTorque",
           "StepTorque", "Torque", "ConstantSpeed", "Speed", "Position", "AngleSensor",
           "SpeedSensor", "RelAngleSensor", "RelSpeedSensor", "TorqueSensor", "PowerSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Damper", "ElasticGearWithDeadzone", "Fixed", "GearWithBacklash",
                    "IdealGear", "IdealGearR2T", "IdealRollingWheel", "Inertia",
                    "RackAndPinion", "Spring", "SpringDamper"),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialCompliantWithRelativeStates",
                    "PartialElementaryOneFlange",
                    "PartialElementaryOneFlangeAndSupport",
                    "PartialElementaryRotationalToTranslational",
                    "PartialElementaryTwoFlangesAndSupport", "PartialRelativeSensor",
                    "PartialTwoFlanges"),
    ".sensors": ("AngleSensor", "PowerSensor", "RelAngleSensor", "RelSpeedSensor",
                 "SpeedSensor", "TorqueSensor"),
    ".sources": ("ConstantSpeed", "ConstantTorque", "Position", "Speed", "StepTorque",
                 "Torque"),
})
