"""The C tool chain: which compiler builds generated C, and where built libraries live.

The compiler is ``$CC`` or the first of cc, gcc, clang on the path; the cache of built
libraries is ``$ACAUSAL_CACHE`` or ``~/.cache/acausal`` (the compile cache's models are
kept there too, :mod:`acausal.compiler.cache`; what is trusted there,
:mod:`acausal.native.cachefiles`).
"""
from __future__ import annotations

import os
import shutil

from . import cachefiles

__all__ = ["find_compiler", "cache_dir"]


def find_compiler() -> str | None:
    """The path of the C compiler to use, or None when there is none."""
    cc = os.environ.get("CC")
    if cc:
        return shutil.which(cc)
    for name in ("cc", "gcc", "clang"):
        path = shutil.which(name)
        if path:
            return path
    return None


def cache_dir() -> str | None:
    """The directory of built libraries, or None when the cache cannot be used (it is
    made private if missing, and trusted only as :mod:`acausal.native.cachefiles` says;
    warned once)."""
    return cachefiles.root()
