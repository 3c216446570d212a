"""Loading the shared libraries built with acausal's installation.

A fixed library of acausal (the solvers' compiled step loop) is built when acausal is
installed, as an optional extension (``setup.py``), and lives beside the package's
modules under the name the platform gives extension modules; it is found by that name,
without importing it as a module (it is not one), and loaded with ctypes.
"""
from __future__ import annotations

import ctypes
import importlib.util

__all__ = ["installed_library"]


def installed_library(module: str):
    """The ``ctypes.CDLL`` of the library installed as the extension ``module`` (a dotted
    name), or None when the install did not build it."""
    try:
        spec = importlib.util.find_spec(module)
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.origin:
        return None
    try:
        return ctypes.CDLL(spec.origin)
    except OSError:
        return None
