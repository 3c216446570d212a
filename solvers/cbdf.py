"""The BDF step loop compiled: :class:`CompiledBDF`, the C twin of :class:`~.bdf.BDF`.

Why: with the generated model code in C (:mod:`acausal.compiler.backends.cbackend`), a step of the
Python loop spends about 95 % of its time in the interpreter (coefficients, predictor,
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
returns with the whole state (the divided differences ``phi``, ``h``, the order, the
coefficients), which :meth:`CompiledBDF.run` copies back into the attributes the
driver and :meth:`BDF.interpolate` read.  Output at requested times is the BDF
interpolant, evaluated in C.

With dynamic state selection the loop also tests, after every step, whether the current
choice of states is still good enough (:mod:`.cbdf_dyn`), and returns to Python only for
the search when it is not; a new choice comes back as other active linking rows, the
history kept.

When it is used (``step_loop="auto"``): the problem is a compiled model -- on the C
backend its functions are C; on the numpy backend its generated functions are called
back through the same pointers (:mod:`.cbdf_callbacks`, as IDA calls a Python residual)
-- without ``delay()`` (whose history is kept in Python after
every step) or stability limit detection, and, with dynamic state selection, at most
:data:`MAX_DENSE` unknowns (the sparse LU keeps one pattern, which a new choice of
states changes), and the loop's library is built.  That library is built once per
machine into the C backend's cache, in a process of its own that the first run
starts when it ends, or the first compile if it takes long (:func:`build_in_background`):
a run that starts before the library is there takes the Python loop rather than wait
(``step_loop="c"`` waits for it).  Up to
:data:`MAX_DENSE` unknowns the C loop factors dense (``cbdf_lu.c``); above, sparse, on the
model's fixed Jacobian pattern with the column order and pivot rows of one SuperLU
analysis (``cbdf_sparse.c``, :mod:`~acausal.solvers.cbdf_sparse`).  ``step_loop="c"``
also runs any other problem of at most :data:`MAX_DENSE` unknowns, calling its Python
residual, Jacobian and zero-crossing functions back (mode 1: the problem's functions,
not a model's generated ones; for tests against the Python loop, no faster).  Without a C compiler ``"auto"`` is the Python loop.  Results agree with the
Python loop to the integration tolerance, not bitwise: the LU is not LAPACK's or
SuperLU's, so the iteration matrix's solutions differ in rounding.
"""
from __future__ import annotations

import ctypes
import os
import threading

import numpy as np

from ..errors import BackendError
from . import cbdf_sparse as sparse_lu
from .bdf import _ALPHAS, BDF, MAX_ORDER, StepFailure
from . import cbdf_build
from .cbdf_build import build_if_long, build_in_background
from .cbdf_callbacks import Callbacks
from .linalg import LinearSolver, singular_block

__all__ = ["CompiledBDF", "MAX_DENSE", "STEP_LOOPS", "choose_step_loop", "library",
           "build_in_background", "build_if_long"]

MAX_DENSE = 200          # largest system the compiled loop factors dense (above: sparse LU)
STEP_LOOPS = ("auto", "c", "python")
CAPACITY = 512           # output points per return to Python (fewer above MAX_DENSE)

# indices into dv, iv and pv: as in cbdf.c
D_TN, D_TPREV, D_TSTOP, D_HH, D_HUSED, D_CJ, D_CJOLD, D_CJLAST, D_CJRATIO, D_SS, \
    D_RTOL, D_MAXSTEP, D_FAIL_T, D_FAIL_H, D_FAIL_CJ, D_FAIL_TJ = range(16)
D_PSI, D_ALPHA, D_BETA, D_SIGMA, D_GAMMA, D_ALPHAS, D_SIZE = 16, 24, 32, 40, 48, 56, 64
I_N, I_KK, I_KUSED, I_PHASE, I_NS, I_NST, I_FORCE, I_KMAX, I_MAXORD, I_NROOTS, \
    I_MODE, I_BUDGET, I_CAP, I_COUNT, I_NEVAL, I_IEVAL, I_ALLSTEPS, I_FAILKIND, \
    I_HASFAIL, I_HASLAST, I_PENDING, I_ANYALG, I_ANYSS, I_EQUIL, I_NRE, I_NJE, I_NLU, \
    I_NNI, I_NETF, I_NCF, I_NSTEPS, I_SPARSE = range(32)
I_ORD, I_NRES, I_NSZ, I_NLINK, I_NJAC, I_NREL, I_NDISC, I_NROWS, I_SIZE = \
    32, 40, 41, 42, 43, 44, 45, 46, 48
P_PHI, P_ATOL, P_SSMASK, P_ERRMASK, P_ALG, P_SCRATCH, P_LU, P_PIV, P_TEVAL, P_OUT_T, \
    P_OUT_Y, P_OUT_YP, P_WEIGHTED, P_LASTERR, P_GPREV, P_SIGNREF, P_G, P_YP, P_FAILY, \
    P_FAILYP, P_SPLU = range(21)
P_RESFN, P_JACFN, P_ROOTSFN, P_SCALESFN, P_PAR, P_M, P_MW, P_MOUT, P_JROWS, P_JCOLS, \
    P_JSIGN, P_STATEZ, P_LINKS, P_LINKD, P_JVALS, P_RSIGN, P_RSIDE, P_RNOM, P_TIMED, \
    P_OFFSET, P_RV, P_RSCALE, P_DYNL, P_DYND = range(24, 48)
P_SIZE = 48
R_BUDGET, R_FULL, R_SPECIAL, R_FAIL = range(4)
_KINDS = {1: "error_test", 2: "newton", 3: "step_size", 4: "singular", 5: "singular"}

_lib = None
_failed_with = ()         # the compiler a failed build used (() : no build failed)
_lock = threading.Lock()
_SOURCES = ("cbdf_lu.c", "cbdf_dyn.c", "cbdf_sparse.c", "cbdf.c")
_text = None


def library(cached_only: bool = False):
    """The compiled step loop (built once into the C backend's cache), or None when no
    C compiler works (with ``cached_only``: also when it is not built yet).  Without
    ``cached_only`` a build that :func:`build_in_background` started is waited for.
    A build that failed is tried again once another compiler is named (``CC``)."""
    global _lib
    if _lib is False and _failed_with != ():
        from ..compiler.backends.cbackend import compiler_available
        if compiler_available() != _failed_with:
            _lib = None
    if _lib is None:
        if not _lock.acquire(blocking=not cached_only):
            return None
        try:
            if _lib is None:
                _load(cached_only)
        finally:
            _lock.release()
    return _lib or None


def _source() -> str:
    global _text
    if _text is None:       # read once: a run asks for the library more than once
        here = os.path.dirname(__file__)
        parts = []
        for name in _SOURCES:
            with open(os.path.join(here, name)) as f:
                parts.append(f.read() + "\n")
        _text = "".join(parts)
    return _text


def _load(cached_only: bool) -> None:
    global _lib, _failed_with
    from ..compiler.backends.cbackend import build, compiler_available
    try:
        source = _source()
        path = build(source, cached_only=True)
        if path is None and not cached_only:
            builder = cbdf_build._builder
            if builder is not None:
                builder.wait()       # its library, or its failure, then ours
            path = build(source)
        if path is None:
            return
        lib = ctypes.CDLL(path)
    except (BackendError, OSError):
        _lib, _failed_with = False, compiler_available()
        return
    lib.cbdf_run.argtypes = [ctypes.c_void_p] * 3
    lib.cbdf_run.restype = ctypes.c_int
    sparse_lu.bind(lib)
    _lib = lib


def _compiled_model(problem) -> bool:
    """A compiled model whose residual, Jacobian and zero-crossing functions are C, or
    its generated numpy code (called back: :mod:`.cbdf_callbacks`)."""
    from ..compiler.backends.cbackend import _CFunction
    code = getattr(problem, "code", None)
    backend = getattr(problem, "backend", None)
    if code is None or backend not in ("c", "numpy") or \
            not hasattr(problem, "discrete") or not hasattr(problem, "dynamic"):
        return False
    need = [code.residual, code.jacobian] + ([code.roots, code.scales]
                                              if problem.n_roots else [])
    if backend == "numpy":
        return all(callable(f) for f in need)
    return all(isinstance(f, _CFunction) for f in need)


def choose_step_loop(problem, step_loop: str, stald: bool) -> int | None:
    """How the steps are taken: 0 (C, the model's C functions), 1 (C, calling the
    problem's Python functions back; only when asked for), or None (the Python loop)."""
    if step_loop not in STEP_LOOPS:
        raise ValueError(f"step_loop must be one of {', '.join(map(repr, STEP_LOOPS))}, "
                         f"got {step_loop!r}")
    if step_loop == "python":
        return None
    model = _compiled_model(problem)
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
        # a library still being built is not waited for: this run takes the Python loop
        return 0 if model and why is None and library(cached_only=True) is not None \
            else None
    if why is not None:
        raise ValueError(f"step_loop='c' is not available for this problem: {why}")
    if library() is None:
        raise BackendError("step_loop='c' needs a C compiler (set CC, or install "
                           "cc/gcc/clang)")
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
        self.callbacks = None       # a numpy model's functions (mode 0): cbdf_callbacks
        self.dv = np.zeros(D_SIZE)
        self.dv[D_ALPHAS:D_ALPHAS + MAX_ORDER + 2] = _ALPHAS
        self.iv = np.zeros(I_SIZE, dtype=np.int64)
        self.pv = (ctypes.c_void_p * P_SIZE)()
        self._keep = {}
        # above MAX_DENSE unknowns (a compiled model) the LU is sparse: cbdf_sparse.c
        self.sparse = mode == 0 and n > MAX_DENSE
        self.iv[I_SPARSE] = self.sparse
        dense = 0 if self.sparse else n * n
        self._buf("scratch", dense + 13 * n, P_SCRATCH)
        self._buf("lu", max(dense, 1), P_LU)
        self._buf("piv", n, P_PIV, np.int64)
        for name, slot in (("weighted", P_WEIGHTED), ("lasterr", P_LASTERR), ("yp", P_YP),
                           ("faily", P_FAILY), ("failyp", P_FAILYP)):
            self._buf(name, n, slot)
        # a large system's buffer is shorter: allocating (and zeroing) 2 x 512 x n
        # doubles costs milliseconds, a return to Python per 64 points microseconds
        cap = CAPACITY if n <= MAX_DENSE else max(64, min(CAPACITY, 2**17 // max(n, 1)))
        self.out_t = self._buf("out_t", cap, P_OUT_T)
        self.out_y = self._buf("out_y", (cap, n), P_OUT_Y)
        self.out_yp = self._buf("out_yp", (cap, n), P_OUT_YP)
        nr = int(getattr(problem, "n_roots", 0) or 0)
        for name, slot in (("g", P_G), ("gprev", P_GPREV), ("signref", P_SIGNREF)):
            self._buf(name, max(nr, 1), slot)
        self.iv[I_N], self.iv[I_NROOTS], self.iv[I_MODE] = n, nr, mode
        self._n_roots = nr
        self.iv[I_CAP] = cap
        if mode == 0:
            self._bind_model(problem)
        else:
            self._bind_callbacks(problem)
        super().__init__(problem, t0, y0, yp0, **options)
        self.pv[P_PHI] = _ptr(self.phi)
        self._splu = None
        self.pending = False

    def _bind_sparse(self) -> None:
        """The sparse LU on the problem's Jacobian pattern, analysed at the current
        point; again whenever the pattern is another (a new choice of linked states
        makes a new one).  The analysis (SuperLU's orderings) is kept with the problem
        for its next runs: the C factorization pivots afresh where a kept pivot has
        become small (:mod:`.cbdf_sparse`), so values of another run need no new one."""
        p = self.problem
        pattern = p._jac_indptr
        if self._splu is not None and self._splu_pattern is pattern:
            return
        kept = getattr(p, "_cbdf_analysis", None)
        perms = kept[1] if kept is not None and kept[0] is pattern else None
        self._splu = sparse_lu.SparseLU(self.lib, self.n, pattern, p._jac_indices,
                                        p._jac_slot, p.jacobian(self.tn, self.y, self.yp,
                                                                self.cj), perms)
        if self._splu.perms is not None:
            p._cbdf_analysis = (pattern, self._splu.perms)
        self._splu_pattern = pattern
        self.pv[P_SPLU] = self._splu.handle
        self.force_setup = True

    def _buf(self, name, shape, slot, dtype=float):
        a = np.zeros(shape, dtype=dtype)
        self._keep[name] = a
        self.pv[slot] = _ptr(a)
        return a

    def _set(self, name, array, slot, dtype=float):
        a = np.ascontiguousarray(array, dtype=dtype)
        if a.size == 0:
            a = np.zeros(1, dtype=dtype)
        self._keep[name] = a
        self.pv[slot] = _ptr(a)

    # ------------------------------------------------------------------ binding
    def _bind_model(self, p) -> None:
        code = p.code
        d = p.discrete
        if p.backend == "c":
            addr = lambda name, _: ctypes.cast(getattr(code, name).fn,  # noqa: E731
                                               ctypes.c_void_p).value
            n_work = int(code.c_layout["n_work"])
        else:
            self.callbacks = Callbacks(p)
            addr, n_work = self.callbacks.address, 0
        self.pv[P_RESFN] = addr("residual", int(code.n_rows))
        self.pv[P_JACFN] = addr("jacobian", len(code.jac_rows))
        self._buf("mw", max(n_work, 1), P_MW)
        self._buf("mout", max(int(code.n_rows), 1), P_MOUT)
        self._buf("jvals", max(len(code.jac_rows), 1), P_JVALS)
        self._set("jrows", code.jac_rows, P_JROWS, np.int64)
        self._set("jcols", code.jac_cols, P_JCOLS, np.int64)
        self._set("jsign", np.where(p._der_entries, -1.0, 1.0), P_JSIGN)
        self._set("statez", p.state_z, P_STATEZ, np.int64)
        self._set("links", p.link_s, P_LINKS, np.int64)
        self._set("linkd", p.link_d, P_LINKD, np.int64)
        iv = self.iv
        iv[I_NRES], iv[I_NSZ], iv[I_NLINK] = p.n_res, len(p.state_z), len(p.link_s)
        iv[I_NJAC], iv[I_NROWS] = len(code.jac_rows), code.n_rows
        iv[I_NREL], iv[I_NDISC] = d.n_rel, d.n_disc
        if p.n_roots:
            self.pv[P_ROOTSFN] = addr("roots", d.n_rel + d.n_disc)
            self.pv[P_SCALESFN] = addr("scales", d.n_rel)
            self._buf("rv", d.n_rel + d.n_disc, P_RV)
            self._buf("rscale", max(d.n_rel, 1), P_RSCALE)
            self._set("rnom", d.nominal, P_RNOM)
            self._set("timed", d._timed.astype(float), P_TIMED)

    def _bind_callbacks(self, p) -> None:
        n = p.n
        dbl = ctypes.POINTER(ctypes.c_double)
        vec = lambda a, k: np.ctypeslib.as_array(a, (k,)).copy()   # noqa: E731

        def res(t, y, yp, out):
            try:
                np.ctypeslib.as_array(out, (n,))[:] = p.residual(t, vec(y, n), vec(yp, n))
            except Exception:   # a failed evaluation is a failed Newton iterate
                np.ctypeslib.as_array(out, (n,))[:] = np.nan
            return 0

        def jac(t, y, yp, cj, out):
            J = p.jacobian(t, vec(y, n), vec(yp, n), cj)
            J = J.toarray() if hasattr(J, "toarray") else np.asarray(J, float)
            np.ctypeslib.as_array(out, (n * n,))[:] = J.ravel()
            return 0

        def roots(t, y, yp, out):
            m = self.iv[I_NROOTS]
            np.ctypeslib.as_array(out, (m,))[:] = p.roots(t, vec(y, n), vec(yp, n))
            return 0

        self._callbacks = [
            ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, dbl, dbl, dbl)(res),
            ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, dbl, dbl, ctypes.c_double,
                             dbl)(jac),
            ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, dbl, dbl, dbl)(roots)]
        for slot, cb in zip((P_RESFN, P_JACFN, P_ROOTSFN), self._callbacks):
            self.pv[slot] = ctypes.cast(cb, ctypes.c_void_p).value
        self._buf("offset", max(self.iv[I_NROOTS], 1), P_OFFSET)

    # ------------------------------------------------------------------ state transfer
    _DSCALARS = (("tn", D_TN), ("t_prev", D_TPREV), ("t_stop", D_TSTOP), ("hh", D_HH),
                 ("hused", D_HUSED), ("cj", D_CJ), ("cjold", D_CJOLD),
                 ("cjlast", D_CJLAST), ("cjratio", D_CJRATIO), ("ss", D_SS))
    _ISCALARS = (("kk", I_KK), ("kused", I_KUSED), ("phase", I_PHASE), ("ns", I_NS),
                 ("nst", I_NST), ("kmax", I_KMAX))
    _ARRAYS = (("psi", D_PSI), ("alpha", D_ALPHA), ("beta", D_BETA), ("sigma", D_SIGMA),
               ("gamma", D_GAMMA))

    def _push(self) -> None:
        dv, iv = self.dv, self.iv
        for name, k in self._DSCALARS:
            dv[k] = getattr(self, name)
        dv[D_RTOL], dv[D_MAXSTEP] = self.rtol, self.max_step
        for name, k in self._ARRAYS:
            dv[k:k + MAX_ORDER + 2] = getattr(self, name)
        for name, k in self._ISCALARS:
            iv[k] = getattr(self, name)
        iv[I_FORCE], iv[I_MAXORD] = bool(self.force_setup), self.max_order
        iv[I_NRE:I_NSTEPS + 1] = 0
        iv[I_ORD:I_ORD + MAX_ORDER + 1] = 0

    def _pull(self) -> None:
        dv, iv = self.dv, self.iv
        for name, k in self._DSCALARS:
            setattr(self, name, float(dv[k]))
        for name, k in self._ARRAYS:
            setattr(self, name, dv[k:k + MAX_ORDER + 2].tolist())
        for name, k in self._ISCALARS:
            setattr(self, name, int(iv[k]))
        self.force_setup = bool(iv[I_FORCE])
        self.y = self.phi[0].copy()
        if iv[I_NSTEPS]:
            self.yp = self._keep["yp"].copy()
        st = self.stats
        st.steps += int(iv[I_NSTEPS])
        st.residual_evaluations += int(iv[I_NRE])
        st.jacobian_evaluations += int(iv[I_NJE])
        st.lu_factorizations += int(iv[I_NLU])
        st.newton_iterations += int(iv[I_NNI])
        st.error_test_failures += int(iv[I_NETF])
        st.newton_failures += int(iv[I_NCF])
        for k in range(1, MAX_ORDER + 1):
            if iv[I_ORD + k]:
                st.orders[k] = st.orders.get(k, 0) + int(iv[I_ORD + k])
        if iv[I_HASLAST]:
            self._last_err = (self._keep["lasterr"].copy(), np.ones(self.n))

    def restart(self, *args, **kwargs) -> None:
        super().restart(*args, **kwargs)
        self._set("atol", self.atol, P_ATOL)
        self._set("ssmask", np.where(self.self_scaled, 0.0, 1.0), P_SSMASK)
        self._set("errmask", np.ones(self.n) if self.err_mask is None else self.err_mask,
                  P_ERRMASK)
        self.iv[I_ANYALG] = bool(self.alg.any())
        self.iv[I_ANYSS] = bool(self.self_scaled.any())
        self.iv[I_HASLAST] = 0

    def reformulate(self) -> None:
        """Another choice of states (dynamic state selection): the masks the C loop
        reads follow :meth:`BDF.reformulate`'s (the linking rows are bound by
        :meth:`run`)."""
        super().reformulate()
        self._set("ssmask", np.where(self.self_scaled, 0.0, 1.0), P_SSMASK)
        self.iv[I_ANYALG] = bool(self.alg.any())
        self.iv[I_ANYSS] = bool(self.self_scaled.any())

    @property
    def reselect(self) -> bool:
        """The last :meth:`run` returned because the choice of states must be looked at
        again (``cbdf_dyn.c``)."""
        dl = self._keep.get("dynl")
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
        iv, pv, p = self.iv, self.pv, self.problem
        if self.sparse:
            self._bind_sparse()
        self._push()
        iv[I_BUDGET], iv[I_COUNT], iv[I_PENDING] = budget, 0, 0
        iv[I_ALLSTEPS] = t_eval is None
        if t_eval is not None:
            self._set("teval", t_eval, P_TEVAL)
            iv[I_NEVAL], iv[I_IEVAL] = len(t_eval), i_eval
        nr = iv[I_NROOTS]
        if sign_ref is None:     # no zero crossings watched (step())
            iv[I_NROOTS], nr = 0, 0
        if nr:
            self._keep["signref"][:nr] = sign_ref
            self._keep["gprev"][:nr] = g_prev
            if self.mode == 0:
                d = p.discrete
                sign, side = d._orientation()
                self._set("rsign", sign, P_RSIGN)
                self._set("rside", side, P_RSIDE)
                # a chattering relation's hysteresis (runtime/modes.py) rides on the
                # nominal term the loop adds with the side's sign: side^2 = 1
                from ..runtime.modes import ZERO_NOMINAL
                self._set("rnom", d.nominal + side * d.hysteresis / ZERO_NOMINAL, P_RNOM)
                pv[P_OFFSET] = _ptr(d.offset)
        if self.mode == 0:
            self._keep["par"], self._keep["m"] = p.p, p.discrete.m
            pv[P_PAR], pv[P_M] = _ptr(p.p), _ptr(p.discrete.m)
        if getattr(p, "dynamic", None) is not None:
            from .cbdf_dyn import bind
            bind(self)
        code = self.lib.cbdf_run(_ptr(self.dv), _ptr(iv), ctypes.addressof(pv))
        iv[I_NROOTS] = self._n_roots
        if self.callbacks is not None:
            self.callbacks.reraise()
        self._pull()
        if nr:
            sign_ref[:] = self._keep["signref"][:nr]
            g_prev[:] = self._keep["gprev"][:nr]
        k = int(iv[I_COUNT])
        self.points = (self.out_t[:k].copy(), self.out_y[:k].copy(), self.out_yp[:k].copy())
        self.i_eval = int(iv[I_IEVAL])
        self.pending = bool(iv[I_PENDING])
        return code

    def failure(self) -> StepFailure:
        """The :class:`StepFailure` of a failed :meth:`run`, worded as the Python loop's."""
        dv, iv = self.dv, self.iv
        kind = _KINDS.get(int(iv[I_FAILKIND]), "step_size")
        t, h = float(dv[D_FAIL_T]), float(dv[D_FAIL_H])
        weighted = self._keep["weighted"].copy() if iv[I_HASFAIL] else None
        if kind == "singular":
            J = self.problem.jacobian(float(dv[D_FAIL_TJ]), self._keep["faily"].copy(),
                                      self._keep["failyp"].copy(), float(dv[D_FAIL_CJ]))
            if not self.sparse or iv[I_FAILKIND] == 5:
                J = J.toarray() if hasattr(J, "toarray") else np.asarray(J, float)
            if iv[I_FAILKIND] == 5:
                rows, cols = LinearSolver._nonfinite(J)
                msg = "iteration matrix has non-finite entries"
            else:
                rows, cols = singular_block(J)
                msg = "iteration matrix is singular"
            return StepFailure("singular", msg, t, h, rows=rows, cols=cols)
        if kind == "step_size":
            if weighted is None and iv[I_HASLAST]:
                weighted = self._keep["lasterr"].copy()
            return StepFailure("step_size", f"step size {h:.3g} underflow at t={t:.17g}",
                               t, h, weighted)
        if kind == "newton":
            return StepFailure("newton", f"corrector failed to converge 10 times at "
                               f"t={t:.17g} (h={h:.3g})", t, h, weighted)
        return StepFailure("error_test", f"error test failed 10 times at t={t:.17g} "
                           f"(h={h:.3g})", t, h, weighted)
