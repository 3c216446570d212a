"""Initialization, the one path: used by simulate, the analyses and after every event.

At t0 the unknowns are the solver vector z (the states and tearing variables, or every
variable in the full form).  The equations are the model's rows G(t0, z) = 0 plus as many
*initial conditions* as there are states, chosen by the compiler
(:func:`acausal.compiler.assemble.choose_initial_rows`):

1. the user's initial equations (e.g. ``der(w) = 0`` for steady state);
2. ``v = start`` for every variable with ``fixed=True``;
3. ``s = start`` for the states that nothing else fixes (Modelica's rule), kept where they
   complete a perfect structural matching of the initial system.

Start values of everything else are guesses for Newton's method (damped Newton, then a
Newton homotopy: :func:`acausal.solvers.initialization.solve_with_fallback`).  The
parameters found by initialization (``Parameter(fixed=False)``) are unknowns too, each
with a condition of its own, and are written into p (:mod:`.initparams`).

Relations take part as in Modelica's initialization: they first take their values at
the start values (repeatedly, as one relation may read another's value, and with the
Boolean and Integer equations evaluated there, which relations read too), the system is
solved with the relations frozen, then every relation takes the value it has at the
solution (the side the dynamics choose where it sits at zero; one at zero that its rate
does not move keeps its value: a stuck friction element's speed, solved to 1e-31, says
nothing of a side, and either value agrees with the solution), and the system is solved
again, until the values agree with the solution (a fixed point on the discrete state).

Then the derivatives of *every* unknown are made consistent: z'[S] of the states from the
model, and z'[A] of the algebraic unknowns from the derivative of G = 0 along the
solution,

    G_A z'_A = -(G_S z'_S + G_t),

so that the integrator's first predictor is right to first order in every component
(IDA computes y' of the differential components only, Brown, Hindmarsh & Petzold 1998;
an algebraic unknown that moves at t0, a torn acceleration under a sine torque, would
otherwise enter the first steps' error estimate as h |a'|).  The same is done after
every event (:func:`reinitialize`), where the states are kept and the algebraic
unknowns are solved again.
"""
from __future__ import annotations

import math

import numpy as np

from ..solvers.initialization import solve_with_fallback
from ..solvers.newton import damped_newton
from ..solvers.linalg import DENSE_MAX, LinearSolver, SingularMatrixError, assemble
from .diagnostics import DOMAIN_ERRORS, failing_statement
from ..errors import InitializationFailed
from ..words import shortened
from .indeterminate import minimum_norm_newton, null_variables
from .initparams import augmented, check_found, reset_free
from .redundant import check_dropped, choose_rows

__all__ = ["InitialConditions", "initialize", "reinitialize", "consistent_derivatives",
           "algebraic_system", "consistent_output"]

_MODE_ITERATIONS = 10   # solves with updated relation values before giving up
_NEWTON_RTOL = 1e-6     # Newton's weights for initialization (steps below 1e-5 of this)


class InitialConditions:
    """The initial-condition rows (generated code over z) that the compiler kept."""

    def __init__(self, initial):
        self.code = initial.code
        self.all_descriptions = list(initial.descriptions)
        # an over-specified problem (:mod:`.redundant`): the user's conditions that the
        # structure could not keep, and how many of the rows are the user's
        self.redundant = list(getattr(initial, "redundant", ()))
        self.n_mandatory = int(getattr(initial, "n_mandatory", 0))
        self.sizes = list(getattr(initial, "sizes", ()))
        self.dropped = []          # texts of the conditions dropped at the last solve
        self.select(initial.rows)

    def select(self, rows) -> None:
        """Keep ``rows`` (indices into every initial row) as the initial conditions."""
        self.rows = np.asarray(rows, dtype=np.int64)
        self._renumber = np.full(self.code.n_rows, -1)
        self._renumber[self.rows] = np.arange(len(self.rows))
        self._entries = self._renumber[self.code.jac_rows] >= 0

    def residual_all(self, t, z, p, m):
        return self.code.residual(t, z, p, m, np.empty(self.code.n_rows))

    def jacobian_all(self, t, z, p, m, n):
        c = self.code
        vals = c.jacobian(t, z, p, m, np.empty(len(c.jac_rows)))
        return assemble(vals, c.jac_rows, c.jac_cols, (c.n_rows, n), True)

    @property
    def n(self) -> int:
        return len(self.rows)

    @property
    def descriptions(self) -> list:
        return [self.all_descriptions[k] for k in self.rows]

    def residual(self, t, z, p, m):
        return self.code.residual(t, z, p, m, np.empty(self.code.n_rows))[self.rows]

    def jacobian(self, t, z, p, m, n, dense: bool = False):
        c = self.code
        vals = c.jacobian(t, z, p, m, np.empty(len(c.jac_rows)))[self._entries]
        rows = self._renumber[c.jac_rows[self._entries]]
        return assemble(vals, rows, c.jac_cols[self._entries], (self.n, n), dense)


def initialize(model, t0: float):
    """Consistent (z, z') at t0 with the discrete state settled (module docstring)."""
    z = model.start.copy()
    reset_free(model)            # parameters found by initialization: from their starts
    _fresh_start(model, t0, z)
    z = _discrete_at_start(model, t0, z)
    if model.dynamic is not None:
        model.dynamic.switches = []
        model.reselect_states(t0, z, hysteresis=1.0)
    history = []
    for _ in range(_MODE_ITERATIONS):
        z = solve_initial(model, t0, z)
        zp = consistent_derivatives(model, t0, z)
        _finite_derivatives(model, t0, zp)
        history.append(model.m.copy())
        changed = model.discrete.set_all(t0, z, model.p, lambda: model.rates(t0, z, zp),
                                         resting="kept")
        if model.whens is not None and model.whens.has_equations:
            # the Boolean and Integer equations, pre() at the start values
            z, moved = model.whens.update_equations(model, t0, z, model.p)
            changed |= moved
        if model.dynamic is not None:
            changed |= model.reselect_states(t0, z, hysteresis=1.0)
        if not changed:
            return z, zp
    flipping = np.flatnonzero(np.any(np.diff(np.array(history), axis=0) != 0, axis=0))
    raise InitializationFailed(
        f"initialization at t = {t0}: the relations do not settle (each solution "
        "contradicts the values it was computed with): "
        + "; ".join(shortened(model.discrete.describe(k)) for k in flipping[:5]), t0)


def _fresh_start(model, t0, z) -> None:
    """The discrete state and the choice of states as a new run finds them, whatever
    ran before on this model: every relation and floor value taken from the start
    values (in rounds, as relations read through others' values), the static choice of
    dummy derivatives and no memory of earlier searches -- the same inputs give the
    same run."""
    d = model.discrete
    d.m[: d.n_rel + d.n_disc] = 0.0
    d.offset[:] = 0.0
    d.event_band = None
    d.hysteresis[:] = 0.0
    d.last_switch[:] = -np.inf
    model.init_modes(t0, z)
    if model.dynamic is not None:
        model.dynamic.forget()
        static = set(model.model_code.dummies)
        if model.dummies != static:
            model.dummies = static
            model._update_links()


def _discrete_at_start(model, t0, z):
    """The Boolean and Integer equations evaluated at the start values, and the relations
    that read them taken again, in rounds: the first solve then sees the discrete state
    the start values give (a switch whose control holds it open starts open; with the
    Boolean's own start value it would start closed, and with Ron = 0 between two
    sources the first solve would be singular)."""
    whens = model.whens
    if whens is None or not whens.has_equations:
        return z
    for _ in range(_MODE_ITERATIONS):
        z, moved = whens.update_equations(model, t0, z, model.p)
        if not moved:
            break
        model.init_modes(t0, z)
    return z


def _finite_derivatives(model, t0, zp) -> None:
    """The initial point must be inside the domain of the model's functions: a state
    derivative that cannot be evaluated there (sqrt of a negative start) is an error
    in the user's words, not a singular matrix later."""
    bad = np.flatnonzero(~np.isfinite(zp[model.state_index]))
    if bad.size:
        names = [model.names[model.state_index[k]] for k in bad[:5]]
        why = f"; {model.evaluation_errors[0]}" if model.evaluation_errors else ""
        raise InitializationFailed(
            f"initialization at t = {t0}: "
            + ", ".join(f"der({n})" for n in names)
            + f" {'is' if len(names) == 1 else 'are'} not finite at the initial point{why}",
            t0)


def solve_initial(model, t0: float, z_guess: np.ndarray) -> np.ndarray:
    """[G; I](z) = 0 with the discrete state frozen; failures name equations and
    conditions in the user's words."""
    init = model.initial
    free = model.meta.get("free_parameters")     # found by initialization (initparams)
    if model.n == 0 and not free:  # every unknown assigned: the user's conditions checked
        if init.redundant:
            init.dropped = check_dropped(model, t0, z_guess, list(init.redundant), {},
                                         list(init.rows))
        return z_guess

    def F(z):
        try:
            extra = init.residual(t0, z, model.p, model.m)
        except DOMAIN_ERRORS as exc:
            _note_evaluation(model, init, t0, exc)
            extra = np.full(init.n, np.nan)
        return np.concatenate([model.G(t0, z), extra])

    # a system of the size the step loop factors densely is built and factored dense:
    # the same entries, and no scipy.sparse (whose import costs more than a mid-size
    # model's whole run, and a sweep's every worker would pay it)
    dense = model.n <= DENSE_MAX

    def J(z):
        try:
            extra = init.jacobian(t0, z, model.p, model.m, model.n, dense)
        except DOMAIN_ERRORS as exc:
            _note_evaluation(model, init, t0, exc)
            extra = np.full((init.n, model.n), np.nan)
        if dense:
            return np.vstack([model.dG_dy(t0, z, dense=True), extra])
        import scipy.sparse as sps
        return sps.vstack([model.dG_dy(t0, z), sps.csr_matrix(extra)]).tocsc()

    def weights(z):
        # on the iterate's own scale, never finer than the guess's
        return 1.0 / (_NEWTON_RTOL * np.maximum(np.abs(z), np.abs(z_guess))
                      + _NEWTON_RTOL * model.nominal)
    model.evaluation_errors.clear()
    dropped, coords = _choose_conditions(model, t0, z_guess) \
        if init.redundant and not free else (list(init.redundant), {})
    x0, scale, names, split = z_guess, model.nominal, model.names, None
    if free:          # the unknowns are [z; p_free]: the values found are written into p
        F, J, x0, weights, scale, names, split = augmented(model, F, J, z_guess, weights,
                                                           dense)
    try:
        z = solve_with_fallback(F, J, x0.copy(), weights, f"initialization at t = {t0}",
                                names, lambda k: _row_name(model, k), t0)
    except InitializationFailed as err:
        z = _indeterminate(model, t0, F, J, x0, weights, scale, names, err)
        if z is None:
            if model.evaluation_errors:
                err.args = (f"{err.args[0]}; {model.evaluation_errors[0]}",) + err.args[1:]
            raise
    if split is not None:
        z = split(z).copy()
        check_found(model, t0)
    if dropped:
        init.dropped = check_dropped(model, t0, z, dropped, coords, list(init.rows))
    return z


def _choose_conditions(model, t0, z):
    """An over-specified problem: the initial rows kept, chosen numerically at the start
    point (:func:`.redundant.choose_rows`); returns the user's conditions dropped and
    the coordinates that name what each conflicts with."""
    init = model.initial
    try:
        dG = model.dG_dy(t0, z, dense=True)
        dI = init.jacobian_all(t0, z, model.p, model.m, model.n)
    except DOMAIN_ERRORS:
        return list(init.redundant), {}
    dG, dI = np.asarray(dG, dtype=float), np.asarray(dI, dtype=float)
    if not (np.all(np.isfinite(dG)) and np.all(np.isfinite(dI))):
        return list(init.redundant), {}
    order = list(range(init.code.n_rows))      # the user's conditions first, as written
    chosen, coords = choose_rows(dG, dI, model.state_index, model.algebraic_index,
                                 np.abs(z) + model.nominal, order, len(init.rows))
    if chosen is None:                         # keep the structural choice: Newton says why
        return list(init.redundant), {}
    init.select(sorted(chosen))
    kept = set(chosen)
    return [k for k in range(init.n_mandatory) if k not in kept], coords


def _indeterminate(model, t, F, J, x0, weights, scale, names, err):
    """After a singular Jacobian: a solution of the consistent singular system, the one
    nearest the guess (:mod:`acausal.runtime.indeterminate`), noted in the report; None
    when the failure was not a singular Jacobian or the system has no solution."""
    if err.residual is not None:       # a failure to converge, not a singular Jacobian
        return None
    found = minimum_norm_newton(F, J, x0, weights, scale)
    if found is None:
        return None
    x, null = found
    report = getattr(model, "report", None)
    free = null_variables(null, names)
    note = (f"at t = {t:.6g} the equations determine {', '.join(free) or 'some unknowns'} "
            "only in combination (a singular, consistent system, e.g. friction elements "
            "locked on one motion sharing a torque): the solution nearest the guess is "
            "taken")
    if report is not None and note not in report.notes:
        report.notes.append(note)
    return x


def reinitialize(model, t: float, z: np.ndarray, zp=None, *, rtol=1e-6, atol=1e-6):
    """After an event: the states kept, G(t, z) = 0 solved for the algebraic unknowns,
    then consistent z' of every unknown."""
    z = np.array(z, dtype=float)
    alg, F, J = algebraic_system(model, t, z)
    if alg.size:
        # atol: one number, or one per unknown (simulate(atol={name: value}))
        atol_v = (atol[alg] if np.ndim(atol) else atol) * model.nominal[alg]

        def weights(za):
            # on the iterate's own scale: an unknown that the event takes from 0 to
            # 2e9 (a rate after a switch) is not judged on its value before it
            return 1.0 / (rtol * np.maximum(np.abs(za), np.abs(z[alg])) + atol_v)
        model.evaluation_errors.clear()
        labels = [model.names[i] for i in alg]
        try:
            z[alg] = solve_with_fallback(F, J, z[alg].copy(), weights,
                                         "consistent algebraic values after the event",
                                         labels, lambda k: _row_name(model, k), t)
        except InitializationFailed as err:
            found = _indeterminate(model, t, F, J, z[alg].copy(), weights,
                                   model.nominal[alg], labels, err)
            if found is None:
                raise
            z[alg] = found
    return z, consistent_derivatives(model, t, z)


_OUTPUT_ITERATIONS = 4   # Newton iterations for the values at an output time


def consistent_output(model, t: float, z: np.ndarray, rtol: float):
    """z at a requested output time between steps, with the algebraic unknowns solved
    from G(t, z) = 0 and the states at their interpolated values; None when Newton does
    not converge there (the interpolated values are then kept, and counted).

    Why: an algebraic unknown left out of the error test (a derivative solved as an
    unknown, without a nominal of its own: solver contract item 6) is exact at every
    step, but nothing bounds its interpolant between steps.  Where it determines no
    state -- a node pair's voltage derivative that follows a fast source while every
    state stays at rest -- the steps grow long and its interpolated values, and every
    output computed from them, are far from the solution.  The values at output times
    are therefore computed from the interpolated states by the model's equations, as
    a tool integrating the states alone computes its algebraic variables.  Only models
    with such unknowns need it (:attr:`CompiledModel.uncontrolled`); the others'
    interpolants are held to the tolerance by the error test.

    Output times are usually close together, so the factorization of the last one is
    used again (a chord iteration) while it converges, and made afresh where it does
    not: a point then costs a residual and a solve."""
    alg = model.algebraic_index
    z = np.array(z, dtype=float)
    if not alg.size:
        return z
    kept = getattr(model, "_output_lu", None)
    lin = kept[1] if kept is not None and kept[0] is model._jac_indptr else None
    for fresh in ((False, True) if lin is not None else (True,)):
        if fresh:
            lin = _output_factor(model, t, z, alg, rtol)
            if lin is None:
                return None
            model._output_lu = (model._jac_indptr, lin)
        trial = z.copy()
        if _chord(model, t, trial, alg, lin, rtol):
            return trial
    return _damped(model, t, z, rtol)


def _damped(model, t, z, rtol):
    """z with its algebraic unknowns found by damped Newton from the interpolated values,
    where the chord iteration does not converge (a steep algebraic relation, whose
    interpolant between two long steps is far from its value); None if that fails."""
    alg, F, J = algebraic_system(model, t, z)
    nominal = model.nominal[alg]
    try:
        found = damped_newton(F, J, z[alg].copy(), tol=0.5,
                              weights=lambda za: 1.0 / (rtol * (np.abs(za) + nominal)))
    except (SingularMatrixError, ArithmeticError):
        return None
    if not found.converged:
        return None
    z = z.copy()
    z[alg] = found.x
    return z


def _output_factor(model, t, z, alg, rtol):
    """The LU of dG/dz over the algebraic unknowns at (t, z), or None if singular; a
    consistent rank-deficient one (friction elements locked on one motion) is factored
    for minimum-norm corrections, as the integrator's (:mod:`acausal.solvers.linalg`)."""
    dense = model.n <= DENSE_MAX
    try:
        J = model.dG_dy(t, z, dense=dense)
        lin = LinearSolver(alg.size, not dense)
        lin.factor(J[:, alg] if dense else J.tocsc()[:, alg])
        return lin
    except SingularMatrixError:
        pass
    # the sparse form carries the structure the rank-deficient factorization judges
    weights = 1.0 / (rtol * (np.abs(z[alg]) + model.nominal[alg]))
    try:
        lin = LinearSolver(alg.size, not dense)
        lin.factor(model.dG_dy(t, z).tocsc()[:, alg], weights)
    except SingularMatrixError:
        return None
    return lin


def _chord(model, t, z, alg, lin, rtol) -> bool:
    """Newton's corrections with the factorization ``lin``, in place, until the last is
    half the tolerance (what is left is that times the contraction rate, small for a
    matrix of a nearby point); False if they stall or the residual is not finite."""
    last = np.inf
    nominal = model.nominal[alg]
    for _ in range(_OUTPUT_ITERATIONS):
        g = model.G(t, z)
        try:
            dx = lin.solve(g)
        except SingularMatrixError:        # rank-deficient and inconsistent here
            return False
        if not np.isfinite(dx.sum()):
            return False
        za = z[alg] - dx
        z[alg] = za
        scaled = dx / (rtol * (np.abs(za) + nominal))
        size = math.sqrt(scaled.dot(scaled) / scaled.size)
        if size <= 0.5:
            return True
        if not size < 0.5 * last:
            return False
        last = size
    return False


def algebraic_system(model, t: float, z: np.ndarray):
    """``(alg, F, J)``: G(t, z) = 0 as a function of the algebraic unknowns ``z[alg]``
    alone, the states (and the discrete state) held at their values in ``z``."""
    alg = model.algebraic_index

    def F(za):
        zz = z.copy()
        zz[alg] = za
        return model.G(t, zz)

    def J(za):
        zz = z.copy()
        zz[alg] = za
        return model.dG_dy(t, zz).tocsc()[:, alg]

    return alg, F, J


def consistent_derivatives(model, t: float, z: np.ndarray) -> np.ndarray:
    """z' of every unknown: the states' from the model, the others from
    G_A z'_A = -(G_S z'_S + G_t) (module docstring)."""
    zp = np.zeros(model.n)
    S = model.state_index
    if S.size:
        zp[S] = model.state_derivatives(t, z)
    alg = model.algebraic_index
    if not alg.size:
        return zp
    Gz = model.dG_dy(t, z).tocsc()
    dt = 6e-6 * (1.0 + abs(t))          # about eps^(1/3): central differences in t
    Gt = (model.G(t + dt, z) - model.G(t - dt, z)) / (2.0 * dt)
    rhs = -(Gz[:, S] @ zp[S] + Gt) if S.size else -Gt
    A = Gz[:, alg]
    if not np.all(np.isfinite(rhs)) or A.shape[0] != A.shape[1]:
        return zp
    lin = LinearSolver(alg.size, alg.size > 60)
    try:
        lin.factor(A)
        zp[alg] = lin.solve(rhs)
    except SingularMatrixError as err:
        # the index-1 system is singular here although the structure said it is not:
        # Pryce's success condition (a nonsingular system Jacobian at a consistent point)
        # fails at this point; said in the report, z'_A left at 0
        _note_singular(model, t, err, alg)
    return zp


def _note_evaluation(model, init, t, exc) -> None:
    """An initial equation outside a function's domain (sqrt of a negative start
    value): kept in the user's words for the failure message."""
    what = failing_statement(init.code.source, exc, init.all_descriptions,
                             model.meta.get("assigned_names", [])) or \
        "evaluating the initial equations"
    note = f"{what} failed at t = {t:.6g}: {type(exc).__name__}: {exc}"
    if note not in model.evaluation_errors:
        model.evaluation_errors.append(note)


def _note_singular(model, t, err, alg) -> None:
    report = getattr(model, "report", None)
    if report is None or getattr(model, "_singular_noted", False):
        return
    # once per model: naming the block analyses the matrix (an SVD), and a model whose
    # charges' potentials are related only through the charges' balance meets it after
    # every event
    model._singular_noted = True
    eqs = [model.equation_names[r] for r in err.rows[:4]] if err.rows else []
    cols = [model.names[alg[c]] for c in err.cols[:4]] if err.cols else []
    note = (f"structural analysis fails at t = {t:.6g}: the Jacobian of the equations with "
            "respect to the algebraic unknowns is singular there"
            + (f" (equations {eqs}, variables {cols})" if eqs or cols else "")
            + "; the index and the states found structurally do not hold at this point")
    if note not in report.notes:
        report.notes.append(note)


def _row_name(model, k):
    names = model.equation_names
    if k < model.n_res:
        return names[k] if k < len(names) else f"equation {k}"
    return model.initial.descriptions[k - model.n_res]
