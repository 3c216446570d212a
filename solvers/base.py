"""The contract between a compiled model and the DAE integrators.

A model reaches the solvers as a :class:`DAEProblem`: a fully implicit, index-1 system

    F(t, y, y') = 0,        y(t0) = y0,  y'(t0) = yp0,

with the parameters already bound.  The solvers never see names; ``problem.names`` is
used only to word error messages in the user's terms.

What a problem provides (numbered, so integrators can cite it)
---------------------------------------------------------------
1. ``n``: the size of y.
2. ``residual(t, y, yp) -> ndarray(n)``: F.
3. ``jacobian(t, y, yp, cj) -> ndarray | scipy.sparse matrix``: the iteration matrix
   dF/dy + cj dF/dy'.  It is linear in cj, so dF/dy' = jacobian(.., 1) - jacobian(.., 0).
4. ``jac_pattern``: a ``(rows, cols)`` pair of int arrays, the structural non-zeros of
   the iteration matrix (for sparse LU), or None for dense.
5. ``algebraic``: bool mask, True where y'_i appears in no equation.
6. ``nominal``: positive array; error weights use ``rtol*|y_i| + atol*nominal_i``.
   Optional ``self_scaled``: bool mask of algebraic components without a nominal of
   their own (derivatives solved as unknowns, variables kept for fill by
   ``compiler/structure/causalize.py``); the error and Newton tests leave them
   out (weight 0), judging them through the unknowns they determine.
   Optional ``error_test``: ``"all"`` (the default) or ``"states"``: what the local
   error test covers unless the caller says (:mod:`acausal.solvers.bdf`).
7. ``names``: the user's name of each y_i (for messages).
8. Events (optional, ``n_roots > 0``): ``roots(t, y, yp) -> ndarray(n_roots)`` are the
   zero-crossing functions; while integrating, the discrete state (modes, relations) is
   frozen.  At a located crossing the driver calls
   ``handle_event(t, y, yp, crossed) -> EventAction`` (``crossed`` is a bool mask of
   the functions that changed sign; the problem updates its discrete state, may reinit
   y, and says whether to stop).  ``time_events`` lists known times of discontinuity
   (steps, pulses) where the integrator must stop and restart; for unbounded
   sequences (periodic pulses, samplers) a problem may instead define
   ``next_time_event(t) -> float | None``, the first such time after ``t``.  There
   ``handle_event`` is called with ``crossed`` all False, so that relations on time
   can be kept frozen like the others and switched there.  After any event the
   driver re-initializes the algebraic part of y and y' (differential y as left by
   the event) and restarts the BDF at order 1.
9. Initialization (optional).  Without it, the differential components of y0 are
   trusted and the algebraic components of y plus all of y' are computed (IDA's
   ``YA_YDP_INIT``).  A problem whose initial state is fixed otherwise (steady state,
   start values on algebraic variables, ...) defines

   * ``init_residual(t, y, yp) -> ndarray(m)``: extra equations G = 0 that hold at the
     initial time only.  The unknowns are then *all* of y plus y' of the differential
     components (``n + n_d`` of them), the equations F = 0 and G = 0; normally
     ``m = n_d`` (e.g. ``y_i - start_i`` for a fixed state, ``yp_i`` for a steady
     state).  A non-square system is solved in the least-squares sense (Gauss-Newton,
     minimum-norm steps from y0) and accepted only if all residuals vanish.
   * ``init_jacobian(t, y, yp) -> (dG/dy, dG/dyp)`` (optional; two (m, n) matrices,
     dense or sparse); without it G is differenced.
   * ``init_equation_names`` (optional): labels of the m initial equations.

   ``y0``/``yp0`` given to the integrator are the start guesses.  Failure raises
   :class:`InitializationFailed`.
10. ``equation_names`` (optional): a label per residual, used in messages about
   singular iteration matrices and failed initialization.
11. ``after_step(t, y, yp) -> bool`` (optional): called after every accepted step
   without an event; returning True means the problem changed its formulation (e.g.
   another choice of states); y means the same after the change, so the driver keeps
   the BDF's history, order and step and only forms a new iteration matrix.  (For a
   compiled model the compiled step loop does the hook's work in C -- it releases
   armed offsets, and tests the choice of states, :mod:`acausal.solvers.cbdf_dyn` --
   and the hook runs only after steps that return to Python: a stop time, a sign
   change, or a choice of states found degraded.)
12. ``reinitialize(t, y, yp, rtol=, atol=) -> (y, yp)`` (optional): the problem's own
   consistent re-initialization after an event (it replaces ``YA_YDP_INIT``).
13. Oriented roots and the discrete state (optional).  A problem with
   ``oriented_roots = True`` returns zero-crossing functions that are >= 0 while its
   discrete state agrees with the solution: the driver arms every one with reference
   sign +1 (also where it is 0) and reports a crossing where one reaches zero or below
   at the end of a step, located to within the time resolution; such a problem settles
   its discrete state completely in ``handle_event`` (its own event iteration), so the
   driver does not iterate on the functions' signs.  ``arm(t, y, yp, resolution)``
   (optional) is called whenever the functions are (re)armed, with the time to within
   which the driver locates a crossing.  ``discrete_state()``
   (optional) returns a copy of the discrete state: the driver records, for every output
   point, the state it was computed in (``SolverOutput.discrete_states`` and
   ``discrete_index``), so that results are evaluated in the modes that were integrated.
14. ``max_step`` (optional float): the problem's own bound on the step size, combined
   with the caller's (a model with delays: the shortest delay time).
15. ``commit(t_lo, t_hi, interpolate, rtol=)`` (optional): called by the driver once
   the solution on [t_lo, t_hi] is final -- after every accepted step, or up to a
   located event before the event is handled -- with ``interpolate(t) -> (y, y')``
   valid on it (the integrator's dense output) and the run's relative tolerance.  A
   problem with delays keeps its history so.
16. ``point_values(t) -> ndarray | None`` (optional): values the problem wants recorded
   with every output point (``SolverOutput.point_values``, one row per point): the
   delayed values, which results need after the history is gone.

17. ``output_point(t, y, rtol, every=False) -> y | None`` (optional): y at a requested
   output time that falls between steps, given its interpolated value; the problem may
   solve components the error test does not bound between steps (item 6) from its
   equations, and with ``every`` (the error test leaves algebraic components out:
   ``error_test="states"``, or a recovery, :mod:`.recovery`) it solves every algebraic
   one.  The driver also locates crossings on such values.  None: it could not, the interpolated value is kept and counted
   (``SolverStats.interpolated_outputs``).
18. ``loop_model() -> LoopModel | None`` (optional): a model whose residual, Jacobian
   and zero-crossing functions are generated gives their layout (:class:`LoopModel`),
   so that a compiled step loop (:mod:`acausal.solvers.cbdf`) can call them and
   assemble F, the iteration matrix and the oriented roots (item 13) itself; None
   where it cannot run there.  The loop reads nothing else of the problem.
19. ``check_point(t, y, m, every=False) -> str | None`` (optional, may be None): whether
   the values the problem computes from an output point (y, in the discrete state
   ``m``) are finite -- all of them with ``every`` (the first point of a run), else
   those that need it (its ``every_point`` False: none); a sentence saying which is
   not ends the run as a failure (``nonfinite="warn"``: said, and the run goes on).
   The driver itself checks that y is finite at every output point.

18. ``tolerances(rtol, atol)`` (optional): called once before a run with its
   tolerances (a compiled model bounds the hysteresis it gives a relation that chatters
   on round-off by atol).

What a solver counts (``SolverStats``): steps, residual evaluations, Jacobian
evaluations, LU factorizations, Newton iterations, error-test failures, Newton
(convergence) failures, events, the steps taken at each order, the order reductions
made by stability limit detection, and which LU
(dense or sparse) and which step loop ran.

What a solver returns (``SolverOutput``): accepted times ``t``, values ``y`` and
derivatives ``yp`` (rows = time), ``success``, ``message``, ``stats``, and the event
times.  A run that fails raises :class:`SimulationError` whose ``partial`` is the
``SolverOutput`` computed up to the failure, with the reason.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Sequence

import numpy as np
from ..errors import InitializationFailed, SimulationError


__all__ = ["DAEProblem", "EventAction", "root_label", "LoopModel", "SolverStats", "SolverOutput",
           "SimulationError", "InitializationFailed"]


class DAEProblem:
    """Base class of everything a DAE integrator can solve (see the module docstring)."""

    n: int = 0
    n_roots: int = 0
    jac_pattern: tuple[np.ndarray, np.ndarray] | None = None
    time_events: Sequence[float] = ()

    def __init__(self, n: int, names: Sequence[str] | None = None):
        self.n = int(n)
        self.names = list(names) if names is not None else [f"y[{i}]" for i in range(n)]
        self.algebraic = np.zeros(self.n, dtype=bool)
        self.nominal = np.ones(self.n)

    def residual(self, t: float, y: np.ndarray, yp: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def jacobian(self, t: float, y: np.ndarray, yp: np.ndarray, cj: float):
        """dF/dy + cj*dF/dy'; the default differences the residual (dense)."""
        return numerical_jacobian(self, t, y, yp, cj)

    def roots(self, t: float, y: np.ndarray, yp: np.ndarray) -> np.ndarray:
        return np.empty(0)

    def handle_event(self, t: float, y: np.ndarray, yp: np.ndarray,
                     crossed: np.ndarray) -> "EventAction":
        return EventAction()


@dataclass
class EventAction:
    """What a problem asks of the driver after an event.

    ``y``: new values (None: unchanged; the driver re-initializes the algebraic part and
    y' consistently either way).  ``stop``: end the simulation here (terminate()).
    ``changed``: whether any discrete state or value changed (False ends event iteration).
    """

    y: np.ndarray | None = None
    stop: bool = False
    changed: bool = True
    message: str = ""


@dataclass
class LoopModel:
    """What a compiled step loop reads of a model (contract item 18).

    The model's rows are ``F = [G(t, z); z'[state_z] - D(t, z); z'[link_s] - z[link_d]]``:
    the generated residual returns G then D (``n_rows`` values, the first ``n_res`` of
    them G).  Its Jacobian returns the values at ``(jac_rows, jac_cols)`` of dG/dz and
    dD/dz; ``jac_sign`` is +1 on G's rows and -1 on D's (they enter F negated).  Each
    generated function is either the address of a C function
    ``int f(double t, const double *z, const double *p, const double *m, double *out,
    double *work)`` (``work``: ``n_work`` doubles) or a Python callable
    ``f(t, z, out)`` that writes ``out`` in place (raising where it fails).  The roots
    are the relations' values ``g`` (``n_rel`` of them, oriented by ``orientation()``,
    which returns ``(sign, side, nominal)``: ``sign * g + side * (1e-10 |scale| + 1e-12
    nominal)``, the nominal term carrying a chattering relation's hysteresis, all three
    changing only with the discrete state) followed by the frozen
    integer values' arguments (``n_disc``, each two oriented functions), plus
    ``offset``; ``timed`` marks the items that are functions of time alone.  ``p`` and
    ``m`` are the model's own parameter and discrete-state arrays (read by address).
    ``links()`` gives the current linking rows and the iteration matrix's CSC pattern
    ``(link_s, link_d, indptr, indices, slot)``: they change with dynamic state
    selection, whose test of the current choice ``dynamic_test()`` describes (None
    without dynamic states; ``acausal.solvers.cbdf_dyn``).  ``cache`` is a dict the
    solver may keep what it learned about the model in (the sparse LU's analysis),
    for its next runs."""

    functions: dict
    n_work: int
    n_rows: int
    n_res: int
    state_z: np.ndarray
    jac_rows: np.ndarray
    jac_cols: np.ndarray
    jac_sign: np.ndarray
    n_rel: int
    n_disc: int
    root_nominal: np.ndarray
    timed: np.ndarray
    p: np.ndarray
    m: np.ndarray
    offset: np.ndarray
    orientation: object
    links: object
    dynamic_test: object = None
    cache: dict = field(default_factory=dict)


@dataclass
class SolverStats:
    steps: int = 0
    residual_evaluations: int = 0
    jacobian_evaluations: int = 0
    lu_factorizations: int = 0
    newton_iterations: int = 0
    error_test_failures: int = 0
    newton_failures: int = 0
    events: int = 0
    orders: dict = field(default_factory=dict)
    stability_limit_reductions: int = 0   # order lowered by stability limit detection
    linear_solver: str = ""      # "dense" or "sparse" LU, as chosen for the problem
    lu: str = ""                 # which: "compiled", "numpy", "lapack" or "superlu"
                                 # (solvers.linalg.LinearSolver.kind)
    step_loop: str = "python"    # where the steps ran: "python" or "c" (solvers.cbdf)
    interpolated_outputs: int = 0   # output times whose item-17 solve failed
    relaxed_components: int = 0     # algebraic components the driver took out of the
                                    # error test to recover a step (solvers/recovery.py)
    relaxed_at: float = None        # the time it first did, and the components' names
    relaxed_names: list = field(default_factory=list)
    forced_steps: int = 0           # steps accepted without the error test (the same)
    error_test: str = ""            # what the error test covered: "all" or "states"

    def as_dict(self) -> dict:
        return dict(self.__dict__)


@dataclass
class SolverOutput:
    t: np.ndarray
    y: np.ndarray
    yp: np.ndarray
    success: bool
    message: str
    stats: SolverStats
    event_times: list = field(default_factory=list)
    discrete_states: list = field(default_factory=list)   # snapshots (item 13)
    discrete_index: list = field(default_factory=list)    # per point: its snapshot
    point_values: list = field(default_factory=list)      # per point, item 16


def unbounded(algebraic, self_scaled) -> np.ndarray:
    """The components the error test leaves out (item 6): algebraic and self-scaled,
    unless every component is (a problem with nothing else to judge them by)."""
    mask = np.asarray(algebraic, bool) & (False if self_scaled is None
                                           else np.asarray(self_scaled, bool))
    if mask.all():
        mask[:] = False
    return mask


def equation_label(problem: DAEProblem, i: int) -> str:
    """The user's label of residual ``i`` (``problem.equation_names`` if present)."""
    names = getattr(problem, "equation_names", None)
    if names is not None and 0 <= i < len(names):
        return str(names[i])
    return f"residual {i}"


def root_label(problem: DAEProblem, k: int) -> str:
    """The user's words for root function ``k`` (``problem.root_label(k)`` if present)."""
    label = getattr(problem, "root_label", None)
    if label is not None:
        try:
            return str(label(k))
        except (IndexError, ValueError):
            pass
    return f"root function {k}"


def numerical_jacobian(problem: DAEProblem, t, y, yp, cj):
    """Forward-difference iteration matrix, column by column (fallback only)."""
    f0 = problem.residual(t, y, yp)
    n = problem.n
    J = np.empty((n, n))
    for j in range(n):
        h = 1e-7 * max(abs(y[j]), problem.nominal[j])
        y1 = y.copy()
        yp1 = yp.copy()
        y1[j] += h
        yp1[j] += cj * h
        J[:, j] = (problem.residual(t, y1, yp1) - f0) / h
    return J
