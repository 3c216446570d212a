"""Causal signal blocks usable inside acausal models (Modelica.Blocks)."""
from ... import _lazy_exports

__all__ = ["SO", "SISO", "SI2SO", "SignalSource", "Constant", "Step", "Ramp", "Sine",
           "Pulse", "Gain", "Add", "Feedback", "Product", "Integrator", "Derivative",
           "FirstOrder", "SecondOrder", "TransferFunction", "PI", "PID", "Limiter",
           "Saturation", "DeadZone", "CombiTimeTable", "CombiTable1D", "CombiTable2D",
           "PadeDelay", "FixedDelay"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".continuous": ("PI", "PID", "Derivative", "FirstOrder", "Integrator", "SecondOrder",
                    "TransferFunction"),
    ".delays": ("FixedDelay", "PadeDelay"),
    ".interfaces": ("SI2SO", "SISO", "SO", "SignalSource"),
    ".math": ("Add", "Feedback", "Gain", "Product"),
    ".nonlinear": ("DeadZone", "Limiter", "Saturation"),
    ".sources": ("Constant", "Pulse", "Ramp", "Sine", "Step"),
    ".tables": ("CombiTable1D", "CombiTable2D", "CombiTimeTable"),
})
