"""Operating points of a compiled model: given, taken from a simulation, or steady.

An operating point is a time t and a *consistent* solver vector z: the states are
chosen, the rest of z (torn variables, derivative variables of the full form) solves
the model equations G(t, z) = 0.  The states are those of ``compiled.state_index``
(the selected states after index reduction, see the README's design section).

A model with top-level ``RealInput`` ports cannot be compiled on its own (an unconnected
input leaves it under-determined), so it is placed in a small harness that drives each
such input from a parameter; names are translated both ways, so the user never sees it.

Steady state (Egeland & Gravdahl 1.2.3): der(x) = 0 for every state, i.e.
F(t, z, z' = 0) = 0, solved by damped Newton with a Newton-homotopy fallback.  A
singular Jacobian at the solution means the equilibrium is not isolated (a free angle,
a floating potential) or does not exist; the error names the states in the null space.
"""
from __future__ import annotations

from contextlib import contextmanager

import numpy as np
import scipy.sparse as sps

from ..compiler.model import CompiledModel
from ..components.component import Component
from ..components.declarations import Parameter
from ..components.symbols import Eq
from ..ports import RealInput, RealOutput
from ..solvers.linalg import SingularMatrixError
from ..solvers.newton import damped_newton, homotopy

__all__ = ["OperatingPoint", "SteadyStateError", "steady_state", "operating_point",
           "make_consistent", "constant_value"]


class SteadyStateError(ValueError):
    """No isolated equilibrium: none found, or a singular Jacobian (names the states)."""


class OperatingPoint:
    """A consistent point (t, z) of a compiled model, readable by variable name.

    ``op["J.w"]`` is any variable's value there; ``op.states`` maps the state names to
    their values; ``op.inputs`` the values of the top-level inputs.
    """

    def __init__(self, plant, t: float, z: np.ndarray):
        self.plant = plant
        self.t = float(t)
        self.z = np.asarray(z, dtype=float)

    @property
    def compiled(self) -> CompiledModel:
        return self.plant.compiled

    def __getitem__(self, name: str) -> float:
        c = self.compiled
        if name in self.plant.input_params:
            return float(c.p[c.param_names.index(self.plant.input_params[name])])
        sign, k = c.outputs[self.plant.internal(name)]
        if sign is None:
            return constant_value(c, k)
        with _modes_at(c, self.t, self.z):
            return float(sign * c.expand(self.t, self.z)[k])

    @property
    def states(self) -> dict:
        c = self.compiled
        return {self.plant.external(c.names[k]): float(self.z[k]) for k in c.state_index}

    @property
    def inputs(self) -> dict:
        return {name: self[name] for name in self.plant.input_params}

    def __repr__(self):
        return f"<OperatingPoint t={self.t:g} states={self.states}>"


# -- the model behind the user's object ------------------------------------------------------
class Plant:
    """A compiled model and the translation of the user's names into its names.

    ``input_params`` maps each top-level RealInput of the user's component to the
    parameter of the harness that drives it.
    """

    def __init__(self, compiled, prefix: str = "", input_params=None):
        self.compiled = compiled
        self.prefix = prefix
        self.input_params = dict(input_params or {})

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
        internal = self.internal(name)
        names = self.compiled.param_names
        return names.index(internal) if internal in names else None


def as_plant(model, values=None) -> Plant:
    """The Plant for a Component, CompiledModel, Result, OperatingPoint or Plant."""
    if isinstance(model, Plant):
        return model
    if isinstance(model, OperatingPoint):
        return model.plant
    if isinstance(model, CompiledModel):
        return Plant(model)
    if hasattr(model, "compiled") and hasattr(model, "_z"):      # a Result
        return Plant(model.compiled)
    if isinstance(model, Component):
        return _compile_plant(model, values or {})
    raise TypeError(f"expected a Component or a CompiledModel, got {type(model).__name__}")


def top_level_inputs(model: Component) -> list:
    """Names of the RealInput ports declared directly on a component."""
    return [name for name, child in model.children().items() if isinstance(child, RealInput)]


class _InputValue(Component):
    """Drives a top-level input from a parameter (so linearize can perturb it)."""

    y = RealOutput()
    k = Parameter(1.0, description="value of the input")

    def equations(self):
        return [Eq(self.y, self.k)]


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


def _compile_plant(model: Component, values: dict, unfreeze=()) -> Plant:
    """Compile ``model`` (in a harness if it has top-level inputs).

    Parameters equal to 0 are structural zeros of the compiled model (not tunable), so
    the parameters to be perturbed (``unfreeze``, the harness's input values) are
    compiled as 1 and set to their value afterwards; they enter the equations
    additively, so the structure does not depend on the value.
    """
    from ..simulation import compile as compile_model
    names = top_level_inputs(model)
    vals = {n: float(values.get(n, values.get(f"{n}.signal", 0.0))) for n in names}
    mods = {}
    for path in unfreeze:
        _nested_set(mods, path.split("."), 1.0)
    root = type(model)(*model._init_call[0], **_merged(model._init_call[1], mods))
    if not names:
        plant = Plant(compile_model(root))
    else:
        compiled = compile_model(_Harness(root, {n: 1.0 for n in names}))
        params = {n: f"input{k}.k" for k, n in enumerate(names)}
        params.update({f"{n}.signal": p for n, p in params.items()})
        plant = Plant(compiled, "plant.", params)
        for n in names:
            compiled.p[plant.parameter_index(n)] = vals[n]
    for path in unfreeze:
        plant.compiled.p[plant.parameter_index(path)] = 0.0
    return plant


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


# -- consistency -------------------------------------------------------------------------------
@contextmanager
def _modes_at(compiled, t, z):
    """Relations evaluated at (t, z) for the duration, the caller's modes restored."""
    saved = compiled.m.copy()
    try:
        compiled.init_modes(t, z)
        yield
    finally:
        compiled.m[:] = saved


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


def make_consistent(compiled, t: float, z: np.ndarray) -> np.ndarray:
    """Solve G(t, z) = 0 for the non-state part of z, the states held."""
    alg = np.flatnonzero(compiled.algebraic)
    if alg.size == 0:
        return z.copy()
    z = z.copy()

    def fun(za):
        z[alg] = za
        return compiled.G(t, z)

    def jac(za):
        z[alg] = za
        return compiled.dG_dy(t, z)[:, alg]

    w = 1.0 / (1e-10 * np.abs(z[alg]) + 1e-10 * compiled.nominal[alg])
    with _modes_at(compiled, t, z):
        out = damped_newton(fun, jac, z[alg], weights=w, tol=1.0, max_iter=50)
        if not out.converged:
            out = homotopy(fun, jac, z[alg], weights=w, tol=1.0)
    if not out.converged:
        raise ValueError(f"the algebraic variables could not be made consistent at t = {t}: "
                         f"{out.message}")
    z[alg] = out.x
    return z


# -- operating points ------------------------------------------------------------------------
def operating_point(plant: Plant, at=None, t: float = 0.0) -> OperatingPoint:
    """Resolve ``at`` (see :func:`acausal.analysis.linearize`) to an OperatingPoint."""
    c = plant.compiled
    if isinstance(at, OperatingPoint):
        return at
    if isinstance(at, str):
        if at != "steady":
            raise ValueError(f"at='{at}': the only named operating point is 'steady'")
        return steady_state(plant, t=t)
    if isinstance(at, tuple) and len(at) == 2 and hasattr(at[0], "_z"):
        return _from_result(plant, *at)
    values = dict(at or {})
    z = _start_values(c, t)
    for name, v in values.items():
        if plant.parameter_index(name) is not None:
            continue                      # parameters and inputs are set by the caller
        z[_z_index(plant, name)] = v * _z_sign(plant, name)
    if c.dynamic is not None:
        c.reselect_states(t, z, hysteresis=1.0)
    return OperatingPoint(plant, t, make_consistent(c, t, z))


def _start_values(compiled, t):
    from ..simulation import initial_values
    try:
        return initial_values(compiled, t)
    except Exception:                     # an inconsistent start is fine: z is re-solved
        return compiled.start.copy()


def _from_result(plant, result, t):
    c = plant.compiled
    z_t = result._z
    k = int(np.argmin(np.abs(result.t - t)))
    if abs(result.t[k] - t) <= 1e-12 * max(1.0, abs(t)):
        z = z_t[k].copy()
    else:
        z = np.array([np.interp(t, result.t, z_t[:, j]) for j in range(z_t.shape[1])])
    if c.dynamic is not None:
        c.reselect_states(t, z, hysteresis=1.0)
    return OperatingPoint(plant, t, make_consistent(c, t, z))


def _z_index(plant, name):
    c = plant.compiled
    internal = plant.internal(name)
    if internal not in c.outputs:
        raise KeyError(f"no variable '{name}' in the model")
    sign, k = c.outputs[internal]
    z_of_sym = {c.outputs[zn][1]: j for j, zn in enumerate(c.names)}
    if sign is None or k not in z_of_sym or z_of_sym[k] not in set(c.state_index):
        states = ", ".join(plant.external(c.names[j]) for j in c.state_index)
        raise KeyError(f"'{name}' is not a state of the compiled model, so its value cannot "
                       f"be given; the states are: {states}")
    return z_of_sym[k]


def _z_sign(plant, name):
    return plant.compiled.outputs[plant.internal(name)][0]


def steady_state(model, *, hold=(), t: float = 0.0, inputs=None, parameters=None,
                 guess=None, tol: float = 1e-10) -> OperatingPoint:
    """The equilibrium der(x) = 0 nearest the start values (or ``guess``).

    Parameters
    ----------
    model : Component, CompiledModel or OperatingPoint
    hold : list of str
        States whose derivative need not vanish; they keep their start (or ``guess``)
        value.  Use it for a free angle that drifts at constant speed.
    t : float
        Time at which sources are evaluated.
    inputs, parameters : dict, optional
        Values of top-level inputs and of parameters (kept in the compiled model).
    guess : dict, optional
        Starting values of states for Newton's method.

    Returns
    -------
    OperatingPoint

    Raises
    ------
    SteadyStateError
        If Newton's method and the homotopy fail (the message lists the derivatives
        that could not be driven to zero), or if the Jacobian at the solution is
        singular (the message names the states of the null space).

    Notes
    -----
    Solves F(t, z, 0) = 0 of the compiled model, i.e. the index-reduced equations with
    every state derivative zero (Egeland & Gravdahl 1.2.3, the equilibrium of
    x' = f(x, u)).  Rows and columns of the held states are left out.
    """
    plant = as_plant(model, inputs)
    c = plant.compiled
    if parameters:
        c.set_parameters({plant.internal(k): v for k, v in parameters.items()})
    for name, v in (inputs or {}).items():
        k = plant.parameter_index(name)
        if k is None:
            raise KeyError(f"the model has no top-level input or parameter '{name}'")
        c.p[k] = float(v)
    z0 = _start_values(c, t)
    for name, v in (guess or {}).items():
        z0[_z_index(plant, name)] = v * _z_sign(plant, name)
    held = [_z_index(plant, h) for h in hold]
    return OperatingPoint(plant, t, _solve_steady(plant, t, z0, held, tol))


def _steady_system(c, t, z0, held):
    """F(t, z, 0) without the rows and columns of the held states."""
    rows_of = {int(s): c.n_res + i for i, s in enumerate(c.state_index)}
    cols = np.array([j for j in range(c.n) if j not in held], dtype=int)
    rows = np.array([r for r in range(c.n) if r not in {rows_of[h] for h in held}], dtype=int)
    zero = np.zeros(c.n)

    def full(x):
        z = z0.copy()
        z[cols] = x
        return z

    def fun(x):
        return c.residual(t, full(x), zero)[rows]

    def jac(x):
        return sps.csc_matrix(c.jacobian(t, full(x), zero, 0.0)[rows][:, cols])

    return fun, jac, full, cols


def _solve_steady(plant, t, z0, held, tol):
    c = plant.compiled
    fun, jac, full, cols = _steady_system(c, t, z0, held)
    x0 = z0[cols]
    w = 1.0 / (1e-10 * np.abs(x0) + 1e-10 * c.nominal[cols])
    with _modes_at(c, t, z0):
        try:
            out = damped_newton(fun, jac, x0, weights=w, tol=1.0, max_iter=100)
            if not out.converged:
                out = homotopy(fun, jac, x0, weights=w, tol=1.0)
        except SingularMatrixError:
            out = None
        if out is None or not out.converged or \
                np.max(np.abs(out.residual), initial=0.0) > 1e-8 * max(1.0, np.abs(x0).max()):
            _raise_singular(plant, jac(x0 if out is None else out.x).toarray(), cols)
            raise SteadyStateError(_no_equilibrium(plant, t, full(out.x)))
        _raise_singular(plant, jac(out.x).toarray(), cols)
    return full(out.x)


def _raise_singular(plant, J, cols):
    """A (numerically) singular steady-state Jacobian: name the null-space variables."""
    if J.size == 0:
        return
    Js = J / np.maximum(np.abs(J).max(axis=1, keepdims=True), 1e-300)   # row scaling
    _, s, Vt = np.linalg.svd(Js)
    if s[-1] > 1e-10 * s[0]:
        return
    c = plant.compiled
    v = np.abs(Vt[-1])
    involved = [cols[k] for k in np.argsort(-v) if v[k] > 1e-3 * v.max()]
    states = [plant.external(c.names[j]) for j in involved if j in set(c.state_index)]
    others = [plant.external(c.names[j]) for j in involved if j not in set(c.state_index)]
    raise SteadyStateError(
        "the steady-state equations der(x) = 0 are singular: the equilibrium is not "
        "isolated or does not exist. States in the null space: "
        + (", ".join(states) or "none") + (f" (with {', '.join(others)})" if others else "")
        + ". Hold a drifting state at a given value with hold=[...], or fix the free "
        "quantity (a Fixed flange, a Ground)")


def _no_equilibrium(plant, t, z):
    c = plant.compiled
    d = c.state_derivatives(t, z)
    worst = np.argsort(-np.abs(d))[:5]
    parts = [f"der({plant.external(c.names[c.state_index[k]])}) = {d[k]:.4g}"
             for k in worst if abs(d[k]) > 0]
    return ("no steady state found from the start values: the derivatives that did not "
            "vanish are " + ", ".join(parts or ["(none; the algebraic equations failed)"]))
