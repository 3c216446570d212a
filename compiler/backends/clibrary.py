"""A model's generated C library loaded behind its Python functions.

:func:`attach` puts the compiled functions of a freshly built library behind a
:class:`~acausal.compiler.backends.codegen.GeneratedCode` (the Python ones stay, as the
fallback for a non-finite output), and keeps what that needs in ``code.c_layout``, so
that a model loaded from a pickle or the compile cache attaches the library again
(:func:`reattach`) without the Program, sympy or the code generator.
"""
from __future__ import annotations

import ctypes

import numpy as np

from ... import native
from ...native import cachefiles
from ...errors import BackendError

__all__ = ["CFunction", "FUNCTIONS", "attach", "reattach"]

FUNCTIONS = ("residual", "jacobian", "roots", "scales", "expand")


class CFunction:
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
    _wrap(code, cachefiles.load_library(lib_path), code.c_layout)
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
        setattr(code, name, CFunction(fn, py, layout["n_work"], *layout["sizes"], n_out))
    code.backend = "c"


def reattach(code, lib_path: str, source: str, layout: dict) -> str:
    """Put the library ``lib_path`` behind the Python functions of ``code`` (a loaded
    model), building it again from ``source`` when it is missing or does not load
    (another machine, a cleaned cache).  Returns the path of the library in use; raises
    :class:`BackendError` when it can be neither loaded nor built."""
    try:
        # verified first (a damaged library is removed); and dlopen would hand back a
        # deleted library still mapped in this process
        lib = cachefiles.load_library(lib_path)
    except OSError:
        lib_path = native.build_library(source)
        try:
            lib = cachefiles.load_library(lib_path)
        except OSError as exc:
            raise BackendError(f"the rebuilt library {lib_path} does not load: {exc}") from exc
    _wrap(code, lib, layout)
    code.library = lib_path
    code.c_source = source
    code.c_layout = layout
    return lib_path
