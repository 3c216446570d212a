"""DAE integrators: variable-order BDF, consistent initialization and events."""
from .base import (DAEProblem, EventAction, InitializationFailed, SimulationError,
                   SolverOutput, SolverStats)
from .bdf import BDF
from .driver import integrate

__all__ = ["BDF", "integrate", "DAEProblem", "SimulationError", "InitializationFailed",
           "SolverOutput", "SolverStats", "EventAction"]
