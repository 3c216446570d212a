"""1-D rotational mechanics."""
from .components import (Damper, ElasticGearWithDeadzone, Fixed, GearWithBacklash, IdealGear,
                         IdealGearR2T, IdealRollingWheel, Inertia, RackAndPinion, Spring,
                         SpringDamper)
from .interfaces import (PartialAbsoluteSensor, PartialCompliant, PartialElementaryOneFlange,
                         PartialElementaryRotationalToTranslational, PartialRelativeSensor,
                         PartialTwoFlanges)
from .sensors import (AngleSensor, PowerSensor, RelAngleSensor, RelSpeedSensor, SpeedSensor,
                      TorqueSensor)
from .sources import ConstantSpeed, ConstantTorque, Position, Speed, StepTorque, Torque

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryRotationalToTranslational", "Fixed", "Inertia", "Spring",
           "Damper", "SpringDamper", "IdealGear", "IdealGearR2T", "IdealRollingWheel",
           "RackAndPinion", "ElasticGearWithDeadzone", "GearWithBacklash", "ConstantTorque",
           "StepTorque", "Torque", "ConstantSpeed", "Speed", "Position", "AngleSensor",
           "SpeedSensor", "RelAngleSensor", "RelSpeedSensor", "TorqueSensor", "PowerSensor"]
