"""acausal: object-oriented, port-based modelling and simulation of physical systems.

Write a model as components with ports, connect them like a schematic, and simulate::

    import acausal as ac
    res = ac.simulate(MyModel(), t_end=1.0)
    res["C1.v"]

See the README for the modelling language and the design.

The public names are imported on first use (PEP 562), so ``import acausal`` loads
neither sympy nor scipy: sympy comes with the first symbol or equation (or a library
module written with it), scipy with ``compile``, ``simulate`` and the analyses.
"""
from __future__ import annotations

import importlib
import sys

_EXPORTS = {
    ".components": ("Across", "Component", "Connection", "Eq", "Equation", "Parameter", "Port",
                    "Signal", "Through", "Variable", "When", "assign", "connect", "delay", "der",
                    "if_else", "no_event", "pre", "ref", "reinit", "replaces", "sample",
                    "sign", "time", "when", "edge", "change", "initial", "integer",
                    "Conditional", "Init", "PortGroup", "ExpandableConnector"),
    ".errors": ("ModelError", "InvalidValue", "InvalidEquation", "DiscreteVariableError",
                "InvalidConnection", "InvalidHierarchy", "InvalidInheritance", "InvalidIndex",
                "NotInModel", "AbsentComponent", "MissingInput", "UnitError",
                "StructuralError", "IndexReductionFailed", "StructurallySingular",
                "OverdeterminedModel", "UnderdeterminedModel", "SimulationError",
                "UnderdeterminedInitialization",
                "InitializationFailed", "BackendError", "CacheError", "CacheWarning",
                "InvalidArgument", "OperatingPointError",
                "SteadyStateError", "ModeConflict", "UnitWarning", "ModeWarning",
                "TransferFunctionWarning", "InitialConditionWarning"),
    ".result": ("Result",),
    ".runtime": ("CompiledModel",),
    ".simulation": ("compile", "initial_values", "simulate"),
    ".analysis": ("StateSpace", "energy_balance", "estimate", "is_passive", "linearize",
                  "linearize_grid", "linearize_symbolic", "steady_state"),
    ".fmi": ("export_fmu",),
    ".results_io": ("load_result",),
    ".display.animation": ("animate",),
    ".sweeps": ("sweep", "ensemble"),
    ".functions": ("sqrt", "exp", "log", "log10", "sin", "cos", "tan", "asin", "acos", "atan",
                   "atan2", "sinh", "cosh", "tanh", "abs", "min", "max", "pi"),
    ".components.userfunctions": ("function", "Function"),
}

__all__ = ["Component", "Port", "Parameter", "Variable", "Across", "Through", "Signal",
           "Eq", "Equation", "der", "connect", "ref", "when", "When", "reinit", "pre",
           "sample", "assign", "edge", "change", "initial", "integer", "Conditional",
           "AbsentComponent", "MissingInput", "Init", "PortGroup", "ExpandableConnector",
           "Connection", "if_else", "no_event", "delay", "sign", "time", "replaces",
           "compile", "simulate", "initial_values", "Result", "CompiledModel",
           "ModelError", "InvalidValue", "InvalidEquation", "DiscreteVariableError",
           "InvalidConnection", "InvalidHierarchy", "InvalidIndex", "InvalidInheritance",
           "NotInModel", "UnitError", "StructuralError", "IndexReductionFailed",
           "StructurallySingular", "OverdeterminedModel", "UnderdeterminedModel",
           "UnderdeterminedInitialization",
           "SimulationError", "InitializationFailed", "BackendError", "OperatingPointError",
           "SteadyStateError", "ModeConflict", "UnitWarning", "ModeWarning",
           "TransferFunctionWarning", "InitialConditionWarning",
           "linearize", "linearize_grid", "linearize_symbolic", "StateSpace", "steady_state",
           "energy_balance", "is_passive", "estimate", "CacheError", "CacheWarning",
           "InvalidArgument", "export_fmu",
           "load_result", "animate", "sweep", "ensemble", "sqrt", "exp", "log", "log10", "sin", "cos",
           "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "pi", "function",
           "Function"]
# ac.abs, ac.min and ac.max exist too, but not in __all__: `import *` must not shadow builtins


def _lazy_exports(namespace: dict, exports: dict, submodules=()) -> tuple:
    """``(__getattr__, __dir__)`` for the package whose globals are ``namespace``, with
    public names that live in submodules imported on first use (PEP 562).

    ``exports`` maps a relative submodule name to the names it provides; the first
    access imports the submodule and binds the name in the package, so later accesses
    are plain look-ups.  The submodules of ``exports`` and ``submodules`` stay reachable
    as attributes (``acausal.library.electrical.sources``), as they were when the
    package imported them eagerly.
    """
    package = namespace["__name__"]
    where = {name: module for module, names in exports.items() for name in names}
    modules = {m.lstrip(".") for m in exports} | set(submodules)

    def __getattr__(name: str):
        module = where.get(name)
        if module is not None:
            value = getattr(importlib.import_module(module, package), name)
            namespace[name] = value
            return value
        if name in modules:
            return importlib.import_module(f"{package}.{name}")
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__():
        return sorted(set(namespace) | set(where) | modules)

    return __getattr__, __dir__


__getattr__, __dir__ = _lazy_exports(globals(), _EXPORTS,
                                     submodules=("compiler", "ports", "solvers"))


# -- notebooks ---------------------------------------------------------------------------
# Jupyter shows a component, a compiled model, its index report, a result and a linear
# model as HTML (acausal.display).  The classes know nothing of their pictures: the
# renderers are registered here with IPython's HTML formatter, by class name (so nothing
# is imported until an object is shown), when acausal is imported in an IPython session.
_SHOWN = (("components.component", "Component"), ("runtime.model", "CompiledModel"),
          ("compiler.report", "IndexReport"), ("result", "Result"),
          ("analysis.statespace", "StateSpace"))


def _html(obj) -> str:
    from .display import show
    return show(obj).text


def _show_in_notebooks() -> None:
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if hasattr(ipython, "get_ipython") else None
    formatters = getattr(getattr(shell, "display_formatter", None), "formatters", {})
    html = formatters.get("text/html")
    if html is None:
        return
    for module, name in _SHOWN:
        html.for_type_by_name(f"{__name__}.{module}", name, _html)


_show_in_notebooks()
