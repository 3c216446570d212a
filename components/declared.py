"""What a component class declares, over its method resolution order: its parameters
and variables, its structural parameters, and the named arguments of its constructor.

Read by the component itself, by the checks of modifications (``validation.py``) and by
conditional components (``conditional.py``); cached per class.
"""
from __future__ import annotations

import inspect

from .declarations import Parameter, Variable

__all__ = ["class_declarations", "class_structurals", "constructor_arguments"]

_DECL_CACHE: dict = {}
_STRUCTURAL_CACHE: dict = {}


def constructor_arguments(cls) -> set:
    """The named arguments of ``cls.__init__`` beyond the modifications."""
    try:
        params = inspect.signature(cls.__init__).parameters.values()
    except (TypeError, ValueError):
        return set()
    return {p.name for p in params if p.name != "self"
            and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)}


def class_declarations(cls) -> dict:
    """Parameters and variables of the model over the MRO (not structural parameters,
    which shape the model and are no part of it)."""
    if cls not in _DECL_CACHE:
        out, structural = {}, {}
        for klass in reversed(cls.__mro__):
            for name, value in vars(klass).items():
                if isinstance(value, Parameter) and value.structural:
                    structural[name] = value
                    out.pop(name, None)
                elif isinstance(value, (Parameter, Variable)):
                    out[name] = value
                    structural.pop(name, None)
        _DECL_CACHE[cls] = out
        _STRUCTURAL_CACHE[cls] = structural
    return _DECL_CACHE[cls]


def class_structurals(cls) -> dict:
    """The structural parameters of ``cls`` over the MRO."""
    if cls not in _STRUCTURAL_CACHE:
        class_declarations(cls)
    return _STRUCTURAL_CACHE[cls]
