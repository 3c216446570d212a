"""Connectors of every domain: what a port carries and how ports connect."""
from .base import Port, SignalPort
from .electrical import Pin, PositivePin, NegativePin
from .mechanical import RotationalFlange, TranslationalFlange
from .planar import Frame
from .fluid import FluidPort
from .gas import GasPort, NormalizedGasPort
from .thermal import HeatPort
from .fluidheatflow import FlowPort
from .signal import (BooleanInput, BooleanOutput, IntegerInput, IntegerOutput, RealInput,
                     RealOutput)

__all__ = ["Port", "SignalPort", "Pin", "PositivePin", "NegativePin", "RotationalFlange",
           "TranslationalFlange", "Frame", "FluidPort", "GasPort",
           "NormalizedGasPort", "HeatPort", "FlowPort", "RealInput", "RealOutput",
           "BooleanInput", "BooleanOutput", "IntegerInput", "IntegerOutput"]
