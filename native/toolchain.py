"""The C tool chain: which compiler builds generated C, and where built libraries live.

The compiler is ``$CC`` or the first of cc, gcc, clang on the path; the cache of built
libraries is ``$ACAUSAL_CACHE`` or ``~/.cache/acausal`` (the compile cache's models are
kept there too, :mod:`acausal.compiler.cache`).
"""
from __future__ import annotations

import os
import shutil

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


def cache_dir() -> str:
    """The directory of built libraries (made if missing)."""
    root = os.environ.get("ACAUSAL_CACHE") or os.path.join(
        os.path.expanduser("~"), ".cache", "acausal")
    os.makedirs(root, exist_ok=True)
    return root
