"""Which outputs can be NaN or inf where the solver saw only finite numbers.

At an accepted point the integrator has checked its unknowns and every residual row,
and with them every assigned variable a row reads.  An assigned variable that only the
results read (a sensor, a power, ``y = sqrt(x)`` that nothing else uses) is computed by
``expand`` alone, and nothing checks it: past the domain of a function in it the run
would report success with NaN or inf in the result.  :func:`output_checks` lists those
outputs whose computation, through such assignments, contains an operation that can
leave the finite numbers for finite arguments -- a power that is not a positive whole
number (``1/x``, ``sqrt``), ``log``, ``exp``, ``tan``, the inverse and hyperbolic
functions with restricted domains or overflow -- of something that changes during the
run, so that the runtime checks only those at every output point
(:meth:`acausal.runtime.CompiledModel.check_point`), and a model without any pays
nothing.  What depends on parameters alone is the same at every point: every output is
checked at the first point of a run.
"""
from __future__ import annotations

import sympy as sp

__all__ = ["output_checks", "restricted"]

_RESTRICTED = (sp.log, sp.exp, sp.tan, sp.cot, sp.sec, sp.csc, sp.asin, sp.acos,
               sp.acosh, sp.atanh, sp.acoth, sp.asec, sp.acsc, sp.sinh, sp.cosh,
               sp.gamma, sp.loggamma)
_TEXT = 160           # characters of an equation's text kept for a message


def restricted(e, constant=lambda s: False) -> bool:
    """Whether ``e`` has an operation that can give NaN or inf for finite arguments that
    change during a run (``constant(symbol)``: a parameter, fixed for the run; where only
    those enter, the value is the same at every point, and the first point's check
    finds it).  ``sqrt(abs(x))`` and other positive powers of an ``abs`` cannot, nor any
    power of what sympy proves positive (``(x**2 + 1e-6)**(-1/4)``)."""
    def varies(x):
        return any(not constant(q) for q in x.free_symbols)

    stack = [e]
    while stack:
        node = stack.pop()
        if isinstance(node, sp.Pow):
            base, exp = node.args
            if not (exp.is_Integer and exp > 0) and not base.is_Number and varies(base) \
                    and not (isinstance(base, sp.Abs) and exp.is_positive) \
                    and base.is_positive is not True:
                return True
        elif isinstance(node, _RESTRICTED) and varies(node):
            return True
        stack.extend(node.args)
    return False


def output_checks(program, names, equations) -> list:
    """[(output index, variable name, equation text)] of the outputs of ``program``'s
    ``expand`` that are computed through assignments the residual does not read, one of
    which has a :func:`restricted` operation, in the order they are computed (the first
    that is not finite at a point is where it went wrong).  ``names[k]`` and
    ``equations(k)`` name the k-th assigned variable and the equation it is solved
    from."""
    outputs = program.functions.get("expand")
    if not outputs or not program.assigned:
        return []
    checked = set(program.needed(program.functions["residual"]))
    refs = program.refs

    def constant(q):
        return refs.get(q, ("",))[0] == "p"

    # in the order they are computed: an assignment reads only earlier ones
    unsafe = [False] * len(program.assigned)
    for k, e in enumerate(program.assigned):
        if k in checked:
            continue
        unsafe[k] = any(unsafe[j] for j in program.reads[k] if j not in checked) or \
            restricted(e, constant)
    found = {}
    for i, s in enumerate(outputs):
        where = program.refs.get(s)
        if where is not None and where[0] == "a" and unsafe[where[1]]:
            found.setdefault(where[1], i)
    out = []
    for k, i in sorted(found.items()):
        text = str(equations(k))
        out.append((i, str(names[k]), text if len(text) <= _TEXT
                    else text[:_TEXT - 3] + "..."))
    return out
