"""Looped C: a large model's functions as one loop per group of statements of the same
shape, instead of one C statement per value.

gcc's time grows with the code it compiles (about 3 us of processor time per character
at -O0, a third of it register allocation), and a large model is many copies of few
components: the straight-line C of a 100k-equation ladder is 5 MB and 12-18 s of gcc.
The statements are grouped as the numpy backend's array code groups them
(:mod:`acausal.compiler.backends.arraycode`: same shape, same level), and each group becomes

    for (int i = 0; i < n; ++i) { double x0 = w[I0[i]]; ...; w[lo + i] = <shape>; }

with the shape printed once by the scalar C printer (:class:`acausal.compiler.backends.emit.Emitter`:
if-expressions stay lazy ternaries, powers and functions as in the straight-line C), a
leaf read at evenly spaced positions as ``w[a + s*i]`` and otherwise through an index
array (given to the library when it is loaded, :func:`looped_program`), and the linear
terms of a long sum (a node balance) as an inner loop over coefficients.  The work
array ``w`` holds the inputs (y, p, m, t: the parts a function reads are copied in on
entry) followed by every computed value, as the array code's ``V``.  Every function
computes what it needs itself (the straight-line C shares the assignments through one
function).

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


def looped_program(prefix, prog, index: list | None = None) -> tuple[list, int] | None:
    """The functions of a Program as ``(name, statements, calls, n_out)`` specs for
    :func:`acausal.compiler.backends.cbackend._c_function`, and the size of the work array; None
    when the straight-line C is kept (also for a program with other functions than
    those of a model's or its initial equations' code).  A looped program records its
    residual's numbers of statements and of loops as ``prog.looped``.

    The index arrays of the loops are static arrays in the source, or, given a list
    ``index``, appended to it and read through the pointer ``<prefix>ix`` that the
    library is given when it is loaded (:func:`acausal.compiler.backends.cbackend.attach`): the
    arrays are most of a large model's looped C (176 of 219 kB, some 28 000 numbers,
    on the 1000-section RLC ladder: 0.12-0.17 s of gcc at -O0 with them, 0.08-0.12 s
    without)."""
    mode = os.environ.get("ACAUSAL_ARRAY_CODE", "auto")
    if mode == "never" or not set(prog.functions) <= set(FUNCTIONS):
        return None
    sizes, inputs = input_layout(prog)
    arrays = _Arrays(prefix, index)
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
                [_loop(g, sched, arrays) for g in sched.groups]
            if outputs:
                body.append(_copy_out([sched.where(o) for o in outputs], arrays))
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


class _Arrays:
    """Where a program's index arrays go: static arrays in the source, or the list
    ``index`` read through the pointer ``<prefix>ix`` (:func:`looped_program`)."""

    def __init__(self, prefix, index):
        self.pointer, self.index = f"{prefix}ix", index

    def declare(self, name, slots, lines) -> None:
        if self.index is None:
            lines.append(f"static const int {name}[{len(slots)}] = "
                         f"{{{', '.join(map(str, slots))}}};")
        else:
            lines.append(f"const int *{name} = {self.pointer} + {len(self.index)};")
            self.index.extend(slots)


def _index(slots, name, lines, arrays, i="i") -> str:
    """The C text of ``w``'s position for member ``i``: a constant, an evenly spaced
    position, or an index array declared in ``lines``."""
    first = slots[0]
    if all(s == first for s in slots):
        return str(first)
    if len(slots) > 1:
        step = slots[1] - slots[0]
        if all(b - a == step for a, b in zip(slots, slots[1:])):
            return f"{first} + {step}*({i})" if step != 1 else f"{first} + ({i})"
    arrays.declare(name, slots, lines)
    return f"{name}[{i}]"


def _loop(group, sched, arrays) -> list:
    """One group as a loop over its members (one statement of lines)."""
    rep, n = group[0], len(group)
    lo = sched.slot[rep.target]
    linear, rest = _linear_part(rep)
    lines, body = [], []
    used = range(len(rep.leaves)) if rest is None else _leaves_read(rep, rest)
    slot = sched.slot           # sched.where, looked up once
    for k in used:
        pos = _index([slot[st.leaves[k]] for st in group], f"I{k}", lines, arrays)
        body.append(f"double x{k} = w[{pos}];")
    temps, text = _print_group(rep, rest, lambda ref: Emitter("c", ref))
    body += temps
    if linear:
        coefs = ", ".join(repr(c) for c, _ in linear)
        slots = [slot[st.leaves[k]] for _, k in linear for st in group]
        lines.append(f"static const double C[{len(linear)}] = {{{coefs}}};")
        pos = _index(slots, "J", lines, arrays, i=f"k*{n} + i")
        body.append("double s = 0.0;")
        body.append(f"for (int k = 0; k < {len(linear)}; ++k) s += C[k]*w[{pos}];")
        text = "s" if text is None else f"s + {text}"
    body.append(f"w[{lo} + i] = {text};")
    return lines + [f"for (int i = 0; i < {n}; ++i) {{"] + ["  " + b for b in body] + ["}"]


def _copy_out(slots, arrays) -> list:
    lines = []
    pos = _index(slots, "O", lines, arrays)
    return lines + [f"for (int i = 0; i < {len(slots)}; ++i) out[i] = w[{pos}];"]
