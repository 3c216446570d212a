"""Values fixed by the parameters, as functions f(p) of the tunable ones.

A variable fixed to an expression of parameters, a derived parameter's bound and a
delay time that depends on tunable parameters are each a small generated Python function
of the parameter vector ``p`` (:class:`~acausal.compiler.backends.emit.Emitter`),
picklable as its source (:class:`~acausal.compiler.backends.lazycode.ParameterFunction`,
which a model loaded from the compile cache unpickles without sympy).
"""
from __future__ import annotations

from .emit import Emitter
from .lazycode import ParameterFunction

__all__ = ["parameter_functions"]


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
