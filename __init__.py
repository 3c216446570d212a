"""acausal: object-oriented, port-based modelling and simulation of physical systems.

Write a model as components with ports, connect them like a schematic, and simulate::

    import acausal as ac
    res = ac.simulate(MyModel(), t_end=1.0)
    res["C1.v"]

See the README for the modelling language and the design.
"""
from .components import (Across, Component, Connection, Eq, Equation, InvalidConnection,
                         InvalidEquation, InvalidHierarchy, InvalidValue, ModelError,
                         NotInModel, Parameter, Port, Signal, Through, Variable, When,
                         connect, der, if_else, no_event, pre, ref, reinit, sign, time, when)
from .errors import InitializationFailed, SimulationError
from .result import Result
from .runtime import CompiledModel
from .simulation import compile, initial_values, simulate
from .analysis import (ModeWarning, OperatingPointError, StateSpace, SteadyStateError,
                       TransferFunctionWarning, energy_balance, estimate, is_passive,
                       linearize, linearize_symbolic, steady_state)

__all__ = ["Component", "Port", "Parameter", "Variable", "Across", "Through", "Signal",
           "Eq", "Equation", "der", "connect", "ref", "when", "When", "reinit", "pre",
           "Connection", "if_else", "no_event", "sign", "time",
           "compile", "simulate", "initial_values", "Result", "CompiledModel",
           "ModelError", "InvalidValue", "InvalidEquation", "InvalidConnection",
           "InvalidHierarchy", "NotInModel", "SimulationError", "InitializationFailed",
           "linearize", "linearize_symbolic", "StateSpace", "steady_state",
           "SteadyStateError", "OperatingPointError", "ModeWarning", "TransferFunctionWarning",
           "energy_balance", "is_passive", "estimate"]
