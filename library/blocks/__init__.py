"""Causal signal blocks usable inside acausal models (Modelica.Blocks)."""
from .continuous import (PI, PID, Derivative, FirstOrder, Integrator, SecondOrder,
                         TransferFunction)
from .interfaces import SI2SO, SISO, SO, SignalSource
from .math import Add, Feedback, Gain, Product
from .nonlinear import DeadZone, Limiter, Saturation
from .sources import Constant, Pulse, Ramp, Sine, Step

__all__ = ["SO", "SISO", "SI2SO", "SignalSource", "Constant", "Step", "Ramp", "Sine",
           "Pulse", "Gain", "Add", "Feedback", "Product", "Integrator", "Derivative",
           "FirstOrder", "SecondOrder", "TransferFunction", "PI", "PID", "Limiter",
           "Saturation", "DeadZone"]
