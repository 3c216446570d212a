"""Electromechanical examples: DC motor drives of Egeland & Gravdahl ch. 3."""
from .controlled_motor import CurrentLoop, PositionLoop, VelocityLoop
from .dc_motor import DCMotorStep, DCMotorStepNoInductance
from .elastic_transmission import (ElasticTransmission, FreeElasticTransmission,
                                   LockedElasticTransmission)
from .geared_load import MotorGearLoad
from .two_motors import TwoMotorsElasticLoad

__all__ = ["DCMotorStep", "DCMotorStepNoInductance", "CurrentLoop", "VelocityLoop",
           "PositionLoop", "MotorGearLoad", "ElasticTransmission", "FreeElasticTransmission",
           "LockedElasticTransmission", "TwoMotorsElasticLoad"]
