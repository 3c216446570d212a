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

Modes.  Every operating point carries the modes (relation and floor values, ``m``) it
was computed in, and satisfies them: equilibria and consistent points are found by a
mode search (:mod:`.modes`) that switches the relations a solution contradicts and
solves again, and a point for which no consistent mode is found raises
:class:`OperatingPointError` (:class:`SteadyStateError` for an equilibrium) naming the
relations.  Values read from a point (``op["limit.y"]``) are evaluated in its modes.
"""
from __future__ import annotations

from contextlib import contextmanager

import numpy as np
import scipy.sparse as sps

from ..runtime import CompiledModel
from ..solvers.linalg import SingularMatrixError
from ..solvers.newton import damped_newton, homotopy
from .modes import ModeConflict, NoSolution, mode_values, search_modes
from .plant import Plant, as_plant, constant_value

__all__ = ["OperatingPoint", "OperatingPointError", "SteadyStateError", "steady_state",
           "operating_point", "make_consistent", "consistent_point", "constant_value"]


class OperatingPointError(ValueError):
    """No consistent operating point: the algebraic equations have no solution, or no
    mode of the relations is consistent with its own solution (``relations`` names
    them, in the user's words)."""

    def __init__(self, message: str, relations=()):
        super().__init__(message)
        self.relations = list(relations)


class SteadyStateError(OperatingPointError):
    """No isolated equilibrium: none found, a singular Jacobian (names the states), or
    no mode of the relations that the equilibrium satisfies (names the relations)."""


class OperatingPoint:
    """A consistent point (t, z) of a compiled model in modes m, readable by name.

    ``op["J.w"]`` is any variable's value there (evaluated in the point's modes);
    ``op.states`` maps the state names to their values; ``op.inputs`` the values of the
    top-level inputs; ``op.modes`` the value of every relation ({text: bool}).
    ``m`` None means the modes the point itself gives (``init_modes``).  The point keeps
    the parameter values it was found at (``p``): it is read, and linearized, at those,
    whatever the compiled model's values are later (another ``steady_state(...,
    parameters=...)`` of the same model, ``set_parameters``).
    """

    def __init__(self, plant, t: float, z: np.ndarray, m=None):
        self.plant = plant
        self.t = float(t)
        self.z = np.asarray(z, dtype=float)
        self.m = None if m is None else np.array(m, dtype=float)
        self.p = plant.compiled.p.copy()

    @property
    def compiled(self) -> CompiledModel:
        return self.plant.compiled

    def __getitem__(self, name: str) -> float:
        c = self.compiled
        if name in self.plant.input_params or name in self.plant.input_slots:
            return float(self.p[self.plant.parameter_index(name)])
        internal = self.plant.internal(name)
        if internal not in c.outputs and f"{internal}.signal" in c.outputs:
            internal = f"{internal}.signal"      # a signal port by its own name
        sign, k = c.outputs[internal]
        with self.in_modes():
            if sign is None:
                return constant_value(c, k)
            return float(sign * c.expand(self.t, self.z)[k])

    @contextmanager
    def in_modes(self):
        """Context: the compiled model at this point's parameter values and in its modes
        (the caller's restored)."""
        c = self.compiled
        saved = c.p.copy()
        try:
            c.p[:] = self.p
            modes = _modes_at(c, self.t, self.z) if self.m is None else modes_set(c, self.m)
            with modes:
                yield
        finally:
            c.p[:] = saved

    @property
    def modes(self) -> dict:
        """{relation text: value} of the modes this point is in."""
        with self.in_modes():
            return mode_values(self.compiled, self.plant.prefix)

    @property
    def states(self) -> dict:
        c = self.compiled
        return {self.plant.external(c.names[k]): float(self.z[k]) for k in c.state_index}

    @property
    def inputs(self) -> dict:
        return {name: self[name] for name in self.plant.input_names}

    def __repr__(self):
        return f"<OperatingPoint t={self.t:g} states={self.states}>"


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
def modes_set(compiled, m):
    """The modes ``m`` for the duration, the caller's restored."""
    saved = compiled.m.copy()
    try:
        compiled.m[:] = m
        yield
    finally:
        compiled.m[:] = saved


def make_consistent(compiled, t: float, z: np.ndarray, modes=None) -> np.ndarray:
    """Solve G(t, z) = 0 for the non-state part of z, the states held, in modes that
    the solution satisfies (see :func:`consistent_point`)."""
    return consistent_point(compiled, t, z, modes)[0]


def consistent_point(compiled, t: float, z: np.ndarray, modes=None, prefix: str = ""):
    """(z, m): G(t, z) = 0 solved for the non-state part of z with the states held, and
    the modes m it satisfies, by a mode search from ``modes`` (default: those of the
    given point).  Raises OperatingPointError naming the relations if none is found."""
    alg = np.flatnonzero(compiled.algebraic)
    z = np.array(z, dtype=float)
    w = 1.0 / (1e-10 * np.abs(z[alg]) + 1e-10 * compiled.nominal[alg])

    def solve(guess):
        if alg.size == 0:
            return guess.copy()
        zz = guess.copy()

        def fun(za):
            zz[alg] = za
            return compiled.G(t, zz)

        def jac(za):
            zz[alg] = za
            return compiled.dG_dy(t, zz)[:, alg]

        try:
            out = damped_newton(fun, jac, guess[alg], weights=w, tol=1.0, max_iter=50)
            if not out.converged:
                out = homotopy(fun, jac, guess[alg], weights=w, tol=1.0)
        except SingularMatrixError as err:
            raise NoSolution(f"singular Jacobian of the algebraic equations: {err}") from None
        zz[alg] = out.x
        if not out.converged:
            raise NoSolution(out.message, zz.copy())
        return zz.copy()

    try:
        z, m, _ = search_modes(compiled, t, z, solve, modes=modes, prefix=prefix)
    except NoSolution as err:
        raise OperatingPointError(f"the algebraic variables could not be made consistent "
                                  f"at t = {t}: {err.message}") from None
    except ModeConflict as err:
        raise OperatingPointError(f"no consistent operating point at t = {t}: {err}",
                                  err.relations) from None
    return z, m


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
    return OperatingPoint(plant, t, *consistent_point(c, t, z, prefix=plant.prefix))


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
    modes = None
    if abs(result.t[k] - t) <= 1e-12 * max(1.0, abs(t)):
        z = z_t[k].copy()
        # the modes the integrator used at that output point, where the result has them
        if len(result._discrete_index) == len(result.t) and result._discrete:
            modes = result._discrete[result._discrete_index[k]]
    else:
        z = np.array([np.interp(t, result.t, z_t[:, j]) for j in range(z_t.shape[1])])
    if c.dynamic is not None:
        c.reselect_states(t, z, hysteresis=1.0)
    return OperatingPoint(plant, t, *consistent_point(c, t, z, modes, plant.prefix))


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
        that could not be driven to zero), if the Jacobian at the solution is
        singular (the message names the states of the null space), or if no mode of
        the relations is consistent with its own equilibrium (the message, and the
        error's ``relations``, name the relations that kept being contradicted).

    Notes
    -----
    Solves F(t, z, 0) = 0 of the compiled model, i.e. the index-reduced equations with
    every state derivative zero (Egeland & Gravdahl 1.2.3, the equilibrium of
    x' = f(x, u)).  Rows and columns of the held states are left out.  The relations
    are frozen in the modes of the start point, then switched where the solution
    contradicts them, until the equilibrium satisfies the modes it was computed in
    (:mod:`acausal.analysis.modes`); the point's ``modes`` lists them.
    """
    plant = as_plant(model, inputs)
    c = plant.compiled
    from ..runtime.delays import refuse_delays
    refuse_delays(c, "steady_state does not solve models with delay() (at a steady state "
                     "delay(expr, T) = expr, which this solver does not substitute)",
                  "Simulate to the steady state, or use PadeDelay")
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
    z, m = _solve_steady(plant, t, z0, held, tol)
    return OperatingPoint(plant, t, z, m)


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
    """(z, m): the equilibrium and the modes it satisfies (mode search, :mod:`.modes`)."""
    c = plant.compiled
    fun, jac, full, cols = _steady_system(c, t, z0, held)
    w = 1.0 / (1e-10 * np.abs(z0[cols]) + 1e-10 * c.nominal[cols])

    def solve(guess):
        x0 = guess[cols]
        try:
            out = damped_newton(fun, jac, x0, weights=w, tol=1.0, max_iter=100)
            if not out.converged:
                out = homotopy(fun, jac, x0, weights=w, tol=1.0)
        except SingularMatrixError:
            out = None
        if out is None or not out.converged or \
                np.max(np.abs(out.residual), initial=0.0) > 1e-8 * max(1.0, np.abs(x0).max(initial=0.0)):
            x = x0 if out is None else out.x
            raise NoSolution(_singular_message(plant, jac(x).toarray(), cols)
                             or _no_equilibrium(plant, t, full(x)), full(x))
        return full(out.x)

    try:
        z, m, _ = search_modes(c, t, z0, solve, prefix=plant.prefix)
    except NoSolution as err:
        raise SteadyStateError(err.message) from None
    except ModeConflict as err:
        raise SteadyStateError(f"no steady state that satisfies the modes it is computed "
                               f"in: {err}", err.relations) from None
    with modes_set(c, m):
        message = _singular_message(plant, jac(z[cols]).toarray(), cols)
    if message:
        raise SteadyStateError(message)
    return z, m


def _singular_message(plant, J, cols):
    """For a (numerically) singular steady-state Jacobian, the message naming the
    null-space variables; None if it is regular."""
    if J.size == 0:
        return None
    Js = J / np.maximum(np.abs(J).max(axis=1, keepdims=True), 1e-300)   # row scaling
    _, s, Vt = np.linalg.svd(Js)
    if s[-1] > 1e-10 * s[0]:
        return None
    c = plant.compiled
    v = np.abs(Vt[-1])
    involved = [cols[k] for k in np.argsort(-v) if v[k] > 1e-3 * v.max()]
    states = [plant.external(c.names[j]) for j in involved if j in set(c.state_index)]
    others = [plant.external(c.names[j]) for j in involved if j not in set(c.state_index)]
    return ("the steady-state equations der(x) = 0 are singular: the equilibrium is not "
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
