"""Values fixed by the parameters, as functions f(p) of the tunable ones.

A variable fixed to an expression of parameters, a derived parameter's bound and a
delay time that depends on tunable parameters are each a small generated Python function
of the parameter vector ``p`` (:class:`~acausal.compiler.backends.emit.Emitter`),
picklable as its source.
"""
from __future__ import annotations

import math

from .emit import Emitter

__all__ = ["ParameterFunction", "parameter_functions"]


class ParameterFunction:
    """f(p): a variable's value as a function of the parameters, from generated Python
    (``source`` defines ``name``); pickles as its source."""

    def __init__(self, source: str, name: str):
        self.source, self.name = source, name
        namespace = {"math": math}
        exec(compile(source, "<acausal constants>", "exec"), namespace)
        self._f = namespace[name]

    def __call__(self, p):
        return self._f(p)

    def __reduce__(self):
        return (ParameterFunction, (self.source, self.name))


def parameter_functions(exprs: dict, psyms) -> list:
    """(name, f(p)) for each expression of parameters in ``exprs``, each from its own
    generated source; ``psyms`` are the symbols of ``p``'s entries."""
    pos = {q: k for k, q in enumerate(psyms)}
    em = Emitter("py", lambda q: f"p[{pos[q]}]")
    out = []
    for name, e in exprs.items():
        lines = ["def f(p):"] + ["    " + ln for ln in em.assign("_v", e)] + ["    return _v"]
        out.append((name, ParameterFunction("\n".join(lines) + "\n", "f")))
    return out
