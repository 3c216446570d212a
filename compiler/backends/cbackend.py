"""The C backend: the generated functions as C, compiled once per model into a cache.

The same :class:`~acausal.compiler.backends.codegen.Program` that the Python module is printed
from is printed as C99 (:mod:`acausal.compiler.backends.emit`: the same operations in the same
order, so both backends agree to rounding), compiled by the system C compiler into a
shared library named by the hash of its source and the flags, and loaded with ctypes.
Every generated function keeps the contract ``f(t, y, p, m, out) -> out``.  The
compiler is started as soon as the source is printed and runs while the pipeline goes
on, a thread waiting for it (:func:`prepare`), and
a looped program's index arrays are given to the library when it is loaded, not
compiled (:func:`c_source`).

* Assigned variables and gradient entries live in a work array ``w``, and each function
  is split into pieces of about ``PIECE`` lines (``PIECE_LARGE`` in a source large
  enough to be compiled at ``-O0``, :mod:`acausal.native.build`): the compiler's time
  stays linear in the model's size (one function of 100k statements is not).  Why two
  sizes (gcc 12, processor time, medians of 2-3 runs on a shared machine): at ``-O2``
  pieces of 100 lines compile in 0.6-0.7 of the time of 400 (a 160 kB source: 1.3 s
  against 1.9 s) with the same simulation time to the measurement's noise; at ``-O0``
  they cost some 20 % more than 400 (an 870 kB source: 2.4 s against 1.9 s).  The
  pieces are the places where a large source is cut into translation units.
* Floating point as written: ``-ffp-contract=off`` (no fused multiply-add), no
  ``-ffast-math``.
* Outside a function's domain C computes NaN or inf where Python raises; a call whose
  output is not finite is repeated by the Python function, so the error, its message
  and the equation it names are those of the numpy backend.

A pickled model (:mod:`acausal.compiler.cache.entries`) keeps the C source and the library's
path: :func:`reattach` loads the library again, or builds it from the source when the
file is gone.  Loading needs neither sympy nor the code generator.

The cache is ``$ACAUSAL_CACHE`` or ``~/.cache/acausal``.  The compiler is ``$CC`` or the
first of cc, gcc, clang on the path; without one, ``backend="auto"`` uses the numpy
backend and says so in the index report, and ``backend="c"`` raises
:class:`BackendError`.
"""
from __future__ import annotations

import ctypes
import functools
import hashlib
import os
import shutil
import threading

import numpy as np

from ...errors import BackendError
from ...native import build as cbuild

__all__ = ["BackendError", "c_source", "build", "start_build", "attach", "reattach",
           "compiler_available", "cache_dir", "programs", "prepare"]

PIECE = 100               # lines per piece of a function compiled at -O2
PIECE_LARGE = 400         # and at -O0
FLAGS, FLAGS_LARGE = cbuild.FLAGS, cbuild.FLAGS_LARGE
LARGE, UNIT = cbuild.LARGE, cbuild.UNIT
FUNCTIONS = ("residual", "jacobian", "roots", "scales", "expand")


def compiler_available() -> str | None:
    cc = os.environ.get("CC")
    if cc:
        return shutil.which(cc)
    for name in ("cc", "gcc", "clang"):
        path = shutil.which(name)
        if path:
            return path
    return None


def cache_dir() -> str:
    root = os.environ.get("ACAUSAL_CACHE") or os.path.join(
        os.path.expanduser("~"), ".cache", "acausal")
    os.makedirs(root, exist_ok=True)
    return root


# -- printing ------------------------------------------------------------------------------
def c_source(programs: dict, index: dict | None = None) -> tuple[str, dict]:
    """C for {prefix: Program}; returns (source, {prefix: work size}).

    Given a dict ``index``, the index arrays of looped programs (:mod:`acausal.compiler.backends.cloops`)
    are not in the source: they go into ``index`` as {prefix: int32 array}, which the
    library reads through ``<prefix>ix`` once :func:`attach` has set it.  The source
    names each array's digest, so a library (named by its source) has one index."""
    parts = ["#include <math.h>", "", "#define ARGS double t, const double *y, "
             "const double *p, const double *m, double *out, double *w", "#define PASS t, y, p, m, out, w", ""]
    sizes, functions, any_looped = {}, [], False
    for prefix, prog in programs.items():
        # a large program's functions: one loop per group (compiler/backends/cloops.py)
        values = [] if index is not None else None
        looped = _looped(prefix, prog, values)
        any_looped = any_looped or looped is not None
        specs, n_work = looped or _c_program(prefix, prog)
        functions += specs
        sizes[prefix] = n_work
        if looped and values:
            index[prefix] = np.array(values, dtype=np.int32)
    # the pieces' size follows the optimization the source will be compiled with
    # (cbuild.flags_for): short pieces for -O2, long ones for a large source at -O0
    # (a line's indentation and newline counted as 4 characters)
    n_chars = sum(len(ln) + 4 for spec in functions for st in spec[1] for ln in st)
    piece = PIECE if n_chars <= LARGE else PIECE_LARGE
    if any_looped:
        parts += [cbuild.LOOPED]
    if index:
        parts += _index_pointers(index)
    parts += [_c_function(*spec, piece=piece) for spec in functions]
    if index:
        parts += [UNIT] + [f"HIDDEN const int *{k}ix = 0;\n"
                           f"void {k}set_ix(const int *d) {{ {k}ix = d; }}" for k in index]
    return "\n".join(parts) + "\n", sizes


def _index_pointers(index) -> list:
    """The header's declarations of the index pointers (hidden: no other library's
    symbol of the same name can stand in for them)."""
    lines = ["#if defined(__GNUC__)", '#define HIDDEN __attribute__((visibility("hidden")))',
             "#else", "#define HIDDEN", "#endif"]
    for k, values in index.items():
        digest = hashlib.sha256(values.tobytes()).hexdigest()[:24]
        lines += [f"/* {k}ix: {len(values)} indices, sha256 {digest} */",
                  f"extern HIDDEN const int *{k}ix;"]
    return lines + [""]


def _looped(prefix, prog, index=None):
    from .cloops import looped_program
    return looped_program(prefix, prog, index)


def _c_program(prefix, prog) -> tuple[list, int]:
    """The functions of one Program as (name, statements, calls, outputs), and the size
    of its work array."""
    # imported here: printing needs sympy, loading a library built before does not
    from .codegen import combinations, row_groups
    from .emit import Emitter
    n_a = len(prog.assigned)
    slot = {}
    for k, g in prog.grads.items():
        for j in g:
            slot[(k, j)] = n_a + len(slot)

    def ref(q):
        where = prog.refs[q]
        if where[0] == "t":
            return "t"
        if where[0] == "a":
            return f"w[{where[1]}]"
        return f"{where[0]}[{where[1]}]"

    em = Emitter("c", ref)
    assign = {}

    def prologue(ks):
        out = []
        for k in ks:
            if k not in assign:
                assign[k] = [em.assign(f"w[{k}]", prog.assigned[k])]
            out += assign[k]
        return out

    aliases = {}

    def grad(b, j):
        name = f"w[{slot[(b, j)]}]"
        return aliases.get(name, name)

    grads = []
    for k, g in prog.grads.items():
        grads.append(combinations(em, list(g.values()), [f"w[{slot[(k, j)]}]" for j in g],
                                  list(g), grad, aliases))
    out = []
    grads = [g for g in grads if g]
    res = prog.functions["residual"]
    # the assignments the rows need, once: residual, Jacobian and expand call them
    base = prog.needed(res)
    out.append((f"{prefix}assigned", prologue(base), (), 0))
    pre = [f"{prefix}assigned"]
    out.append((f"{prefix}residual", _c_rows(em, res), pre, len(res)))
    jac = [combinations(em, prog.jac[lo:hi], [f"out[{n}]" for n in range(lo, hi)],
                        prog.jac_cols[lo:hi], grad) for lo, hi in row_groups(prog)]
    out.append((f"{prefix}jacobian", grads + jac, pre, len(prog.jac)))
    have = set(base)
    for name in ("roots", "scales", "expand"):
        exprs = prog.functions.get(name)
        if exprs is None:
            continue
        need = prog.needed(exprs)
        if name == "expand":
            rest = [k for k in need if k not in have]
            out.append((f"{prefix}{name}", prologue(rest) + _c_rows(em, exprs), pre,
                        len(exprs)))
        else:
            out.append((f"{prefix}{name}", prologue(need) + _c_rows(em, exprs), (),
                        len(exprs)))
    return out, n_a + len(slot)


def _c_rows(em, exprs) -> list:
    return [em.assign(f"out[{k}]", e) for k, e in enumerate(exprs)]


def _c_function(name, statements, calls=(), n_out=0, piece=PIECE) -> str:
    """One exported function calling ``calls`` and then pieces of about ``piece`` lines
    each (whole statements); a statement's temporaries are local to its block.  Each
    piece, and the exported function with the prototypes it calls, is one segment
    between :data:`UNIT` marks: a translation unit may start at any of them."""
    pieces, current, size = [], [], 0
    for st in statements:
        current.append(st)
        size += len(st)
        if size >= piece:
            pieces.append(current)
            current, size = [], 0
    if current:
        pieces.append(current)
    lines = []
    for n, piece in enumerate(pieces):
        lines += [UNIT, f"void {name}_{n}(ARGS) {{"]
        for st in piece:
            if len(st) == 1:
                lines.append("  " + st[0])
            else:
                lines.append("  {")
                lines += ["    " + ln for ln in st]
                lines.append("  }")
        lines.append("}")
    lines.append(UNIT)
    lines += [f"int {c}(ARGS);" for c in calls]
    lines += [f"void {name}_{n}(ARGS);" for n in range(len(pieces))]
    lines.append(f"int {name}(ARGS) {{")
    lines += [f"  {c}(PASS);" for c in calls]
    lines += [f"  {name}_{n}(PASS);" for n in range(len(pieces))]
    # how many outputs are not finite: the caller repeats such a call in Python
    lines += ["  int bad = 0;", f"  for (int i = 0; i < {n_out}; ++i) bad += !isfinite(out[i]);",
              "  return bad;", "}"]
    return "\n".join(lines) + "\n"


# -- building and loading ---------------------------------------------------------------------
def build(source: str, cached_only: bool = False,
          unit_size: int | None = None) -> str | None:
    """The path of the shared library for source, compiled now or found in the cache
    (with ``cached_only``: None rather than compiling it).

    A large source is compiled without optimization (the straight-line code of a model
    gains little from it, and the compiler's time grows faster than the source) and in
    translation units of about ``unit_size`` characters (:mod:`acausal.native.build`),
    as many compiled at once as there are processors.  The split does not enter the
    name of the library: every split of a source gives the same functions."""
    if cached_only:
        lib = _library_path(source)
        return lib if os.path.exists(lib) else None
    return start_build(source, unit_size)()


def _library_path(source: str) -> str:
    cc = compiler_available()
    if cc is None:
        raise BackendError("no C compiler found (set CC, or install cc/gcc/clang)")
    flags = cbuild.flags_for(source)
    key = hashlib.sha256((source + " ".join([os.path.basename(cc)] + flags)).encode())
    return os.path.join(cache_dir(), f"model_{key.hexdigest()[:24]}.so")


def start_build(source: str, unit_size: int | None = None):
    """:func:`build` begun: the compilers are started now, by this thread; returns
    ``wait()``, which returns the library's path (it may be called from another
    thread)."""
    lib = _library_path(source)
    if os.path.exists(lib):
        return lambda: lib
    cc, flags = compiler_available(), cbuild.flags_for(source)
    units = cbuild.split(source, unit_size or cbuild.UNIT_SIZE, cbuild.jobs()) \
        if len(source) > cbuild.LARGE or unit_size else [source]
    tmp = cbuild.temporary_dir(cache_dir())
    try:
        job = cbuild.Compilation(cc, units, flags, tmp.name)
    except BaseException:
        tmp.cleanup()
        raise

    def wait() -> str:
        try:
            os.replace(job.wait(), lib)   # atomic: a concurrent build finds a whole file
        finally:
            tmp.cleanup()
        return lib
    return wait


class _CFunction:
    """A compiled function with the contract f(t, y, p, m, out) -> out.

    The arguments are copied into buffers whose addresses are fixed, which costs less
    than taking the address of each argument array on every call."""

    def __init__(self, fn, fallback, n_work, n_y, n_p, n_m, n_out):
        self.fn = fn
        self.fallback = fallback
        self.bufs = [np.zeros(max(n, 1)) for n in (n_y, n_p, n_m, n_out, n_work)]
        self.y, self.p, self.m, self.out, _ = self.bufs
        self.sizes = (n_y, n_p, n_m)
        self.ptrs = [b.ctypes.data for b in self.bufs]

    def __call__(self, t, y, p, m, out):
        n_y, n_p, n_m = self.sizes
        if len(y) != n_y or len(p) != n_p or len(m) < n_m:
            raise ValueError(f"generated function called with {len(y)} unknowns, "
                             f"{len(p)} parameters and {len(m)} discrete values; it "
                             f"reads {n_y}, {n_p} and {n_m}")
        self.y[:n_y] = y
        self.p[:n_p] = p
        self.m[:n_m] = m[:n_m]
        py, pp, pm, po, pw = self.ptrs
        bad = self.fn(float(t), py, pp, pm, po, pw)
        out[:] = self.out[:len(out)]
        if bad:
            # what Python raises (sqrt of a negative, 1/0) or returns there
            return self.fallback(t, y, p, m, out)
        return out


def attach(code, lib_path: str, prefix: str, n_work: int, index=None):
    """Replace the Python functions of a GeneratedCode by the compiled ones (the Python
    ones stay as the fallback).  What the wrappers need is kept in ``code.c_layout``, so
    that a loaded model can attach the library again without the Program; ``index``:
    the program's index array, when :func:`c_source` left it out of the source."""
    prog = code.program
    sizes = (sum(1 for w in prog.refs.values() if w[0] == "y"),
             sum(1 for w in prog.refs.values() if w[0] == "p"),
             1 + max((w[1] for w in prog.refs.values() if w[0] == "m"), default=-1))
    n_out = {}
    for name in FUNCTIONS:
        if getattr(code, name, None) is not None:
            n_out[name] = {"residual": code.n_rows, "jacobian": len(code.jac_rows),
                           "roots": code.n_roots}.get(name)
            if n_out[name] is None:
                n_out[name] = len(prog.functions[name])
    code.c_layout = {"prefix": prefix, "n_work": n_work, "sizes": sizes, "n_out": n_out,
                     "index": index}
    _wrap(code, ctypes.CDLL(lib_path), code.c_layout)
    code.library = lib_path
    return code


# the index arrays given to loaded libraries, by (library handle, prefix): a library is
# given its index once and keeps reading it, whichever of the models it serves is freed
_INDEX_GIVEN: dict = {}


def _give_index(lib, prefix, index) -> None:
    """Point ``<prefix>ix`` of the library at its index array.  The array is kept for
    the life of the process; the source names its digest, so every model that loads
    this library has an equal one."""
    key = (lib._handle, prefix)
    if key not in _INDEX_GIVEN:
        kept = np.ascontiguousarray(index, dtype=np.int32)
        setter = getattr(lib, f"{prefix}set_ix")
        setter.argtypes, setter.restype = [ctypes.c_void_p], None
        setter(kept.ctypes.data)
        _INDEX_GIVEN[key] = kept


def _wrap(code, lib, layout) -> None:
    argtypes = [ctypes.c_double] + [ctypes.c_void_p] * 5
    if layout.get("index") is not None:
        _give_index(lib, layout["prefix"], layout["index"])
    for name, n_out in layout["n_out"].items():
        py = getattr(code, name)
        py = getattr(py, "fallback", py)
        fn = getattr(lib, f"{layout['prefix']}{name}")
        fn.argtypes = argtypes
        fn.restype = ctypes.c_int
        setattr(code, name, _CFunction(fn, py, layout["n_work"], *layout["sizes"], n_out))
    code.backend = "c"


def reattach(code, lib_path: str, source: str, layout: dict) -> str:
    """Put the library ``lib_path`` behind the Python functions of ``code`` (a loaded
    model), building it again from ``source`` when it is missing or does not load
    (another machine, a cleaned cache).  Returns the path of the library in use; raises
    :class:`BackendError` when it can be neither loaded nor built."""
    try:
        if not os.path.exists(lib_path):
            # dlopen would hand back a deleted library still mapped in this process
            raise OSError(f"{lib_path} is gone")
        lib = ctypes.CDLL(lib_path)
    except OSError:
        lib_path = build(source)
        try:
            lib = ctypes.CDLL(lib_path)
        except OSError as exc:
            raise BackendError(f"the rebuilt library {lib_path} does not load: {exc}") from exc
    _wrap(code, lib, layout)
    code.library = lib_path
    code.c_source = source
    code.c_layout = layout
    return lib_path


BACKENDS = ("auto", "c", "numpy")


def _numpy(mc, report) -> None:
    """The numpy backend: a large model's functions in array form when that is faster
    (:mod:`acausal.compiler.backends.arraycode`)."""
    from .arraycode import use_array_code
    made = use_array_code(mc.code)
    if made is not None:
        report.notes.append(f"the numpy backend evaluates the residual's {made[0]} "
                            f"statements as {made[1]} array operations")


def programs(code, initial, whens=None, delays=None) -> dict:
    """{prefix: Program} of a model's generated codes (the model's, its initial
    equations', when-clauses' and delays'), in the order of the library's source."""
    codes = {"f_": code, "i_": initial, "w_": whens, "d_": delays}
    return {k: c.program for k, c in codes.items() if c is not None}


def prepare(progs: dict):
    """Print the C source of ``progs`` ({prefix: Program}) now, start its compiler, and
    wait for it in a thread; returns ``finish()``, which waits for the compiler and
    returns the source, its work sizes ({prefix: size}), the library's path and the
    index arrays ({prefix: array}, :func:`c_source`), or raises what printing or
    building raised.

    The compiler is a process of its own: while it runs, this one goes on with the rest
    of the compile (the pipeline calls this as soon as the Programs are made)."""
    outcome, index = {}, {}
    try:
        source, sizes = c_source(progs, index)
        wait = start_build(source)      # the compiler starts now, not when a thread can
    except Exception as exc:          # noqa: BLE001 - raised where the library is wanted
        outcome["error"] = exc
        return functools.partial(_finish, outcome, None)

    def compile_it():
        try:
            outcome["lib"] = wait()
        except BaseException as exc:  # noqa: BLE001 - raised by finish()
            outcome["error"] = exc

    thread = threading.Thread(target=compile_it, name="acausal-cc-build", daemon=True)
    thread.start()
    return functools.partial(_finish, outcome, thread, source, sizes, index)


def _finish(outcome, thread, *printed):
    if thread is not None:
        thread.join()
    if "error" in outcome:
        raise outcome["error"]
    source, sizes, index = printed
    return source, sizes, outcome["lib"], index


def bind(mc, backend: str, report, prepared=None) -> None:
    """Put the compiled functions behind the ModelCode ``mc`` (model, initial and when
    code share one library), or keep the Python ones: ``backend`` is ``"c"`` (raise
    :class:`BackendError` when it cannot be built), ``"numpy"``, or ``"auto"`` (C when a
    compiler works, else numpy, with the reason in the report).  ``prepared``: what
    :func:`prepare` returned for the model's Programs, if it was called already."""
    if backend not in BACKENDS:
        raise ValueError(f"backend must be one of {', '.join(map(repr, BACKENDS))}, "
                         f"got {backend!r}")
    mc.meta["backend"] = "numpy"
    if backend == "numpy":
        return _numpy(mc, report)
    codes = {"f_": mc.code, "i_": mc.initial.code}
    if mc.whens is not None:
        codes["w_"] = mc.whens.code
    if mc.delays is not None:
        codes["d_"] = mc.delays.code
    try:
        finish = prepared or prepare({k: c.program for k, c in codes.items()})
        source, sizes, lib, index = finish()
        if sizes.keys() != codes.keys():     # printed from other codes than the model's
            raise RuntimeError(f"the C library was printed for {sorted(sizes)}, the model "
                               f"has {sorted(codes)}")
        for prefix, code in codes.items():
            attach(code, lib, prefix, sizes[prefix], index.get(prefix))
            code.c_source = source       # one string, shared: a pickle holds it once
    except (BackendError, OSError) as exc:
        if backend == "c":
            raise BackendError(str(exc)) from exc
        report.notes.append(f"the C backend is not available ({str(exc).splitlines()[0]}); "
                            "the numpy backend runs the model")
        return _numpy(mc, report)
    mc.meta["backend"] = "c"
    looped = getattr(mc.code.program, "looped", None)
    if looped is not None:
        report.notes.append(f"the C backend evaluates the residual's {looped[0]} "
                            f"statements in {looped[1]} loops")
