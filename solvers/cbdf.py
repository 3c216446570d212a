"""The BDF step loop compiled: :class:`CompiledBDF`, the C twin of :class:`~.bdf.BDF`.

Why: with the generated model code in C, a step of the Python loop spends about 95 % of its time in the interpreter (coefficients, predictor,
Newton iterations, error test, one ctypes call per residual).  ``cbdf.c`` runs the same
method -- the same coefficients, corrector, error test and order/step control, statement
for statement -- in C, and calls the model's generated residual, Jacobian and
zero-crossing functions directly through function pointers, so a step costs a few
microseconds on a small model.

What stays in Python (the driver, :mod:`acausal.solvers.driver`): initialization, the
first step after an event (:func:`~.first_step.probed_step`), locating and handling
events, and output assembly.  ``cbdf_run`` takes steps until something needs Python --
a zero-crossing function changed sign, a step landed on the stop time (a time event or
t_end), the output buffer is full, the step budget is used, or a step failed -- and
returns with the whole state -- one struct, ``cbdf_state`` of ``cbdf.h``, which Python
reads from that header (:mod:`.cbdf_layout`) -- whose divided differences ``phi``,
``h``, order and coefficients :meth:`CompiledBDF.run` copies back into the attributes
the driver and :meth:`BDF.interpolate` read.  Output at requested times is the BDF
interpolant, evaluated in C.

A step whose iteration matrix the C loop finds singular is taken by the Python loop
(:meth:`BDF.step` on the same state), which may solve a consistent rank-deficient matrix
in the minimum-norm sense (:mod:`.linalg`: friction elements locked on one motion) and
refuses an inconsistent one; the following steps stay in Python while its matrix stays
rank-deficient, then return to C.

With dynamic state selection the loop also tests, after every step, whether the current
choice of states is still good enough (:mod:`.cbdf_dyn`), and returns to Python only for
the search when it is not; a new choice comes back as other active linking rows, the
history kept.

When it is used (``step_loop="auto"``): the problem gives the layout of its generated
functions (solver contract item 18, :class:`~.base.LoopModel`: a compiled model, which
reads nothing else of the problem) -- on the C backend its functions are C; on the
numpy backend its generated functions are called back through the same pointers
(:mod:`.cbdf_callbacks`, as IDA calls a Python residual) -- without ``delay()`` (whose
history is kept in Python after every step) or stability limit detection, and, with
dynamic state selection, at most :data:`MAX_DENSE` unknowns (the sparse LU keeps one
pattern, which a new choice of states changes), and the loop's library was built when
acausal was installed (:mod:`.cbdf_library`).  Up to
:data:`MAX_DENSE` unknowns the C loop factors dense (``cbdf_lu.c``); above, sparse, on the
model's fixed Jacobian pattern with the column order and pivot rows of one SuperLU
analysis (``cbdf_sparse.c``, :mod:`~acausal.solvers.cbdf_sparse`).  ``step_loop="c"``
also runs any other problem of at most :data:`MAX_DENSE` unknowns, calling its Python
residual, Jacobian and zero-crossing functions back (mode 1: the problem's functions,
not a model's generated ones; for tests against the Python loop, no faster).  Without the
library ``"auto"`` is the Python loop.  Results agree with the
Python loop to the integration tolerance, not bitwise: the LU is not LAPACK's or
SuperLU's, so the iteration matrix's solutions differ in rounding.
"""
from __future__ import annotations

import ctypes

import numpy as np

from . import cbdf_sparse as sparse_lu
from .bdf import _ALPHAS, BDF, MAX_CRAWL, MAX_ORDER, StepFailure
from .cbdf_callbacks import Callbacks, problem_callbacks
from .cbdf_dyn import bind as bind_dynamic
from .cbdf_layout import CbdfState
from .cbdf_library import library
from .linalg import DENSE_MAX, LinearSolver, singular_block
from ..errors import BackendError

__all__ = ["CompiledBDF", "MAX_DENSE", "STEP_LOOPS", "choose_step_loop", "library",
           "R_BUDGET", "R_FULL", "R_SPECIAL", "R_FAIL"]

MAX_DENSE = DENSE_MAX    # largest system the compiled loop factors dense (above: sparse LU)
STEP_LOOPS = ("auto", "c", "python")
CAPACITY = 512           # output points per return to Python (fewer above MAX_DENSE)

R_BUDGET, R_FULL, R_SPECIAL, R_FAIL = range(4)     # what cbdf_run returns (cbdf.c)
F_SINGULAR, F_NONFINITE = 4, 5                     # two of its failure kinds
_KINDS = {1: "error_test", 2: "newton", 3: "step_size", 4: "singular", 5: "singular",
          6: "crawl"}


def _loop_model(problem):
    """The problem's :class:`~.base.LoopModel` (contract item 18), or None."""
    make = getattr(problem, "loop_model", None)
    return make() if callable(make) else None


def choose_step_loop(problem, step_loop: str, stald: bool) -> int | None:
    """How the steps are taken: 0 (C, the model's generated functions), 1 (C, calling the
    problem's Python functions back; only when asked for), or None (the Python loop).
    The choice depends on the problem, the options and the installation only."""
    if step_loop not in STEP_LOOPS:
        raise ValueError(f"step_loop must be one of {', '.join(map(repr, STEP_LOOPS))}, "
                         f"got {step_loop!r}")
    if step_loop == "python":
        return None
    model = _loop_model(problem) is not None
    why = None
    if problem.n > MAX_DENSE and not model:
        why = (f"it has {problem.n} unknowns, more than {MAX_DENSE} (dense LU; the "
               "sparse LU needs a compiled model)")
    elif problem.n > MAX_DENSE and getattr(problem, "dynamic", None) is not None:
        why = (f"it has {problem.n} unknowns, more than {MAX_DENSE}, and dynamic state "
               "selection (the sparse LU keeps one pattern)")
    elif stald:
        why = "stability limit detection runs in the Python loop"
    elif getattr(problem, "delays", None) is not None:
        why = "delay() keeps the history of every accepted step in Python"
    elif getattr(problem, "inputs_vary", False):
        why = "its inputs are functions of time, evaluated in Python before every call"
    elif not model and getattr(problem, "after_step", None) is not None:
        why = "its after_step hook runs in Python after every step"
    if step_loop == "auto":
        return 0 if model and why is None and library() is not None else None
    if why is not None:
        raise ValueError(f"step_loop='c' is not available for this problem: {why}")
    if library() is None:
        raise BackendError("step_loop='c': the compiled step loop is not installed "
                           "(acausal was installed without a working C compiler; "
                           "install one and reinstall acausal)")
    return 0 if model else 1


def _ptr(a: np.ndarray) -> int:
    return a.__array_interface__["data"][0]     # cheaper than a.ctypes.data


class CompiledBDF(BDF):
    """:class:`BDF` whose steps run in C (module docstring); ``mode`` as returned by
    :func:`choose_step_loop`.  The attributes the driver reads (``t``, ``t_prev``, ``y``,
    ``yp``, :meth:`interpolate`) are those of :class:`BDF`, brought up to date after
    every :meth:`run`."""

    def __init__(self, problem, t0, y0, yp0, *, mode: int = 0, **options):
        n = problem.n
        self.lib = library()
        self.mode = mode
        self.callbacks = None       # the Python functions the loop calls back, if any
        self.st = st = CbdfState()
        self._st_ptr = ctypes.pointer(st)
        st.alphas[:MAX_ORDER + 2] = _ALPHAS
        self._keep = {}
        # above MAX_DENSE unknowns (a compiled model) the LU is sparse: cbdf_sparse.c
        self.sparse = mode == 0 and n > MAX_DENSE
        st.sparse = self.sparse
        dense = 0 if self.sparse else n * n
        self._buf("scratch", dense + 13 * n)
        self._buf("lu", max(dense, 1))
        self._buf("piv", n, np.int64)
        for name in ("weighted", "last_err", "yp", "fail_y", "fail_yp"):
            self._buf(name, n)
        # a large system's buffer is shorter: allocating (and zeroing) 2 x 512 x n
        # doubles costs milliseconds, a return to Python per 64 points microseconds
        cap = CAPACITY if n <= MAX_DENSE else max(64, min(CAPACITY, 2**17 // max(n, 1)))
        self.out_t = self._buf("out_t", cap)
        self.out_y = self._buf("out_y", (cap, n))
        self.out_yp = self._buf("out_yp", (cap, n))
        nr = int(getattr(problem, "n_roots", 0) or 0)
        for name in ("g", "g_prev", "sign_ref"):
            self._buf(name, max(nr, 1))
        st.n, st.n_roots, st.mode, st.capacity = n, nr, mode, cap
        self._n_roots = nr
        self.model = _loop_model(problem) if mode == 0 else None
        if mode == 0:
            self._bind_model(self.model, n)
        else:
            self._bind_callbacks(problem)
        super().__init__(problem, t0, y0, yp0, **options)
        st.phi = self._pointer(self.phi)
        self._splu = None
        self.pending = False
        self._in_python = False     # steps taken by the Python loop (module docstring)
        self._python_failure = None

    # ------------------------------------------------------------------ buffers
    def _pointer(self, a: np.ndarray):
        """``a`` as the struct's pointer field wants it (the array is kept alive)."""
        kind = ctypes.c_int64 if a.dtype == np.int64 else ctypes.c_double
        return ctypes.cast(_ptr(a), ctypes.POINTER(kind))

    def _buf(self, name, shape, dtype=float):
        """A zeroed buffer of the loop, its address in the struct field ``name``."""
        a = np.zeros(shape, dtype=dtype)
        self._keep[name] = a
        setattr(self.st, name, self._pointer(a))
        return a

    def _set(self, name, array, dtype=float):
        """The struct field ``name`` pointing at a contiguous copy of ``array``."""
        a = np.ascontiguousarray(array, dtype=dtype)
        if a.size == 0:
            a = np.zeros(1, dtype=dtype)
        self._keep[name] = a
        setattr(self.st, name, self._pointer(a))

    def _share(self, name, array):
        """The struct field ``name`` pointing at ``array`` itself (the model's own)."""
        self._keep[name] = array
        setattr(self.st, name, self._pointer(array))

    def _bind_sparse(self) -> None:
        """The sparse LU on the problem's Jacobian pattern, analysed at the current
        point; again whenever the pattern is another (a new choice of linked states
        makes a new one).  The analysis (SuperLU's orderings) is kept in the model's
        ``cache`` for its next runs: the C factorization pivots afresh where a kept pivot
        has become small (:mod:`.cbdf_sparse`), so values of another run need no new one."""
        m = self.model
        _, _, indptr, indices, slot = m.links()
        if self._splu is not None and self._splu_pattern is indptr:
            return
        kept = m.cache.get("sparse_analysis")
        perms = kept[1] if kept is not None and kept[0] is indptr else None
        self._splu = sparse_lu.SparseLU(self.lib, self.n, indptr, indices, slot,
                                        self.problem.jacobian(self.tn, self.y, self.yp,
                                                              self.cj), perms)
        if self._splu.perms is not None:
            m.cache["sparse_analysis"] = (indptr, self._splu.perms)
        self._splu_pattern = indptr
        self.st.splu = self._splu.handle
        self.force_setup = True

    # ------------------------------------------------------------------ binding
    def _bind_model(self, m, n: int) -> None:
        st = self.st
        if all(isinstance(f, int) for f in m.functions.values()):
            address = m.functions.__getitem__
        else:
            self.callbacks = Callbacks()
            address = lambda name: self.callbacks.address(  # noqa: E731
                m.functions[name], n, _N_OUT[name](m))
        st.residual_fn = address("residual")
        st.jacobian_fn = address("jacobian")
        self._buf("work", max(m.n_work, 1))
        self._buf("model_out", max(m.n_rows, 1))
        self._buf("jac_values", max(len(m.jac_rows), 1))
        self._set("jac_rows", m.jac_rows, np.int64)
        self._set("jac_cols", m.jac_cols, np.int64)
        self._set("jac_sign", m.jac_sign)
        self._set("state_z", m.state_z, np.int64)
        st.n_res, st.n_state_rows = m.n_res, len(m.state_z)
        st.n_jac, st.n_rows = len(m.jac_rows), m.n_rows
        st.n_rel, st.n_disc = m.n_rel, m.n_disc
        self._bind_links()
        if self._n_roots:
            st.roots_fn = address("roots")
            st.scales_fn = address("scales")
            self._buf("root_values", m.n_rel + m.n_disc)
            self._buf("root_scales", max(m.n_rel, 1))
            self._set("root_nominal", m.root_nominal)
            self._set("timed", m.timed)

    def _bind_links(self) -> None:
        """The current linking rows (a new choice of dynamic states changes them)."""
        link_s, link_d = self.model.links()[:2]
        self._set("link_s", link_s, np.int64)
        self._set("link_d", link_d, np.int64)
        self.st.n_links = len(link_s)

    def _bind_callbacks(self, p) -> None:
        """Mode 1: the problem's own residual, Jacobian and roots, called back."""
        self._callbacks = problem_callbacks(p, lambda: self.st.n_roots)
        st = self.st
        st.residual_fn, st.jacobian_fn, st.roots_fn = (
            ctypes.cast(cb, ctypes.c_void_p).value for cb in self._callbacks)
        self._buf("root_offset", max(self._n_roots, 1))

    # ------------------------------------------------------------------ state transfer
    _SCALARS = ("tn", "t_prev", "t_stop", "hh", "hused", "cj", "cjold", "cjlast",
                "cjratio", "ss", "kk", "kused", "phase", "ns", "nst", "kmax", "crawl")
    _COEFFICIENTS = ("psi", "alpha", "beta", "sigma", "gamma")
    _COUNTERS = ("n_residuals", "n_jacobians", "n_lu", "n_newton", "n_error_fails",
                 "n_newton_fails", "n_steps")

    def _push(self) -> None:
        st = self.st
        for name in self._SCALARS:
            setattr(st, name, getattr(self, name))
        st.rtol, st.max_step = self.rtol, self.max_step
        for name in self._COEFFICIENTS:
            getattr(st, name)[:MAX_ORDER + 2] = getattr(self, name)
        st.force_setup, st.max_order = bool(self.force_setup), self.max_order
        st.max_crawl = MAX_CRAWL
        for name in self._COUNTERS:
            setattr(st, name, 0)
        st.orders[:] = [0] * len(st.orders)

    def _pull(self) -> None:
        st = self.st
        for name in self._SCALARS:
            setattr(self, name, getattr(st, name))
        for name in self._COEFFICIENTS:
            setattr(self, name, list(getattr(st, name)[:MAX_ORDER + 2]))
        self.force_setup = bool(st.force_setup)
        self.y = self.phi[0].copy()
        if st.n_steps:
            self.yp = self._keep["yp"].copy()
        stats = self.stats
        stats.steps += st.n_steps
        stats.residual_evaluations += st.n_residuals
        stats.jacobian_evaluations += st.n_jacobians
        stats.lu_factorizations += st.n_lu
        stats.newton_iterations += st.n_newton
        stats.error_test_failures += st.n_error_fails
        stats.newton_failures += st.n_newton_fails
        for k in range(1, MAX_ORDER + 1):
            if st.orders[k]:
                stats.orders[k] = stats.orders.get(k, 0) + st.orders[k]
        if st.has_last:
            self._last_err = (self._keep["last_err"].copy(), np.ones(self.n))

    def restart(self, *args, **kwargs) -> None:
        super().restart(*args, **kwargs)
        self._set("atol", self.atol)
        self._set("ss_mask", np.where(self.self_scaled, 0.0, 1.0))
        self._set("err_mask", np.ones(self.n) if self.err_mask is None else self.err_mask)
        self._set("alg_mask", np.where(self.alg, 1.0, 0.0))
        self.st.any_algebraic = bool(self.alg.any())
        self.st.any_self_scaled = bool(self.self_scaled.any())
        self.st.has_last = 0

    def reformulate(self) -> None:
        """Another choice of states (dynamic state selection): the masks the C loop
        reads follow :meth:`BDF.reformulate`'s (the linking rows are bound by
        :meth:`run`)."""
        super().reformulate()
        self._set("ss_mask", np.where(self.self_scaled, 0.0, 1.0))
        self._set("alg_mask", np.where(self.alg, 1.0, 0.0))
        self.st.any_algebraic = bool(self.alg.any())
        self.st.any_self_scaled = bool(self.self_scaled.any())

    @property
    def reselect(self) -> bool:
        """The last :meth:`run` returned because the choice of states must be looked at
        again (``cbdf_dyn.c``)."""
        dl = self._keep.get("dyn_longs")
        return dl is not None and bool(dl[1])

    def step(self) -> None:
        """One step through the compiled loop, without looking at zero crossings (the
        driver uses :meth:`run`)."""
        code = self.run(1, None, 0, None, None)
        if code == R_FAIL:
            raise self.failure()

    # ------------------------------------------------------------------ the loop
    def run(self, budget, t_eval, i_eval, sign_ref, g_prev) -> int:
        """Steps in C until something needs Python (module docstring).  ``t_eval``
        (None: every step is output) from index ``i_eval``; ``sign_ref``/``g_prev``: the
        driver's armed signs and last values of the zero-crossing functions (updated in
        place).  Returns R_BUDGET, R_FULL, R_SPECIAL or R_FAIL; the points output are in
        :attr:`points`."""
        st, m = self.st, self.model
        if self._in_python:
            return self._python_step(i_eval)
        if self.sparse:
            self._bind_sparse()
        self._push()
        st.budget, st.count, st.pending = budget, 0, 0
        st.all_steps = t_eval is None
        if t_eval is not None:
            self._set("t_eval", t_eval)
            st.n_eval, st.i_eval = len(t_eval), i_eval
        nr = self._n_roots if sign_ref is not None else 0   # None: none watched (step())
        st.n_roots = nr
        if nr:
            self._keep["sign_ref"][:nr] = sign_ref
            self._keep["g_prev"][:nr] = g_prev
            if self.mode == 0:
                sign, side, nominal = m.orientation()
                self._set("root_sign", sign)
                self._set("root_side", side)
                self._set("root_nominal", nominal)
                self._share("root_offset", m.offset)
        if self.mode == 0:
            self._share("par", m.p)
            self._share("m", m.m)
            if m.dynamic_test is not None:
                self._bind_links()
                bind_dynamic(self, m.dynamic_test())
        code = self.lib.cbdf_run(self._st_ptr)
        st.n_roots = self._n_roots
        if self.callbacks is not None:
            self.callbacks.reraise()
        self._pull()
        if nr:
            sign_ref[:] = self._keep["sign_ref"][:nr]
            g_prev[:] = self._keep["g_prev"][:nr]
        k = st.count
        self.points = (self.out_t[:k].copy(), self.out_y[:k].copy(), self.out_yp[:k].copy())
        self.i_eval = st.i_eval
        self.pending = bool(st.pending)
        if code == R_FAIL and st.fail_kind == F_SINGULAR:
            return self._python_step(self.i_eval, self.points)
        return code

    def _python_step(self, i_eval, points=None) -> int:
        """One step of the Python loop from the current state (a singular iteration
        matrix: module docstring); R_SPECIAL (the driver handles the step as one that
        needs Python), or R_FAIL with its failure.  ``points``: the output of the C
        steps before it."""
        self.i_eval, self.pending = i_eval, False
        if points is None:
            n = self.n
            points = (np.empty(0), np.empty((0, n)), np.empty((0, n)))
        self.points = points
        self._python_failure = None
        try:
            BDF.step(self)
        except StepFailure as exc:
            self._in_python = False
            self._python_failure = exc
            return R_FAIL
        self._in_python = self.lin.deficient
        self.force_setup = True        # the C loop's factorization is not this one
        return R_SPECIAL

    def failure(self) -> StepFailure:
        """The :class:`StepFailure` of a failed :meth:`run`, worded as the Python loop's."""
        if self._python_failure is not None:
            return self._python_failure
        st = self.st
        kind = _KINDS.get(st.fail_kind, "step_size")
        t, h = st.fail_t, st.fail_h
        weighted = self._keep["weighted"].copy() if st.has_fail else None
        if kind == "singular":
            J = self.problem.jacobian(st.fail_tj, self._keep["fail_y"].copy(),
                                      self._keep["fail_yp"].copy(), st.fail_cj)
            if not self.sparse or st.fail_kind == F_NONFINITE:
                J = J.toarray() if hasattr(J, "toarray") else np.asarray(J, float)
            if st.fail_kind == F_NONFINITE:
                rows, cols = LinearSolver._nonfinite(J)
                msg = "iteration matrix has non-finite entries"
            else:
                rows, cols = singular_block(J)
                msg = "iteration matrix is singular"
            return StepFailure("singular", msg, t, h, rows=rows, cols=cols)
        if kind == "step_size":
            if weighted is None and st.has_last:
                weighted = self._keep["last_err"].copy()
            return StepFailure("step_size", f"step size {h:.3g} underflow at t={t:.17g}",
                               t, h, weighted)
        if kind == "crawl":
            return StepFailure("crawl", f"steps failed on algebraic unknowns alone "
                               f"{MAX_CRAWL} times in a row before t={t:.17g} (h={h:.3g})",
                               t, h, weighted)
        if kind == "newton":
            return StepFailure("newton", f"corrector failed to converge 10 times at "
                               f"t={t:.17g} (h={h:.3g})", t, h, weighted)
        return StepFailure("error_test", f"error test failed 10 times at t={t:.17g} "
                           f"(h={h:.3g})", t, h, weighted)


# the number of outputs of each generated function of a LoopModel
_N_OUT = {"residual": lambda m: m.n_rows, "jacobian": lambda m: len(m.jac_rows),
          "roots": lambda m: m.n_rel + m.n_disc, "scales": lambda m: m.n_rel}
