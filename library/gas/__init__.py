"""Gas: pneumatic volumes, cylinders, throttles and sources, and the Moore-Greitzer
compression system (Egeland & Gravdahl 14.1.2, 14.4.5)."""
from ... import _lazy_exports

__all__ = ["PartialOnePort", "PartialTwoPort", "polytropic_density", "signed_sqrt",
           "GasVolume", "PneumaticCylinder", "Throttle", "CompressibleThrottle",
           "LaminarThrottle",
           "FixedPressure", "PressureSource", "ConstantMassFlow", "MassFlowSource",
           "MooreGreitzerCompressor", "Plenum", "CompressorThrottle", "Ambient"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".compressors": ("Ambient", "CompressorThrottle", "MooreGreitzerCompressor", "Plenum"),
    ".interfaces": ("PartialOnePort", "PartialTwoPort", "polytropic_density", "signed_sqrt"),
    ".restrictions": ("CompressibleThrottle", "LaminarThrottle", "Throttle"),
    ".sources": ("ConstantMassFlow", "FixedPressure", "MassFlowSource", "PressureSource"),
    ".volumes": ("GasVolume", "PneumaticCylinder"),
})
