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

A model may differentiate its input (a ship whose rudder term is K (T_a delta' +
delta), a position imposed on a mass).  A top-level input is driven as
u = k + rate (t - t_ref) + accel (t - t_ref)^2 / 2, so F_u' and F_u'' are the
derivatives by ``rate`` and ``accel`` at t = t_ref, and the linearization
x' = A x + B u + B1 u' + B2 u'' is brought to state-space form in the state
xi = x - (B1 + A B2) u - B2 u' (B + A B1 + A^2 B2, D + C B1 + C A B2); an output that
follows u' or u'' directly has no proper transfer function and is refused.  A
parameter's derivative is 0 to the compiler: when ``linearize`` compiles the model
itself (a Component), each parameter named as an input is therefore *driven* the same
way (its component rebuilt with the parameter a variable, ``plant.driven_class``),
unless another parameter is bound to it; a CompiledModel's parameters are constant
perturbations.
"""
from __future__ import annotations

import warnings

import numpy as np

from ..components.component import Component
from ..runtime.delays import refuse_delays
from .modes import describe_items, mode_values, relations_at_switch
from .operating import OperatingPoint, operating_point
from .plant import as_plant, compile_plant, parameters_set, top_level_inputs
from .statespace import StateSpace
from ..errors import ModeWarning, OperatingPointError

__all__ = ["linearize", "linear_residual", "ModeWarning"]


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
        the user's names for states, inputs and outputs; ``modes`` gives the value of
        every relation it was linearized in.

    Raises
    ------
    OperatingPointError
        If the operating point contradicts the modes it would be linearized in, or no
        consistent point is found (names the relations).

    Warns
    -----
    ModeWarning
        If the point sits exactly where a relation switches and the two sides give
        different Jacobians; the message says which side was taken.

    Notes
    -----
    Egeland & Gravdahl (1.20)-(1.23) for x' = f(x, u); for the DAE, the algebraic part
    is eliminated by the implicit function theorem (module docstring).  Only the poles
    of A belong to the model: A can have more states than a transfer function needs
    (a motor's angle in the speed channel); ``StateSpace.minimal`` removes them.
    """
    values = at if isinstance(at, dict) else {}
    source = at if isinstance(at, OperatingPoint) else (at[0] if isinstance(at, tuple) else model)
    if isinstance(source, Component):
        # parameters taken as inputs are driven, so that their derivatives are seen
        plant = compile_plant(source, _input_values(model, values) or {}, driven=list(inputs))
    else:
        plant = as_plant(source)
    try:
        return _linearize(plant, list(inputs), list(outputs), at, values, t)
    except _NoDrivingParameter:
        if not isinstance(source, Component):
            raise
    # the sources' offsets were 0, i.e. structural zeros: compile them tunable
    zeros = plant.compiled.meta.get("structural_zeros", ())
    offsets = [plant.external(n) for n in zeros if n.endswith(".offset")]
    plant = compile_plant(source, values, offsets, driven=list(inputs))
    return _linearize(plant, list(inputs), list(outputs), at, values, t)


def _linearize(plant, inputs, outputs, at, values, t):
    c = plant.compiled
    refuse_delays(c, "a model with delay() has no finite-dimensional linearization "
                     "(exp(-sT) is not rational)", "Use PadeDelay for a linear model")
    params = {k: v for k, v in values.items() if plant.parameter_index(k) is not None}
    with parameters_set(plant, params):
        op = operating_point(plant, at, t)
        with op.in_modes():
            _check_modes(plant, op)
            kinks = relations_at_switch(c, op.t, op.z)
            A, B, C, D = _matrices(plant, op, inputs, outputs)
            modes = mode_values(c, plant.prefix)
    states = [plant.external(c.names[k]) for k in c.state_index]
    sys = StateSpace(A, B, C, D, states, inputs, outputs)
    sys.modes = modes
    if kinks:
        said = [f"{text} (taken as {_mode_word(modes[text])})"
                for text in describe_items(c, kinks, plant.prefix)]
        warnings.warn("the operating point sits where relations switch, so the model has a "
                      "kink there; linearized in the mode " + "; ".join(said),
                      ModeWarning, stacklevel=3)
    return sys


def _check_modes(plant, op):
    """An operating point must satisfy the modes it is linearized in."""
    c = plant.compiled
    bad = np.flatnonzero(c.contradicted(op.t, op.z))
    if bad.size:
        names = describe_items(c, bad, plant.prefix)
        raise OperatingPointError("the operating point contradicts the modes it would be "
                                  "linearized in: " + "; ".join(names), names)


def _mode_word(value):
    return ("true" if value else "false") if isinstance(value, bool) else f"{value:g}"


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
    ns, m = len(S), len(inputs)
    cols = [_input_column(plant, name, t, z) for name in inputs]
    # the columns of u, then of u' and u'' (top-level inputs only: see _InputValue)
    rate_cols = [_rate_columns(plant, name) for name in inputs]
    with _rates_at(c, rate_cols, t):
        Fp = np.column_stack([_dF_dp(c, t, z, k) / g for k, g in cols]
                             + [_dF_dp(c, t, z, k) if k is not None else np.zeros(c.n)
                                for order in (0, 1) for k in (r[order] for r in rate_cols)]) \
            if cols else np.zeros((c.n, 0))
        Hp = _expand_columns(c, t, z, cols, rate_cols)
    J0, E = linear_residual(c, t, z)
    M = np.hstack([E[:, S], J0[:, alg]])
    W = -np.linalg.solve(M, np.hstack([J0[:, S], Fp]))
    Zx, Zp = np.zeros((c.n, ns)), np.zeros((c.n, 3 * m))
    Zx[S] = np.eye(ns)
    Zx[alg], Zp[alg] = W[ns:, :ns], W[ns:, ns:]
    A, Bs = W[:ns, :ns], W[:ns, ns:]
    H = _dexpand_dz(c, t, z)
    rows = [_output_row(plant, name) for name in outputs]
    C = np.array([s * (H[k] @ Zx) if s is not None else np.zeros(ns) for s, k in rows])
    Ds = np.array([s * (H[k] @ Zp + Hp[k]) if s is not None
                   else np.concatenate([_dconst_dp(c, k, cols), np.zeros(2 * m)])
                   for s, k in rows])
    C, Ds = C.reshape(len(outputs), ns), Ds.reshape(len(outputs), 3 * m)
    B, D = _absorb_input_derivatives(A, C, Bs, Ds, m, inputs)
    return A, B, C, D


def _rate_columns(plant, name):
    """(rate, accel, t_ref) parameter indices of a top-level input, else Nones."""
    names = plant.input_rates.get(name)
    if names is None:
        return (None, None, None)
    return tuple(plant.compiled.param_names.index(q) for q in names)


class _rates_at:
    """t_ref of the harness inputs set to t (so that rate and accel act only as der(u)
    and der(u, 2) there), restored after."""

    def __init__(self, c, rate_cols, t):
        self.c, self.idx, self.t = c, [r[2] for r in rate_cols if r[2] is not None], t

    def __enter__(self):
        self.saved = self.c.p[self.idx].copy()
        self.c.p[self.idx] = self.t

    def __exit__(self, *exc):
        self.c.p[self.idx] = self.saved


def _expand_columns(c, t, z, cols, rate_cols):
    """d expand / d (u, u', u''), the output part of every input column."""
    n_all = len(c.expand(t, z))
    out = [_dexpand_dp(c, t, z, k) / g for k, g in cols]
    out += [_dexpand_dp(c, t, z, k) if k is not None else np.zeros(n_all)
            for order in (0, 1) for k in (r[order] for r in rate_cols)]
    return np.column_stack(out) if out else np.zeros((n_all, 0))


def _absorb_input_derivatives(A, C, Bs, Ds, m, inputs):
    """x' = A x + B u + B1 u' + B2 u'',  y = C x + D u + D1 u' + D2 u''  in the state
    xi = x - (B1 + A B2) u - B2 u':  xi' = A xi + (B + A B1 + A^2 B2) u and
    y = C xi + (D + C B1 + C A B2) u, provided D1 + C B2 = 0 and D2 = 0 (else the
    output follows the derivative of the input: no proper transfer function)."""
    B, B1, B2 = Bs[:, :m], Bs[:, m:2 * m], Bs[:, 2 * m:]
    D, D1, D2 = Ds[:, :m], Ds[:, m:2 * m], Ds[:, 2 * m:]
    if not (B1.any() or B2.any() or D1.any() or D2.any()):
        return B, D
    improper = np.abs(D1 + C @ B2) + np.abs(D2)
    scale = np.abs(D) + np.abs(C @ B1) + np.abs(C @ A @ B2) + 1e-300
    if np.any(improper > 1e-6 * np.max(scale, axis=0, keepdims=True)):
        j = int(np.argmax(np.max(improper / np.max(scale, axis=0, keepdims=True), axis=0)))
        raise ValueError(f"an output follows the derivative of input '{inputs[j]}' "
                         "directly: the linearization has no proper transfer function "
                         "(choose an output behind a state, or the input's integral)")
    return B + A @ B1 + A @ A @ B2, D + C @ B1 + C @ A @ B2


def linear_residual(compiled, t, z):
    """(F_z, E = F_z') of the compiled model at (t, z), dense."""
    zp = np.zeros(compiled.n)
    J0 = compiled.jacobian(t, z, zp, 0.0).toarray()
    E = compiled.jacobian(t, z, zp, 1.0).toarray() - J0
    return J0, E


def _inside(plant, name) -> str:
    """'; did you mean ...' naming the variables inside ``name`` when it is a port or a
    component (a RealInput ``force.f`` is read as ``force.f.signal``), else ''."""
    inner = sorted(plant.external(n) for n in plant.compiled.outputs
                   if plant.external(n).startswith(name + "."))
    if not inner:
        return ""
    more = ", ..." if len(inner) > 4 else ""
    return f"; '{name}' is a port or component: did you mean {', '.join(inner[:4])}{more}?"


def _output_row(plant, name):
    c = plant.compiled
    internal = plant.internal(name)
    if internal not in c.outputs and f"{internal}.signal" in c.outputs:
        internal = f"{internal}.signal"      # a signal port by its own name, as in results
    if internal not in c.outputs:
        raise KeyError(f"no variable '{name}' in the model (outputs are variables by their "
                       f"dotted names, or der(x) of a state){_inside(plant, name)}")
    return c.outputs[internal]


def _input_column(plant, name, t, z):
    """(parameter index, d input / d parameter) for one input name."""
    k = plant.parameter_index(name)
    if k is not None:
        return k, 1.0
    c = plant.compiled
    internal = plant.internal(name)
    if internal in c.meta.get("structural_zeros", ()):
        from ..components import NotInModel
        raise NotInModel(f"input '{name}' was 0 when the model was compiled, so it is a "
                         "structural zero (its terms were removed, it is not tunable): "
                         "pass the Component to linearize, which compiles it tunable, or "
                         f"compile the model with a non-zero {name}")
    if internal not in c.outputs:
        raise KeyError(f"no parameter, input or variable named '{name}'{_inside(plant, name)}")
    sign, idx = c.outputs[internal]
    if sign is None and not callable(idx):
        from ..words import zero_causes
        zeros = zero_causes(c.meta.get("structural_zeros", ()), [internal.rsplit(".", 1)[0]])
        raise ValueError(f"'{name}' is a constant of the model, it cannot be an input"
                         + (f" ({zeros}; or take the parameter that is 0 as the input, "
                            "passing the Component)" if zeros else ""))
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
