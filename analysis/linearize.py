"""Linearization of a compiled model about an operating point (Egeland & Gravdahl 1.2.3).

The compiled model is the index-1 DAE F(t, z, z', p) = 0 of the README's design
section, whose states x = z[state_index] are the selected states after index
reduction; the rest of z, a (torn variables, derivative variables of the full form),
is fixed by the equations.  Perturbing F at a consistent point (z, z'),

    E dz' + F_z dz + F_p dp = 0,       E = dF/dz' = J(cj=1) - J(cj=0),  F_z = J(cj=0),

where E is zero outside the state columns.  Unknowns (dx', da) given (dx, dp):

    [E_x  F_a] [dx'; da] = -[F_x  F_p] [dx; dp]

which is uniquely solvable exactly when the DAE is index 1 (the implicit function
theorem), giving A, B (rows of dx') and da/dx, da/dp.  Outputs are any variables of
the model, y = h(t, z, p) (``CompiledModel.expand``), so C = h_z dz/dx and
D = h_z dz/dp + h_p.  h_p, F_p and h_z are central differences (the generated code
gives F_z exactly); for the affine dependence on sources this is exact to round-off.

Inputs are parameters, top-level RealInput ports (driven from a parameter in a
harness, see :mod:`.operating`), or variables that a source drives: such a variable is
perturbed through the source's parameter that shifts it additively (its ``offset``,
a ``Constant``'s ``k``, a ``ConstantVoltage``'s ``V``).
"""
from __future__ import annotations

import numpy as np

from ..components.component import Component
from .operating import (OperatingPoint, _compile_plant, _modes_at, as_plant,
                        operating_point, parameters_set, top_level_inputs)
from .statespace import StateSpace

__all__ = ["linearize", "linear_residual"]


def linearize(model, inputs=(), outputs=(), at=None, *, t: float = 0.0) -> StateSpace:
    """Linearize a model: dx' = A dx + B du, dy = C dx + D du at an operating point.

    Parameters
    ----------
    model : Component or CompiledModel
        A Component is compiled (top-level RealInput ports are driven by parameters).
    inputs : list of str
        Parameters (``"motor.R"``), top-level inputs (``"u"``) or variables driven by a
        source (``"source.v"``, ``"drive.tau.signal"``).
    outputs : list of str
        Any variable of the model, ``der(x)`` of a state included.
    at : optional
        The operating point: ``(result, t)`` (a time of a simulation),
        ``{"J.w": 10.0, "u": 1.0}`` (state values, inputs and parameters; the other
        states keep their start values), ``"steady"`` (:func:`steady_state`), an
        :class:`OperatingPoint`, or None for the start values.
    t : float
        Time of the operating point when ``at`` does not give one.

    Returns
    -------
    StateSpace
        With the selected states of the compiled model (``compiled.state_index``) and
        the user's names for states, inputs and outputs.

    Notes
    -----
    Egeland & Gravdahl (1.20)-(1.23) for x' = f(x, u); for the DAE, the algebraic part
    is eliminated by the implicit function theorem (module docstring).  Only the poles
    of A belong to the model: A can have more states than a transfer function needs
    (a motor's angle in the speed channel); ``StateSpace.minimal`` removes them.
    """
    values = at if isinstance(at, dict) else {}
    source = at if isinstance(at, OperatingPoint) else (at[0] if isinstance(at, tuple) else model)
    plant = as_plant(source, _input_values(model, values))
    try:
        return _linearize(plant, list(inputs), list(outputs), at, values, t)
    except _NoDrivingParameter:
        if not isinstance(source, Component):
            raise
    # the sources' offsets were 0, i.e. structural zeros: compile them tunable
    zeros = plant.compiled.meta.get("structural_zeros", ())
    offsets = [plant.external(n) for n in zeros if n.endswith(".offset")]
    plant = _compile_plant(source, values, offsets)
    return _linearize(plant, list(inputs), list(outputs), at, values, t)


def _linearize(plant, inputs, outputs, at, values, t):
    c = plant.compiled
    params = {k: v for k, v in values.items() if plant.parameter_index(k) is not None}
    with parameters_set(plant, params):
        op = operating_point(plant, at, t)
        with _modes_at(c, op.t, op.z):
            A, B, C, D = _matrices(plant, op, inputs, outputs)
    states = [plant.external(c.names[k]) for k in c.state_index]
    return StateSpace(A, B, C, D, states, inputs, outputs)


class _NoDrivingParameter(ValueError):
    """A variable named as input has no tunable parameter that shifts it."""


def _input_values(model, values):
    if hasattr(model, "children") and top_level_inputs(model):
        return values
    return None


def _matrices(plant, op, inputs, outputs):
    c = plant.compiled
    t, z = op.t, op.z
    S = np.asarray(c.state_index, dtype=int)
    alg = np.flatnonzero(c.algebraic)
    cols = [_input_column(plant, name, t, z) for name in inputs]
    Fp = np.column_stack([_dF_dp(c, t, z, k) / g for k, g in cols]) if cols \
        else np.zeros((c.n, 0))
    J0, E = linear_residual(c, t, z)
    M = np.hstack([E[:, S], J0[:, alg]])
    W = -np.linalg.solve(M, np.hstack([J0[:, S], Fp]))
    ns = len(S)
    Zx, Zp = np.zeros((c.n, ns)), np.zeros((c.n, len(inputs)))
    Zx[S] = np.eye(ns)
    Zx[alg], Zp[alg] = W[ns:, :ns], W[ns:, ns:]
    A, B = W[:ns, :ns], W[:ns, ns:]
    H = _dexpand_dz(c, t, z)
    Hp = np.column_stack([_dexpand_dp(c, t, z, k) / g for k, g in cols]) if cols \
        else np.zeros((H.shape[0], 0))
    rows = [_output_row(plant, name) for name in outputs]
    C = np.array([s * (H[k] @ Zx) if s is not None else np.zeros(ns) for s, k in rows])
    D = np.array([s * (H[k] @ Zp + Hp[k]) if s is not None else _dconst_dp(c, k, cols)
                  for s, k in rows])
    return A, B, C.reshape(len(outputs), ns), D.reshape(len(outputs), len(inputs))


def linear_residual(compiled, t, z):
    """(F_z, E = F_z') of the compiled model at (t, z), dense."""
    zp = np.zeros(compiled.n)
    J0 = compiled.jacobian(t, z, zp, 0.0).toarray()
    E = compiled.jacobian(t, z, zp, 1.0).toarray() - J0
    return J0, E


def _output_row(plant, name):
    c = plant.compiled
    internal = plant.internal(name)
    if internal not in c.outputs:
        raise KeyError(f"no variable '{name}' in the model (outputs are variables by their "
                       "dotted names, or der(x) of a state)")
    return c.outputs[internal]


def _input_column(plant, name, t, z):
    """(parameter index, d input / d parameter) for one input name."""
    k = plant.parameter_index(name)
    if k is not None:
        return k, 1.0
    c = plant.compiled
    internal = plant.internal(name)
    if internal not in c.outputs:
        raise KeyError(f"no parameter, input or variable named '{name}'")
    sign, idx = c.outputs[internal]
    if sign is None and not callable(idx):
        raise ValueError(f"'{name}' is a constant of the model, it cannot be an input")
    if sign is None:        # fixed to a function of the parameters by the compiler
        return _driving_parameter(plant, name, lambda k: _dconst_dp(c, idx, [(k, 1.0)])[0])
    if idx in {c.outputs[c.names[j]][1] for j in range(c.n)}:
        raise ValueError(f"'{name}' is computed by the solver, not driven by a source; "
                         "use a parameter or a top-level RealInput as input")
    return _driving_parameter(plant, name, lambda k: sign * _dexpand_dp(c, t, z, k)[idx])


def _driving_parameter(plant, name, slope):
    """The source parameter that shifts variable ``name`` additively (slope +-1).

    ``slope(k)`` is d(name)/d p_k with the solver vector held; an ``offset`` with slope
    1 is preferred, then any slope +-1, then the steepest.
    """
    c = plant.compiled
    slopes = {}
    for k in range(len(c.p)):
        g = slope(k)
        if abs(g) > 1e-9:
            slopes[k] = g
    unit = [k for k, g in slopes.items() if abs(abs(g) - 1.0) < 1e-6]
    offsets = [k for k in unit if c.param_names[k].endswith(".offset")]
    pick = offsets or unit or sorted(slopes, key=lambda k: -abs(slopes[k]))
    if not pick:
        raise _NoDrivingParameter(
            f"'{name}' does not depend on any tunable parameter at this point, so it cannot "
            "be perturbed as an input (a source's offset that is 0 is a structural zero of "
            "a compiled model: pass the Component, or use a parameter or a top-level "
            "RealInput)")
    return pick[0], slopes[pick[0]]


def _dconst_dp(c, k, cols):
    """D row of an output the compiler fixed to a constant or a function of p."""
    if not callable(k):
        return np.zeros(len(cols))
    out = []
    for j, g in cols:
        p0, h = c.p[j], _step(c.p[j])
        try:
            c.p[j] = p0 + h
            fp = k(c.p)
            c.p[j] = p0 - h
            fm = k(c.p)
        finally:
            c.p[j] = p0
        out.append((fp - fm) / (2 * h) / g)
    return np.array(out)


def _step(x, nominal=1.0):
    return 1e-6 * max(abs(x), nominal, 1e-6)


def _dF_dp(c, t, z, k):
    zp = np.zeros(c.n)
    zp[c.state_index] = c.state_derivatives(t, z)
    p0 = c.p[k]
    h = _step(p0)
    try:
        c.p[k] = p0 + h
        fp = c.residual(t, z, zp)
        c.p[k] = p0 - h
        fm = c.residual(t, z, zp)
    finally:
        c.p[k] = p0
    return (fp - fm) / (2 * h)


def _dexpand_dp(c, t, z, k):
    p0 = c.p[k]
    h = _step(p0)
    try:
        c.p[k] = p0 + h
        fp = c.expand(t, z)
        c.p[k] = p0 - h
        fm = c.expand(t, z)
    finally:
        c.p[k] = p0
    return (fp - fm) / (2 * h)


def _dexpand_dz(c, t, z):
    cols = []
    for j in range(c.n):
        h = _step(z[j], c.nominal[j])
        zp, zm = z.copy(), z.copy()
        zp[j] += h
        zm[j] -= h
        cols.append((c.expand(t, zp) - c.expand(t, zm)) / (2 * h))
    return np.column_stack(cols) if cols else np.zeros((len(c.expand(t, z)), 0))
