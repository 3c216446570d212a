"""Array code: the numpy backend's functions for large models, one numpy operation per
group of statements of the same shape.

The scalar module (:func:`acausal.compiler.backends.codegen.python_code`) runs one Python
statement per assigned variable, gradient entry and row: some 70 ns each, so a model of
thousands of statements spends most of a step in the interpreter.  Large models are made
of many copies of few components, so their statements come in few *shapes*: the same
expression tree with other variables at its leaves (``_a7 = -(y[3] - _a2)`` and
``_a9 = -(y[4] - _a4)``).  Here each function is evaluated on one work vector ``V``
holding the inputs (z, p, m, t) and every computed value:

* each statement's *shape* is its tree with the leaves numbered in order of first
  occurrence (numbers stay in the shape, so ``x**2`` and ``x**3`` differ); its *level*
  is one more than the highest level of the values it reads (inputs have level 0);
* the statements of one level and one shape form a group, evaluated at once: its
  leaves are gathered from ``V`` (a slice when the indices are evenly spaced, one value
  when all members read the same), the shape is printed once by the scalar printer
  (:class:`acausal.compiler.backends.emit.Emitter`) with numpy operations, and the results are
  written to the group's contiguous block of ``V``; a statement that copies one value
  is not computed at all, its readers read the original;
* if-expressions become ``np.where`` (both branches are evaluated, under
  ``np.errstate(all="ignore")``; the one not taken is discarded).

The same operations are applied to the same values as in the scalar code, except that
the operands of a sum or product may be in another order (the shape is printed from one
member): results agree to round-off, not bitwise.  When an output is not finite the
scalar function is called instead, which raises the error the runtime reports with the
failing equation (as the C backend does).  Small models and models whose statements
do not group keep the scalar functions: numpy's fixed cost per operation (about 1 µs)
is more than a few scalar statements cost.
"""
from __future__ import annotations

import os

import sympy as sp
from sympy.core.relational import Relational
from sympy.logic.boolalg import ITE, And, BooleanFalse, BooleanTrue, Not, Or

from ...components.realsymbol import SYMBOLS
from .codegen import _negate
from .emit import _FUNCS, Emitter
from .lazycode import install_array_code

__all__ = ["array_source", "use_array_code", "MIN_STATEMENTS", "MIN_GROUP"]

#: the functions of a program printed as array code (and as looped C)
FUNCTIONS = ("residual", "jacobian", "roots", "scales", "expand")
#: below this many statements in the residual the scalar code is at least as fast
MIN_STATEMENTS = 400
#: statements per group the residual must average for the array code to be used
MIN_GROUP = 8
#: another function of fewer statements stays scalar (the zero-crossing functions of a
#: large model are often a handful of statements: a call of the array form costs more)
MIN_FUNCTION = 64

_ATOMS = (sp.Symbol, sp.Number, sp.NumberSymbol, BooleanTrue, BooleanFalse)
_NODES = (sp.Add, sp.Mul, sp.Pow, sp.Piecewise, sp.functions.elementary.piecewise.ExprCondPair,
          Relational, And, Or, Not, ITE, sp.Abs, sp.Min, sp.Max, sp.sign) + tuple(_FUNCS)


_NUMBERS: dict = {}      # id of a number -> its shape text, during array_source()


class _Unsupported(Exception):
    """A node the array printer has no numpy form for: the scalar code is kept."""


class _Statement:
    __slots__ = ("target", "key", "leaves", "expr", "terms")

    def __init__(self, target, key, leaves, expr=None, terms=None):
        self.target, self.key, self.leaves = target, key, leaves
        self.expr, self.terms = expr, terms


def _shape(e, refs, leafidx, leaves) -> str:
    """The shape text of e; its leaves (value ids) appended to ``leaves`` in order of
    first occurrence, ``leafidx`` maps a leaf to its number."""
    if e.is_Symbol:
        where = refs.get(e)
        if where is None:
            raise _Unsupported(f"unknown symbol {e}")
        n = leafidx.get(e)
        if n is None:
            n = leafidx[e] = len(leaves)
            leaves.append(where)
        return f"${n}"
    if isinstance(e, _ATOMS) or e is sp.zoo or e is sp.nan:
        # by identity: sympy's float() of a Rational goes through mpmath and its == of
        # numbers is slow too (tens of µs each); the program keeps every number alive
        text = _NUMBERS.get(id(e))
        if text is None:
            if isinstance(e, (BooleanTrue, BooleanFalse)):
                text = f"#{e!r}"
            elif e is sp.zoo or e is sp.nan:
                text = "#nan"        # an undefined value in one branch (printed as NaN)
            else:
                text = f"#{float(e)!r}"
            _NUMBERS[id(e)] = text
        return text
    if not isinstance(e, _NODES):
        raise _Unsupported(type(e).__name__)
    return type(e).__name__ + "(" + ",".join([_shape(a, refs, leafidx, leaves)
                                              for a in e.args]) + ")"


def _expr_statement(target, e, refs) -> _Statement:
    if type(e) in SYMBOLS:      # a copy of a value (most outputs of expand)
        where = refs.get(e)
        if where is None:
            raise _Unsupported(f"unknown symbol {e}")
        return _Statement(target, "$0", [where], expr=(e, {e: 0}))
    leafidx, leaves = {}, []
    key = _shape(e, refs, leafidx, leaves)
    return _Statement(target, key, leaves, expr=(e, leafidx))


def _combo_statement(target, terms, refs, j) -> _Statement:
    """``target = sum of partial * gradient``: one gradient or Jacobian entry."""
    leafidx, leaves, parts, printed = {}, [], [], []
    numbers = _NUMBERS
    for d, src in terms:
        # a number seen before (most partials are) by its identity, as _shape finds it
        text = numbers.get(id(d)) or _shape(d, refs, leafidx, leaves)
        if src is None:
            printed.append((d, None))
        else:
            g = ("g", src, j)
            n = leafidx.get(g)
            if n is None:
                n = leafidx[g] = len(leaves)
                leaves.append(g)
            text += f"*${n}"
            printed.append((d, g))
        parts.append(text)
    return _Statement(target, "C[" + ";".join(parts) + "]", leaves,
                      terms=(printed, leafidx))


def _statements(prog, name, assigned: dict, needs: dict) -> list:
    """The statements of one generated function, in an order that computes every value
    before it is read; the outputs are ``("o", i)``.  ``assigned`` keeps the statements
    of the assigned variables, which several functions compute, ``needs`` the assigned
    variables each function's outputs need (the Jacobian's are the residual's)."""
    ids = prog.refs
    which = "residual" if name == "jacobian" else name
    exprs = prog.functions[which]
    needed = needs.get(which)
    if needed is None:
        needed = needs[which] = prog.needed(exprs)
    out = []
    for k in needed:
        st = assigned.get(k)
        if st is None:
            st = assigned[k] = _expr_statement(("a", k), prog.assigned[k], ids)
        out.append(st)
    if name != "jacobian":
        return out + [_expr_statement(("o", i), e, ids) for i, e in enumerate(exprs)]
    for k, g in prog.grads.items():
        out += [_combo_statement(("g", k, j), terms, ids, j) for j, terms in g.items()]
    for i, (terms, j) in enumerate(zip(prog.jac, prog.jac_cols)):
        out.append(_combo_statement(("o", i), terms, ids, j))
    return out


#: the shapes of statements that only copy their one leaf
_COPIES = frozenset(("$0", "C[#1.0*$0]", "C[$0]"))


class _Schedule:
    """Levels, groups and the layout of ``V`` for one function."""

    def __init__(self, statements, n_inputs, input_slot):
        # a value is computed before it is read, so an alias is entered resolved: one
        # look-up resolves any value (this loop runs once per statement and leaf)
        self.alias = alias = {}
        self.read = read = set()        # the values the groups read (resolved)
        level = {}
        groups = {}
        copies = _COPIES
        for st in statements:
            if st.key in copies:
                src = st.leaves[0]
                alias[st.target] = alias.get(src, src)
                continue
            lv = 0
            for v in st.leaves:
                v = alias.get(v, v)
                read.add(v)
                n = level.get(v, 0)
                if n > lv:
                    lv = n
            lv += 1
            level[st.target] = lv
            groups.setdefault((lv, st.key), []).append(st)
        self.groups = sorted(groups.values(), key=lambda g: level[g[0].target])
        slot = dict(input_slot)
        n = n_inputs
        for g in self.groups:
            for st in g:
                slot[st.target] = n
                n += 1
        self.size = n
        # a copy's place is its original's: then slot answers where() for any value
        for a, src in alias.items():
            where = slot.get(src)
            if where is not None:
                slot[a] = where
        self.slot = slot

    def where(self, v) -> int:
        """The position in ``V`` of the value ``v`` (a copy's is its original's)."""
        return self.slot[v]


# numpy's names where they differ from C's (numpy < 2 has no asin, ...), and floor and
# ceil without the scalar code's float()
_NUMPY_NAMES = {sp.asin: "arcsin", sp.acos: "arccos", sp.atan: "arctan", sp.atan2: "arctan2",
                sp.asinh: "arcsinh", sp.acosh: "arccosh", sp.atanh: "arctanh",
                sp.floor: "floor", sp.ceiling: "ceil"}


class _ArrayEmitter(Emitter):
    """The scalar printer with numpy operations: it prints one member of a group, whose
    leaves are arrays (or one value shared by all members)."""

    def __init__(self, ref):
        super().__init__("py", ref)
        self._math = "np."

    def _node(self, e, done, names, shared) -> str:
        f = _NUMPY_NAMES.get(e.func)
        if f is not None:
            return f"np.{f}({', '.join(self._arg(a, done, names) for a in e.args)})"
        if isinstance(e, (And, Or)):
            op = " & " if isinstance(e, And) else " | "
            return "(" + op.join(self._cond(a, done, names) for a in e.args) + ")"
        if isinstance(e, Not):
            return f"(~{self._cond(e.args[0], done, names)})"
        if isinstance(e, ITE):
            c, a, b = (self._cond(x, done, names) for x in e.args)
            return f"np.where({c}, {a}, {b})"
        return super()._node(e, done, names, shared)

    def _cond(self, c, done, names) -> str:
        text = self._arg(c, done, names) if c in done or c in names else self._inline(c)
        return f"({text} != 0.0)" if c.is_Symbol else text

    def _ternary(self, cond, a, b) -> str:
        return f"np.where({cond}, {a}, {b})"

    def _piecewise(self, e) -> str:
        out = None
        for value, cond in reversed(e.args):
            v = self._inline(value)
            if out is None and (cond is sp.true or isinstance(cond, BooleanTrue)):
                out = v
                continue
            if out is None:
                out = "np.nan"
            c = self._inline(cond)
            if cond.is_Symbol:
                c = f"({c} != 0.0)"
            out = self._ternary(c, v, out)
        return out

    def _minmax(self, e, done, names) -> str:
        f = "np.minimum" if isinstance(e, sp.Min) else "np.maximum"
        args = [self._arg(a, done, names) for a in e.args]
        out = args[0]
        for a in args[1:]:
            out = f"{f}({out}, {a})"
        return out

    def _pow(self, e, done, names) -> str:
        return super()._pow(e, done, names).replace("math.pow(", "np.power(")

    def _power(self, b, r) -> str:
        return super()._power(b, r).replace("math.pow(", "np.power(")


#: a sum with more linear terms than this has them evaluated as one dot product
LONG_SUM = 32


def _linear_part(st):
    """([(coefficient, leaf number)], remaining terms or None) of a long sum or of a
    negated one (a node balance solved for one of its currents: ``-(i1 + ... + in)``):
    its terms c*x with a number c and a leaf x are one dot product, not one operation
    each (a negation goes into the coefficients and the remaining terms, which is exact
    in floating point); ``([], None)`` when the statement is not such a sum."""
    sign = 1
    if st.expr is not None:
        e, leafidx = st.expr
        if e.is_Mul and len(e.args) == 2 and e.args[0] is sp.S.NegativeOne \
                and e.args[1].is_Add:
            e, sign = e.args[1], -1
        if not e.is_Add or len(e.args) <= LONG_SUM:
            return [], None
        terms = [(a, None) for a in e.args]
    else:
        terms, leafidx = st.terms
        if len(terms) <= LONG_SUM:
            return [], None
    linear, rest = [], []
    for d, g in terms:
        c, x = (d, g) if g is not None else _coefficient_leaf(d)
        if x is not None and c is not None and c.is_Number and c.is_finite:
            linear.append((sign * float(c), leafidx[x]))
        else:
            rest.append((d if sign == 1 else -d, g))
    if len(linear) <= LONG_SUM:
        return [], None
    return linear, rest


def _coefficient_leaf(d):
    if d.is_Symbol:
        return sp.S.One, d
    if d.is_Mul and len(d.args) == 2 and d.args[0].is_Number and d.args[1].is_Symbol:
        return d.args[0], d.args[1]
    return None, None


def _leaves_read(st, rest) -> list:
    leafidx = st.expr[1] if st.expr is not None else st.terms[1]
    read = set()
    for d, g in rest:
        read.update(leafidx[q] for q in d.free_symbols if q in leafidx)
        if g is not None:
            read.add(leafidx[g])
    return sorted(read)


def _print_group(st, rest=None, emitter=None) -> tuple[list, str | None]:
    """(temporary lines, value text) of one member, its leaf k read as ``x{k}``; with
    ``rest``, of those terms of a long sum only (None when there are none).
    ``emitter(ref)`` makes the printer (numpy's by default; C's for looped C)."""
    emitter = emitter or _ArrayEmitter
    if rest is not None:
        if not rest:
            return [], None
        leafidx = st.expr[1] if st.expr is not None else st.terms[1]
        st = _Statement(st.target, st.key, st.leaves, terms=(rest, leafidx))
    if st.expr is not None:
        e, leafidx = st.expr
        em = emitter(lambda q: f"x{leafidx[q]}")
        lines = []
        return lines, em.expression(e, lines)
    printed, leafidx = st.terms
    em = emitter(lambda q: f"x{leafidx[q]}")
    lines, parts = [], []
    for d, g in printed:
        c = em.expression(d, lines)
        if g is None:
            parts.append(c)
            continue
        x = f"x{leafidx[g]}"
        parts.append(x if c == "1.0" else _negate(x) if c == "-1.0" else f"{c}*{x}")
    return lines, em.join_sum(parts)


class _Writer:
    def __init__(self):
        self.consts, self.coefs = [], []

    def gather(self, slots) -> str:
        """The text reading V at ``slots``: one value, a slice, or a kept index array."""
        first = slots[0]
        if all(s == first for s in slots):
            return f"V[{first}]"
        if len(slots) > 1:
            step = slots[1] - slots[0]
            if step > 0 and all(b - a == step for a, b in zip(slots, slots[1:])):
                stop = slots[-1] + 1
                return f"V[{first}:{stop}]" if step == 1 else f"V[{first}:{stop}:{step}]"
        self.consts.append(slots)
        return f"V[_I{len(self.consts) - 1}]"

    def dot(self, linear, group, sched) -> str:
        """sum_i c_i x_i over the linear terms of a long sum, as one product of the
        coefficients with the (terms x members) matrix of their leaves."""
        coefs = [c for c, _ in linear]
        slots = [sched.where(st.leaves[k]) for _, k in linear for st in group]
        self.coefs.append(coefs)
        shape = f".reshape({len(linear)}, {len(group)})" if len(group) > 1 else ""
        return f"np.dot(_C{len(self.coefs) - 1}, V[{self._index(slots)}]{shape})"

    def _index(self, slots) -> str:
        self.consts.append(slots)
        return f"_I{len(self.consts) - 1}"

    def function(self, name, sched, outputs, sizes) -> list:
        lines = [f"def {name}(t, y, p, m, out):", f"    V = np.empty({sched.size})"]
        base = {"y": 0, "p": sizes[0], "m": sizes[0] + sizes[1]}
        for block, lo, hi in inputs_read(sched, outputs, sizes):
            if block == "t":
                lines.append(f"    V[{sum(sizes)}] = t")
            else:
                b = base[block]
                lines.append(f"    V[{b + lo}:{b + hi}] = {block}[{lo}:{hi}]")
        lines.append("    with _quiet():")
        for g in sched.groups:
            lo = sched.slot[g[0].target]
            hi = lo + len(g)
            linear, rest = _linear_part(g[0])
            body, text = _print_group(g[0], rest)
            used = range(len(g[0].leaves)) if rest is None else _leaves_read(g[0], rest)
            for k in used:
                src = self.gather([sched.where(st.leaves[k]) for st in g])
                lines.append(f"        x{k} = {src}")
            if linear:
                text = self.dot(linear, g, sched) + ("" if text is None else f" + {text}")
            lines += ["        " + ln for ln in body]
            lines.append(f"        V[{lo}:{hi}] = {text}")
        if not sched.groups:
            lines.append("        pass")
        if outputs:
            lines.append(f"    out[:] = {self.gather([sched.where(o) for o in outputs])}")
        return lines + ["    return out", "", ""]


def inputs_read(sched, outputs, sizes) -> list:
    """The parts of the inputs one function reads, as (block, first, past-the-end) with
    block "y", "p", "m" or "t" and positions within it: only they are copied into the
    work vector (a zero-crossing function of a large model reads a few of its thousands
    of inputs, and copying them all would cost more than computing it)."""
    n_y, n_p, n_m = sizes
    starts = (("y", 0, n_y), ("p", n_y, n_p), ("m", n_y + n_p, n_m), ("t", n_y + n_p + n_m, 1))
    n_in = n_y + n_p + n_m + 1
    slot = sched.slot
    read = {slot[v] for v in sched.read}
    read.update(sched.where(o) for o in outputs)
    read = sorted(s for s in read if s < n_in)
    parts = []
    for block, start, size in starts:
        inside = [s - start for s in read if start <= s < start + size]
        if inside:
            parts.append((block, inside[0], inside[-1] + 1))
    return parts


def too_few(n_statements: int, n_groups: int, minimum: int = MIN_STATEMENTS) -> bool:
    """Whether a residual of ``n_statements`` in ``n_groups`` groups stays straight-line
    code: fewer than ``minimum`` statements, or fewer than :data:`MIN_GROUP` a group."""
    return n_statements < minimum or n_statements < MIN_GROUP * n_groups


def schedules(prog, minimum: int | None) -> list | None:
    """``(name, statements, schedule, outputs)`` of each function of ``prog``, in the
    order of :data:`FUNCTIONS`, or None when ``minimum`` is given and the residual is
    too small for grouped code (:func:`too_few`).  The array code and the looped C are
    printed from these."""
    _, inputs = input_layout(prog)
    n_in = len(inputs)
    out, assigned, needs = [], {}, {}
    for name in FUNCTIONS:
        if name not in prog.functions and name != "jacobian":
            continue
        statements = _statements(prog, name, assigned, needs)
        sched = _Schedule(statements, n_in, inputs)
        if name == "residual" and minimum is not None and \
                too_few(len(statements), len(sched.groups), minimum):
            return None
        out.append((name, statements, sched,
                    [st.target for st in statements if st.target[0] == "o"]))
    return out


def input_layout(prog) -> tuple[tuple, dict]:
    """((n_y, n_p, n_m), {input: its position in the work vector}): y, p, m, then t."""
    n_y = sum(1 for w in prog.refs.values() if w[0] == "y")
    n_p = sum(1 for w in prog.refs.values() if w[0] == "p")
    n_m = 1 + max((w[1] for w in prog.refs.values() if w[0] == "m"), default=-1)
    inputs = {("y", k): k for k in range(n_y)}
    inputs.update({("p", k): n_y + k for k in range(n_p)})
    inputs.update({("m", k): n_y + n_p + k for k in range(n_m)})
    inputs[("t",)] = n_y + n_p + n_m
    return (n_y, n_p, n_m), inputs


def array_source(prog, small: bool = False) -> tuple[str, int, int] | None:
    """The array module of a program (functions ``residual``, ``jacobian``, ``roots``,
    ``scales``, ``expand`` as in the scalar module), with the numbers of statements and
    of array operations (groups) in the residual, or None when it would not be faster:
    the residual has fewer than :data:`MIN_STATEMENTS` statements or fewer than
    :data:`MIN_GROUP` per group (unless ``small``), or a statement has an operator with
    no numpy form.  Another function of fewer than :data:`MIN_FUNCTION` statements is
    left out (its scalar form is used), unless ``small``."""
    sizes = input_layout(prog)[0]
    writer, lines = _Writer(), []
    _NUMBERS.clear()
    try:
        made = schedules(prog, None if small else MIN_STATEMENTS)
        if made is None:
            return None
        for name, statements, sched, outputs in made:
            if name == "residual":
                n_st, n_groups = len(statements), len(sched.groups)
            elif not small and len(statements) < MIN_FUNCTION:
                continue          # the scalar function stays
            lines += writer.function(name, sched, outputs, sizes)
    except (_Unsupported, RecursionError):
        return None
    finally:
        _NUMBERS.clear()
    head = ["import numpy as np", "", "_quiet = lambda: np.errstate(all='ignore')"]
    for k, slots in enumerate(writer.consts):
        head.append(f"_I{k} = np.array({slots!r}, dtype=np.intp)")
    for k, coefs in enumerate(writer.coefs):
        head.append(f"_C{k} = np.array({coefs!r})")
    return "\n".join(head + ["", ""] + lines) + "\n", n_st, n_groups


def use_array_code(code) -> tuple[int, int] | None:
    """Put the array functions printed from ``code.program`` in front of the scalar
    functions of a GeneratedCode (``ACAUSAL_ARRAY_CODE``: ``never``, or ``always``
    whatever the size); the residual's numbers of statements and of array operations,
    or None when the scalar functions stay."""
    mode = os.environ.get("ACAUSAL_ARRAY_CODE", "auto")
    prog = getattr(code, "program", None)
    if mode == "never" or prog is None:
        return None
    made = array_source(prog, small=mode == "always")
    if made is None:
        return None
    install_array_code(code, made[0])
    return made[1:]
