"""``sympy``, imported when an expression is first built rather than when a module loads.

Library modules write ``from acausal._sympy import sympy as sp`` and use ``sp.sin`` etc.
inside ``equations()`` and the functions that build expressions: declaring components
and loading a compiled model from the cache then never imports sympy (0.3-0.6 s).
The stand-in is not a module object, so the compile cache's tree key, which follows the
modules a model's code references, does not take it for one.
"""
from __future__ import annotations

__all__ = ["sympy"]


class _Sympy:
    __slots__ = ()

    def __getattr__(self, name: str):
        if name.startswith("__"):          # introspection (copy, pickle, doctest) stays cheap
            raise AttributeError(name)
        import sympy
        return getattr(sympy, name)

    def __repr__(self) -> str:
        return "<sympy, imported on first use>"


sympy = _Sympy()
