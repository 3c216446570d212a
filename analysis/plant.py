"""The model behind the user's object: a compiled model and the translation of the
user's names into its names (used by the operating points, linearization and the
symbolic linearization).

A model with top-level ``RealInput`` ports cannot be compiled on its own (an unconnected
input leaves it under-determined), so it is placed in a small harness that drives each
such input from parameters; names are translated both ways, so the user never sees it.
Parameters that linearize takes as inputs can likewise be *driven*: the component that
declares one is rebuilt with the parameter turned into a variable driven from
parameters (:func:`driven_class`), so that a model that differentiates it (through index
reduction) keeps its derivative.
"""
from __future__ import annotations

from contextlib import contextmanager

from ..components.component import Component
from ..components.declarations import Parameter, Variable
from ..components.symbols import Eq, time
from ..ports import RealInput, RealOutput
from ..runtime import CompiledModel

__all__ = ["Plant", "as_plant", "top_level_inputs", "compile_plant", "parameters_set",
           "constant_value", "driven_class"]


# -- the model behind the user's object ------------------------------------------------------
class Plant:
    """A compiled model and the translation of the user's names into its names.

    ``input_params`` maps each top-level RealInput of the user's component to the
    parameter of the harness that drives it.
    """

    def __init__(self, compiled, prefix: str = "", input_params=None, input_rates=None):
        self.compiled = compiled
        self.prefix = prefix
        self.input_params = dict(input_params or {})
        # input name -> (rate, accel, t_ref) parameters of its _InputValue
        self.input_rates = dict(input_rates or {})
        # the top-level inputs of a model compiled with them (runtime/inputs.py): their
        # values' places in p, set as constants here
        self.input_slots = {}
        drivers = getattr(compiled, "inputs", None)
        if drivers is not None:
            for n, k in zip(drivers.names, drivers.slots):
                self.input_slots[n] = self.input_slots[f"{n}.signal"] = int(k)

    @property
    def input_names(self) -> list:
        """The top-level inputs, by the user's names."""
        return [n for n in list(self.input_params) + list(self.input_slots)
                if not n.endswith(".signal")]

    def internal(self, name: str) -> str:
        if name in self.input_params:
            return self.input_params[name]
        if name.startswith("der(") and name.endswith(")"):
            return f"der({self.internal(name[4:-1])})"
        return self.prefix + name

    def external(self, name: str) -> str:
        if name.startswith("der(") and name.endswith(")"):
            return f"der({self.external(name[4:-1])})"
        return name[len(self.prefix):] if name.startswith(self.prefix) else name

    def parameter_index(self, name: str):
        """Index into ``compiled.p`` of a parameter or top-level input, else None."""
        if name in self.input_slots:
            return self.input_slots[name]
        internal = self.internal(name)
        names = self.compiled.param_names
        return names.index(internal) if internal in names else None


def as_plant(model, values=None) -> Plant:
    """The Plant for a Component, CompiledModel, Result, OperatingPoint or Plant."""
    if isinstance(model, Plant):
        return model
    if hasattr(model, "plant") and hasattr(model, "z"):         # an OperatingPoint
        return model.plant
    if isinstance(model, CompiledModel):
        return Plant(model)
    if hasattr(model, "compiled") and hasattr(model, "_z"):      # a Result
        return Plant(model.compiled)
    if isinstance(model, Component):
        return compile_plant(model, values or {})
    raise TypeError(f"expected a Component or a CompiledModel, got {type(model).__name__}")


def top_level_inputs(model: Component) -> list:
    """Names of the RealInput ports declared directly on a component."""
    return [name for name, child in model.children().items() if isinstance(child, RealInput)]


class _InputValue(Component):
    """Drives a top-level input from parameters, so that linearize can perturb it:

        y = k + rate (time - t_ref) + accel (time - t_ref)^2 / 2

    ``rate`` and ``accel`` are 0 except while linearize takes dF/d rate and dF/d accel
    at time = t_ref: there they are der(y) and der(y, 2), which index reduction puts
    into the equations of a model that differentiates its input (a ship whose rudder
    term is K (T_a der(delta) + delta))."""

    y = RealOutput()
    k = Parameter(1.0, description="value of the input")
    rate = Parameter(1.0, description="der of the input about t_ref (0 outside linearize)")
    accel = Parameter(1.0, description="second der of the input (0 outside linearize)")
    t_ref = Parameter(1.0, description="time about which rate and accel act")

    def equations(self):
        dt = time - self.t_ref
        return [Eq(self.y, self.k + self.rate * dt + self.accel * dt**2 / 2)]


class _Harness(Component):
    """The user's model with each top-level RealInput driven by an ``_InputValue``."""

    def __init__(self, plant, values):
        super().__init__()
        self.plant = plant
        self._inputs = list(values)
        for k, name in enumerate(self._inputs):
            setattr(self, f"input{k}", _InputValue(k=float(values[name])))

    def equations(self):
        return [_connect(getattr(self, f"input{k}").y, getattr(self.plant, name))
                for k, name in enumerate(self._inputs)]


def _connect(a, b):
    from ..components.component import connect
    return connect(a, b)


def compile_plant(model: Component, values: dict, unfreeze=(), driven=()) -> Plant:
    """Compile ``model`` (in a harness if it has top-level inputs).

    Parameters equal to 0 are structural zeros of the compiled model (not tunable), so
    the parameters to be perturbed (``unfreeze``, the harness's input values) are
    compiled as 1 and set to their value afterwards; they enter the equations
    additively, so the structure does not depend on the value.  The parameters named in
    ``driven`` (dotted paths) that can be are turned into driven variables
    (:func:`driven_class`); the others stay parameters.
    """
    from ..simulation import compile as compile_model
    names = top_level_inputs(model)
    vals = {n: float(values.get(n, values.get(f"{n}.signal", 0.0))) for n in names}
    mods = {}
    for path in unfreeze:
        _nested_set(mods, path.split("."), 1.0)
    args, kwargs = model._init_call[0], _merged(model._init_call[1], mods)
    root = type(model)(*args, **kwargs)
    root, drives = _drive_parameters(root, type(model)(*args, **kwargs), driven)
    if not names:
        plant = Plant(compile_model(root))
    else:
        compiled = compile_model(_Harness(root, {n: 1.0 for n in names}))
        params = {n: f"input{k}.k" for k, n in enumerate(names)}
        params.update({f"{n}.signal": p for n, p in params.items()})
        rates = {n: tuple(f"input{k}.{q}" for q in ("rate", "accel", "t_ref"))
                 for k, n in enumerate(names)}
        rates.update({f"{n}.signal": r for n, r in rates.items()})
        plant = Plant(compiled, "plant.", params, rates)
        for n in names:
            compiled.p[plant.parameter_index(n)] = vals[n]
            for q in rates[n]:          # compiled as 1 (tunable), off until linearize
                compiled.p[compiled.param_names.index(q)] = 0.0
    c = plant.compiled
    for path, value in drives.items():
        base = plant.prefix + path
        plant.input_params[path] = f"{base}_value"
        plant.input_rates[path] = tuple(f"{base}_{q}" for q in ("rate", "accel", "t_ref"))
        c.p[c.param_names.index(f"{base}_value")] = value
        for q in plant.input_rates[path]:
            c.p[c.param_names.index(q)] = 0.0
    for path in unfreeze:
        c.p[plant.parameter_index(path)] = 0.0
    return plant


_compile_plant = compile_plant


# -- driven parameters -------------------------------------------------------------------------
_DRIVEN: dict = {}


def driven_class(cls, name: str):
    """``cls`` with its parameter ``name`` turned into a variable driven as

        name = name_value + name_rate (time - name_t_ref) + name_accel (time - name_t_ref)^2 / 2

    (new parameters, the rates 0 outside linearize): the component's equations are
    those of ``cls`` (included as a base's), so where index reduction differentiates one
    that holds ``name``, its derivative is name_rate at time = name_t_ref instead of a
    silent 0."""
    key = (cls, name)
    if key not in _DRIVEN:
        def equations(self):
            dt = time - getattr(self, f"{name}_t_ref")
            drive = (getattr(self, f"{name}_value") + getattr(self, f"{name}_rate") * dt
                     + getattr(self, f"{name}_accel") * dt**2 / 2)
            return [Eq(getattr(self, name), drive)]

        ns = {name: Variable(description=f"parameter {name}, driven for linearization"),
              f"{name}_value": Parameter(1.0, description=f"value of {name}"),
              f"{name}_rate": Parameter(1.0, description=f"der({name}) (0 outside linearize)"),
              f"{name}_accel": Parameter(1.0, description=f"der({name}, 2) (0 outside)"),
              f"{name}_t_ref": Parameter(1.0, description="time about which the rates act"),
              "equations": equations, "__module__": cls.__module__,
              "__doc__": cls.__doc__}
        _DRIVEN[key] = type(cls.__name__, (cls,), ns)
    return _DRIVEN[key]


def _drive_parameters(root, probe, paths):
    """Replace, in the unbound ``root``, each component that declares a parameter named
    in ``paths`` by its driven class; {path: value} of those driven.  A parameter is left
    alone when its value is not a number, another parameter is bound to it (``ref``),
    or its component sits in a list."""
    if not paths:
        return root, {}
    probe._bind("")
    out = {}
    for path in paths:
        owner_path, _, name = path.rpartition(".")
        owner = _find(probe, owner_path)
        if owner is None or not isinstance(owner.declarations().get(name), Parameter) \
                or "[" in owner_path or _is_referenced(owner, name):
            continue
        value = owner.parameter_value(name)
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            continue
        fresh = _find(root, owner_path)
        args, kwargs = fresh._init_call
        extra = {f"{name}_value": float(value), f"{name}_rate": 1.0, f"{name}_accel": 1.0,
                 f"{name}_t_ref": 1.0}
        new = driven_class(type(fresh), name)(*args, **{**kwargs, **extra})
        if not owner_path:
            root = new
        else:
            parent_path, _, child = owner_path.rpartition(".")
            setattr(_find(root, parent_path), child, new)
        out[path] = float(value)
    return root, out


def _find(comp, path):
    for part in path.split(".") if path else []:
        comp = comp.children().get(part)
        if comp is None:
            return None
    return comp


def _is_referenced(owner, name) -> bool:
    """Does a sub-component bind one of its parameters to ``owner.name``?"""
    from ..components.declarations import ref
    for child in owner.children().values():
        for pname, decl in child.declarations().items():
            if isinstance(decl, Parameter):
                raw = child._param_values.get(pname, decl.value)
                if isinstance(raw, ref) and raw.name == name:
                    return True
    return False


def _nested_set(d, keys, value):
    for k in keys[:-1]:
        d = d.setdefault(k, {})
    d[keys[-1]] = value


def _merged(a: dict, b: dict) -> dict:
    out = dict(a)
    for k, v in b.items():
        out[k] = _merged(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) \
            else v
    return out


def constant_value(compiled, k) -> float:
    """The value of a variable the compiler fixed: a number, or a function of p."""
    return float(k(compiled.p)) if callable(k) else float(k)



@contextmanager
def parameters_set(plant: Plant, values: dict):
    """Temporarily set parameters (and top-level inputs) by the user's names."""
    c = plant.compiled
    saved = c.p.copy()
    try:
        for name, v in values.items():
            k = plant.parameter_index(name)
            if k is None:
                raise KeyError(f"the model has no parameter or input '{name}'")
            c.p[k] = float(v)
        yield
    finally:
        c.p[:] = saved
