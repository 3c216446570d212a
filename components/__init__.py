"""The modelling language: Component, Parameter, Variable, der, Eq, connect."""
from .component import (Component, Connection, InvalidConnection, InvalidEquation,
                        InvalidHierarchy, InvalidValue, ModelError, NotInModel, Port, connect)
from .declarations import Across, Parameter, Signal, Through, Variable, ref
from .symbols import Eq, Equation, When, der, if_else, no_event, pre, reinit, sign, time, when

__all__ = ["Component", "Port", "Connection", "connect", "ModelError", "InvalidValue",
           "InvalidEquation", "InvalidConnection", "InvalidHierarchy", "NotInModel",
           "Parameter", "Variable", "Across", "Through", "Signal", "ref", "Eq", "Equation",
           "der", "if_else", "no_event", "when", "When", "reinit", "pre", "sign", "time"]
