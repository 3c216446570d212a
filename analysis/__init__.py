"""Analysis of compiled models: linearization, steady state, energy, estimation."""
from .energy import (EnergyBalance, Passivity, energy_balance, is_passive,
                     register_dissipation, register_storage)
from .estimate import Estimate, estimate
from .grid import linearize_grid
from .linearize import linearize
from .operating import OperatingPoint, steady_state
from .sensitivity import output_sensitivities, simulate_sensitivities
from .statespace import Margins, StateSpace
from .symbolic import SymbolicStateSpace, linearize_symbolic
from ..errors import (ModeConflict, ModeWarning, OperatingPointError, SteadyStateError,
                      TransferFunctionWarning)

__all__ = ["linearize", "linearize_grid", "linearize_symbolic", "steady_state", "estimate",
           "energy_balance", "is_passive", "register_storage", "register_dissipation", "OperatingPoint",
           "SteadyStateError", "StateSpace", "Margins", "Estimate", "EnergyBalance",
           "Passivity", "SymbolicStateSpace", "simulate_sensitivities",
           "output_sensitivities", "OperatingPointError", "ModeConflict", "ModeWarning",
           "TransferFunctionWarning"]
