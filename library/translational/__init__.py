"""1-D translational mechanics."""
from .components import Damper, Fixed, Mass, MassWithStop, Spring, SpringDamper
from .interfaces import (PartialAbsoluteSensor, PartialCompliant, PartialElementaryOneFlange,
                         PartialRelativeSensor, PartialTwoFlanges)
from .sensors import ForceSensor, PositionSensor, PowerSensor, RelPositionSensor, SpeedSensor
from .sources import ConstantForce, ConstantSpeed, Force, Position, Speed, StepForce

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor", "Fixed", "Mass", "MassWithStop",
           "Spring", "Damper", "SpringDamper", "ConstantForce", "StepForce", "Force",
           "ConstantSpeed", "Speed", "Position", "PositionSensor", "SpeedSensor", "RelPositionSensor",
           "ForceSensor", "PowerSensor"]
