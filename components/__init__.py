"""The modelling language: Component, Parameter, Variable, der, Eq, connect.

Components, ports and declarations are plain Python; the symbolic vocabulary
(``Eq``, ``der``, ``time``, ...) is sympy and is imported on first use, so defining
component classes does not load sympy (their symbols and equations do).
"""
from .component import (AbsentComponent, Component, Connection, InvalidConnection,
                        InvalidEquation, InvalidHierarchy, InvalidInheritance, InvalidValue,
                        MissingInput, ModelError, NotInModel, Port, connect)
from .conditional import Conditional
from .initialization import Init
from .declarations import Across, Parameter, Signal, Through, Variable, ref
from .inheritance import replaces
from .units import UnitError, UnitWarning
from .. import _lazy_exports

__all__ = ["Component", "Port", "Connection", "connect", "ModelError", "InvalidValue",
           "InvalidEquation", "InvalidConnection", "InvalidHierarchy", "NotInModel",
           "InvalidIndex", "InvalidInheritance", "UnitError", "UnitWarning", "replaces",
           "Parameter", "Variable", "Across", "Through", "Signal", "ref", "Eq", "Equation",
           "der", "if_else", "no_event", "delay", "when", "When", "reinit", "pre", "sign",
           "time", "sample", "assign", "edge", "change", "initial", "integer", "Conditional",
           "AbsentComponent", "MissingInput", "Init"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".arrays": ("InvalidIndex",),
    ".symbols": ("Eq", "Equation", "When", "delay", "der", "if_else", "no_event", "reinit",
                 "sign", "time", "when", "sample", "assign"),
    ".logic": ("pre", "edge", "change", "initial", "integer"),
})
