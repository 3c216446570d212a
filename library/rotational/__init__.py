"""1-D rotational mechanics."""
from ... import _lazy_exports

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryRotationalToTranslational", "Fixed", "Inertia", "Spring",
           "Damper", "SpringDamper", "IdealGear", "IdealGearR2T", "IdealRollingWheel",
           "RackAndPinion", "ElasticGearWithDeadzone", "GearWithBacklash", "ConstantTorque",
           "StepTorque", "Torque", "ConstantSpeed", "Speed", "Position", "AngleSensor",
           "SpeedSensor", "RelAngleSensor", "RelSpeedSensor", "TorqueSensor", "PowerSensor",
           "Clutch", "Brake", "OneWayClutch", "BearingFriction", "PartialFriction"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".clutches": ("BearingFriction", "Brake", "Clutch", "OneWayClutch"),
    ".components": ("Damper", "ElasticGearWithDeadzone", "Fixed", "GearWithBacklash",
                    "IdealGear", "IdealGearR2T", "IdealRollingWheel", "Inertia",
                    "RackAndPinion", "Spring", "SpringDamper"),
    ".friction_modes": ("PartialFriction",),
    ".interfaces": ("PartialAbsoluteSensor", "PartialCompliant",
                    "PartialElementaryOneFlange",
                    "PartialElementaryRotationalToTranslational", "PartialRelativeSensor",
                    "PartialTwoFlanges"),
    ".sensors": ("AngleSensor", "PowerSensor", "RelAngleSensor", "RelSpeedSensor",
                 "SpeedSensor", "TorqueSensor"),
    ".sources": ("ConstantSpeed", "ConstantTorque", "Position", "Speed", "StepTorque",
                 "Torque"),
})
