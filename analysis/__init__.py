"""Analysis of compiled models: linearization, steady state, energy, estimation."""
from .estimate import Estimate, estimate
from .linearize import linearize
from .operating import OperatingPoint, SteadyStateError, steady_state
from .statespace import Margins, StateSpace

__all__ = ["linearize", "steady_state", "estimate", "OperatingPoint", "SteadyStateError",
           "StateSpace", "Margins", "Estimate"]
