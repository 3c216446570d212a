"""Causal signal blocks usable inside acausal models (Modelica.Blocks)."""
from ... import _lazy_exports

__all__ = ["SO", "SISO", "SI2SO", "SignalSource", "Constant", "Step", "Ramp", "Sine",
           "Cosine", "ExpSine", "Pulse", "Trapezoid", "Gain", "Add", "Add3", "Feedback",
           "Product", "Division", "Abs", "Sqrt", "Min", "Max", "Integrator", "Derivative",
           "FirstOrder", "SecondOrder", "TransferFunction", "PI", "PID", "Limiter",
           "Saturation", "DeadZone", "CombiTimeTable", "CombiTable1D", "CombiTable2D",
           "PadeDelay", "FixedDelay",
           # Boolean and Integer signals (logical, boolean_sources, integer_sources,
           # conversions; math_boolean and math_integer by module: their names are the MSL's)
           "And", "Or", "Xor", "Nor", "Nand", "Not", "Pre", "Edge", "FallingEdge", "Change",
           "GreaterThreshold", "GreaterEqualThreshold", "LessThreshold",
           "LessEqualThreshold", "Greater", "GreaterEqual", "Less", "LessEqual",
           "ZeroCrossing", "LogicalSwitch", "Switch", "Hysteresis", "OnOffController",
           "TriggeredTrapezoid", "Timer", "RSFlipFlop", "BooleanConstant", "BooleanStep",
           "BooleanPulse", "SampleTrigger", "BooleanTable", "BooleanExpression",
           "RadioButtonSource", "IntegerConstant", "IntegerStep", "IntegerTable",
           "BooleanToReal", "BooleanToInteger", "RealToBoolean", "IntegerToBoolean",
           "RealToInteger", "IntegerToReal"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".continuous": ("PI", "PID", "Derivative", "FirstOrder", "Integrator", "SecondOrder",
                    "TransferFunction"),
    ".delays": ("FixedDelay", "PadeDelay"),
    ".interfaces": ("SI2SO", "SISO", "SO", "SignalSource"),
    ".math": ("Abs", "Add", "Add3", "Division", "Feedback", "Gain", "Max", "Min", "Product",
              "Sqrt"),
    ".nonlinear": ("DeadZone", "Limiter", "Saturation"),
    ".sources": ("Constant", "Cosine", "ExpSine", "Pulse", "Ramp", "Sine", "Step",
                 "Trapezoid"),
    ".tables": ("CombiTable1D", "CombiTable2D", "CombiTimeTable"),
    ".logical": ("And", "Or", "Xor", "Nor", "Nand", "Not", "Pre", "Edge", "FallingEdge",
                 "Change", "GreaterThreshold", "GreaterEqualThreshold", "LessThreshold",
                 "LessEqualThreshold", "Greater", "GreaterEqual", "Less", "LessEqual",
                 "ZeroCrossing", "LogicalSwitch", "Switch", "Hysteresis", "OnOffController",
                 "TriggeredTrapezoid", "Timer", "RSFlipFlop"),
    ".boolean_sources": ("BooleanConstant", "BooleanStep", "BooleanPulse", "SampleTrigger",
                         "BooleanTable", "BooleanExpression", "RadioButtonSource"),
    ".integer_sources": ("IntegerConstant", "IntegerStep", "IntegerTable"),
    ".conversions": ("BooleanToReal", "BooleanToInteger", "RealToBoolean",
                     "IntegerToBoolean", "RealToInteger", "IntegerToReal"),
}, submodules=("math_boolean", "math_integer", "interaction", "boolean_interfaces"))
