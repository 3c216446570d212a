"""Looped C: a large model's functions as one loop per group of statements of the same
shape, instead of one C statement per value.

gcc's time grows with the code it compiles (about 3 us of processor time per character
at -O0, a third of it register allocation), and a large model is many copies of few
components: the straight-line C of a 100k-equation ladder is 5 MB and 12-18 s of gcc.
The statements are grouped as the numpy backend's array code groups them
(:mod:`acausal.compiler.arraycode`: same shape, same level), and each group becomes

    for (int i = 0; i < n; ++i) { double x0 = w[I0[i]]; ...; w[lo + i] = <shape>; }

with the shape printed once by the scalar C printer (:class:`acausal.compiler.emit.Emitter`:
if-expressions stay lazy ternaries, powers and functions as in the straight-line C), a
leaf read at evenly spaced positions as ``w[a + s*i]`` and otherwise through a static
index array, and the linear terms of a long sum (a node balance) as an inner loop over
coefficients.  The work array ``w`` holds the inputs (y, p, m, t: the parts a function
reads are copied in on entry) followed by every computed value, as the array code's ``V``.  Every function computes
what it needs itself (the straight-line C shares the assignments through one function).

The same floating-point operations are applied to the same values as in the
straight-line C, except that the operands of a sum or product may be in another order
(a shape is printed from one member): results agree to rounding, not bitwise.  Used for
each program (the model's, its initial equations', when-clauses', delays') whose
residual has at least :data:`MIN_STATEMENTS` statements and whose statements group
(``ACAUSAL_ARRAY_CODE`` as there: ``never`` keeps straight-line C, ``always`` loops
whatever the size).
"""
from __future__ import annotations

import os

from .arraycode import (_NUMBERS, FUNCTIONS, _leaves_read, _linear_part, _print_group,
                        _Unsupported, input_layout, inputs_read, schedules)
from .emit import Emitter

__all__ = ["looped_program", "MIN_STATEMENTS"]

#: below this many residual statements the straight-line C compiles fast enough
MIN_STATEMENTS = 2000


def looped_program(prefix, prog) -> tuple[list, int] | None:
    """The functions of a Program as ``(name, statements, calls, n_out)`` specs for
    :func:`acausal.compiler.cbackend._c_function`, and the size of the work array; None
    when the straight-line C is kept (also for a program with other functions than
    those of a model's or its initial equations' code).  A looped program records its
    residual's numbers of statements and of loops as ``prog.looped``."""
    mode = os.environ.get("ACAUSAL_ARRAY_CODE", "auto")
    if mode == "never" or not set(prog.functions) <= set(FUNCTIONS):
        return None
    sizes, inputs = input_layout(prog)
    specs, n_work = [], len(inputs)
    n_st = n_groups = 0
    _NUMBERS.clear()
    try:
        made = schedules(prog, None if mode == "always" else MIN_STATEMENTS)
        if made is None:
            return None
        for name, statements, sched, outputs in made:
            if name == "residual":
                n_st, n_groups = len(statements), len(sched.groups)
            body = [[ln] for ln in _entry(sched, outputs, sizes)] + \
                [_loop(g, sched) for g in sched.groups]
            if outputs:
                body.append(_copy_out([sched.where(o) for o in outputs]))
            specs.append((f"{prefix}{name}", body, (), len(outputs)))
            n_work = max(n_work, sched.size)
    except (_Unsupported, RecursionError):
        return None
    finally:
        _NUMBERS.clear()
    prog.looped = (n_st, n_groups)     # for the report (cbackend.bind)
    return specs, n_work


def _entry(sched, outputs, sizes) -> list:
    """The inputs the function reads, copied into ``w`` (arraycode.inputs_read)."""
    base = {"y": 0, "p": sizes[0], "m": sizes[0] + sizes[1], "t": sum(sizes)}
    lines = []
    for block, lo, hi in inputs_read(sched, outputs, sizes):
        if block == "t":
            lines.append(f"w[{base['t']}] = t;")
        else:
            lines.append(f"for (int i = {lo}; i < {hi}; ++i) w[{base[block]} + i] = "
                         f"{block}[i];")
    return lines


def _index(slots, name, lines, i="i") -> str:
    """The C text of ``w``'s position for member ``i``: a constant, an evenly spaced
    position, or a static index array declared in ``lines``."""
    first = slots[0]
    if all(s == first for s in slots):
        return str(first)
    if len(slots) > 1:
        step = slots[1] - slots[0]
        if all(b - a == step for a, b in zip(slots, slots[1:])):
            return f"{first} + {step}*({i})" if step != 1 else f"{first} + ({i})"
    lines.append(f"static const int {name}[{len(slots)}] = {{{', '.join(map(str, slots))}}};")
    return f"{name}[{i}]"


def _loop(group, sched) -> list:
    """One group as a loop over its members (one statement of lines)."""
    rep, n = group[0], len(group)
    lo = sched.slot[rep.target]
    linear, rest = _linear_part(rep)
    lines, body = [], []
    used = range(len(rep.leaves)) if rest is None else _leaves_read(rep, rest)
    for k in used:
        pos = _index([sched.where(st.leaves[k]) for st in group], f"I{k}", lines)
        body.append(f"double x{k} = w[{pos}];")
    temps, text = _print_group(rep, rest, lambda ref: Emitter("c", ref))
    body += temps
    if linear:
        coefs = ", ".join(repr(c) for c, _ in linear)
        slots = [sched.where(st.leaves[k]) for _, k in linear for st in group]
        lines.append(f"static const double C[{len(linear)}] = {{{coefs}}};")
        pos = _index(slots, "J", lines, i=f"k*{n} + i")
        body.append("double s = 0.0;")
        body.append(f"for (int k = 0; k < {len(linear)}; ++k) s += C[k]*w[{pos}];")
        text = "s" if text is None else f"s + {text}"
    body.append(f"w[{lo} + i] = {text};")
    return lines + [f"for (int i = 0; i < {n}; ++i) {{"] + ["  " + b for b in body] + ["}"]


def _copy_out(slots) -> list:
    lines = []
    pos = _index(slots, "O", lines)
    return lines + [f"for (int i = 0; i < {len(slots)}; ++i) out[i] = w[{pos}];"]
