"""Analysis of compiled models: linearization, steady state, energy, estimation."""
from .energy import (EnergyBalance, Passivity, energy_balance, is_passive,
                     register_dissipation, register_storage)
from .estimate import Estimate, estimate
from .linearize import linearize
from .operating import OperatingPoint, SteadyStateError, steady_state
from .statespace import Margins, StateSpace

__all__ = ["linearize", "steady_state", "estimate", "energy_balance", "is_passive",
           "register_storage", "register_dissipation", "OperatingPoint",
           "SteadyStateError", "StateSpace", "Margins", "Estimate", "EnergyBalance",
           "Passivity"]
