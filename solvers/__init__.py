"""DAE integrators: variable-order BDF, consistent initialization and events."""
from .. import _lazy_exports

__all__ = ["BDF", "integrate", "DAEProblem", "LoopModel", "SimulationError",
           "InitializationFailed", "SolverOutput", "SolverStats", "EventAction"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".base": ("DAEProblem", "EventAction", "InitializationFailed", "LoopModel",
              "SimulationError", "SolverOutput", "SolverStats"),
    ".bdf": ("BDF",),
    ".driver": ("integrate",),
})
