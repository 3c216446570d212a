"""The compiled step loop's library: built when acausal is installed, loaded here.

``setup.py`` builds ``cbdf_loop.c`` (the four sources of the loop, one translation unit)
as the optional extension ``acausal.solvers._cbdf``, a shared library that this module
loads with ctypes (:func:`acausal.native.installed_library`) and whose entry points it
declares.  Where the install had no C compiler there is none, and simulations run the
Python step loop (``res.stats["step_loop"]`` says which ran).  The library holds the
digest of the sources it was built from: one built from other sources than those beside
it (a checkout changed since it was installed) is not loaded, with a warning, since its
state struct might not be the one :mod:`.cbdf_layout` reads from ``cbdf.h``.

Why at install time: the library is part of the installation, so which step loop and
which dense LU run depends on the installation and the problem only, never on what a
process found in a cache, whether a C compiler is on the path at run time, or whether a
build started by an earlier run has finished.
"""
from __future__ import annotations

import ctypes
import hashlib
import os
import threading
import warnings

from .. import native
from .cbdf_layout import CbdfState

__all__ = ["library", "source_digest", "MODULE"]

MODULE = "acausal.solvers._cbdf"
_SOURCES = ("cbdf.h", "cbdf_lu.c", "cbdf_dyn.c", "cbdf_sparse.c", "cbdf.c", "cbdf_loop.c")
_lib = None
_lock = threading.Lock()


def source_digest() -> str:
    """The digest of the step loop's sources beside this module (as ``setup.py`` makes
    it for the library it builds)."""
    h = hashlib.sha256()
    here = os.path.dirname(os.path.abspath(__file__))
    for name in _SOURCES:
        with open(os.path.join(here, name), "rb") as f:
            h.update(name.encode() + b"\0" + f.read() + b"\0")
    return h.hexdigest()[:32]


def library():
    """The step loop's library, its entry points declared, or None when the install did
    not build it (or built it from other sources)."""
    global _lib
    if _lib is None:
        with _lock:
            if _lib is None:
                _lib = _load() or False
    return _lib or None


def _load():
    lib = native.installed_library(MODULE)
    if lib is None:
        return None
    lib.cbdf_source_digest.restype = ctypes.c_char_p
    lib.cbdf_state_size.restype = ctypes.c_int64
    built = lib.cbdf_source_digest().decode()
    if built != source_digest() or lib.cbdf_state_size() != ctypes.sizeof(CbdfState):
        warnings.warn("the compiled step loop was built from other sources than those "
                      "installed beside it; reinstall acausal (pip install -e . in a "
                      "checkout) to rebuild it -- the Python step loop runs meanwhile",
                      RuntimeWarning, stacklevel=3)
        return None
    state, vp, i64, dbl = ctypes.POINTER(CbdfState), ctypes.c_void_p, ctypes.c_int64, \
        ctypes.c_double
    _declare(lib, "cbdf_run", ctypes.c_int, state)
    _declare(lib, "cbdf_interpolate", None, state, dbl, vp, vp)
    _declare(lib, "dense_factor", ctypes.c_int, vp, vp, vp, vp, vp, i64, vp)
    _declare(lib, "dense_solve", None, vp, vp, vp, vp, i64, vp)
    _declare(lib, "sparse_new", vp, i64, vp, vp, i64, vp, vp, vp, i64)
    _declare(lib, "sparse_free", None, vp)
    _declare(lib, "sparse_values", ctypes.POINTER(dbl), vp)
    _declare(lib, "sparse_factor", ctypes.c_int, vp)
    _declare(lib, "sparse_solve", None, vp, vp)
    _declare(lib, "sparse_nnz", i64, vp)
    return lib


def _declare(lib, name, restype, *argtypes) -> None:
    fn = getattr(lib, name)
    fn.restype, fn.argtypes = restype, list(argtypes)
