"""Causal signal blocks usable inside acausal models (Modelica.Blocks)."""
from ... import _lazy_exports

__all__ = ["SO", "SISO", "SI2SO", "SignalSource", "Constant", "Step", "Ramp", "Sine",
           "Cosine", "ExpSine", "Pulse", "Trapezoid", "Gain", "Add", "Add3", "Feedback",
           "Product", "Division", "Abs", "Sqrt", "Min", "Max", "Integrator", "Der", "Derivative",
           "FirstOrder", "SecondOrder", "TransferFunction", "PI", "PID", "Limiter",
           "Saturation", "DeadZone", "CombiTimeTable", "CombiTable1D", "CombiTable2D",
           "PadeDelay", "FixedDelay", "Filter", "CriticalDamping", "SlewRateLimiter", "Sinc",
           "SineVariableFrequencyAndAmplitude", "CosineVariableFrequencyAndAmplitude",
           "KinematicPTP", "LimPID", "InverseBlockConstraints", "MultiProduct",
           "RectangularToPolar", "Pythagoras", "Mean", "RootMeanSquare", "Harmonic",
           "TotalHarmonicDistortion"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".continuous": ("PI", "PID", "Der", "Derivative", "FirstOrder", "Integrator", "SecondOrder",
                    "TransferFunction"),
    ".delays": ("FixedDelay", "PadeDelay"),
    ".controllers": ("LimPID",),
    ".harmonics": ("MultiProduct", "RectangularToPolar", "Pythagoras", "Mean",
                   "RootMeanSquare", "Harmonic", "TotalHarmonicDistortion"),
    ".filters": ("Filter", "CriticalDamping"),
    ".interfaces": ("SI2SO", "SISO", "SO", "SignalSource"),
    ".math": ("Abs", "Add", "Add3", "Division", "Feedback", "Gain", "Max", "Min", "Product",
              "Sqrt", "InverseBlockConstraints"),
    ".nonlinear": ("DeadZone", "Limiter", "Saturation", "SlewRateLimiter"),
    ".sources": ("Constant", "Cosine", "ExpSine", "Pulse", "Ramp", "Sine", "Step",
                 "Trapezoid", "Sinc", "SineVariableFrequencyAndAmplitude",
                 "CosineVariableFrequencyAndAmplitude", "KinematicPTP"),
    ".tables": ("CombiTable1D", "CombiTable2D", "CombiTimeTable"),
})
