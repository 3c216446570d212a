"""Code generation: what the generated functions compute (:class:`Program`), and its
Python module (the numpy backend; the C backend prints the same program,
:mod:`acausal.compiler.backends.cbackend`).

Each statement is printed on its own by :mod:`acausal.compiler.backends.emit` (common
subexpressions named within a statement, long sums as balanced groups), so the work is
linear in the model's size and nothing symbolic runs at simulation time.
Per model we generate

* ``residual(t, y, p, m, out)``: the residual rows G(t, y, p) = 0;
* ``jacobian(t, y, p, m, out)``: the values of dG/dy at the fixed sparsity pattern
  ``(rows, cols)``: partial derivatives of each statement, chained through the
  assignments in forward mode;
* ``roots(t, y, p, m, out)``: the zero-crossing functions of the relations in
  discontinuous expressions, then the arguments of the frozen floor values;
* ``scales(t, y, p, m, out)``: the magnitude ``|lhs| + |rhs|`` of each relation, the
  scale on which its distance from zero is judged.

Relations inside ``if_else``/``sign`` are *frozen* between events (Modelica semantics):
in the generated code each relation reads a value ``m[k]`` (1.0 or 0.0) that only the
runtime changes at events; the corresponding zero-crossing function is ``lhs - rhs``.
Frozen floor values (:mod:`acausal.compiler.frontend.discrete`) follow the relations in ``m``.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ...components.ifexpr import IfExpr
from ...components.realsymbol import SYMBOLS
from ...components.symbols import no_event, time
from ..algebra.dag import transform, tree_reaches, xreplace
from ..algebra.derivative import partial as _partial
from ..algebra.derivative import simple_partials
from ..algebra.symbolic import symbols_of
from .emit import Emitter, _plain
from .lazycode import GeneratedModule, ModuleSource

__all__ = ["GeneratedCode", "Program", "generate", "plan", "python_code", "python_source",
           "extract_relations", "FrozenSymbols"]


class GeneratedCode(ModuleSource):
    """The generated functions of a :class:`Program` (each ``f(t, y, p, m, out) ->
    out``), the Jacobian's sparsity pattern, and the Python module they are compiled
    in (``module``): its ``source`` is printed when first read, or when a Python function
    is first called (:mod:`acausal.compiler.backends.lazycode`)."""

    def __init__(self, module, residual, jacobian, roots, jac_rows, jac_cols, n_rows,
                 n_roots, scales=None, expand=None, program=None, backend="numpy"):
        self.module = module
        self.residual, self.jacobian, self.roots = residual, jacobian, roots
        self.scales, self.expand = scales, expand
        self.jac_rows, self.jac_cols = jac_rows, jac_cols
        self.n_rows, self.n_roots = n_rows, n_roots
        self.program, self.backend = program, backend



def event_form(expr: sp.Expr) -> sp.Expr:
    """abs, min, max and sign as if-expressions, so their kinks generate events (as in
    Modelica, where only noEvent(...) suppresses them); inside no_event(...) they stay.
    (The relations of such an expression are its own, not frozen: for a value read
    directly, as a relation's scale is.)"""

    def rebuild(node, args, quiet):
        if not quiet:
            kink = _kink(node, args, lambda rel: rel)
            if kink is not None:
                return kink
            if isinstance(node, IfExpr):
                return _if_expression(args)
        return _rebuilt(node, args)

    return transform(sp.sympify(expr), rebuild, context=False,
                     descend=lambda node, quiet: quiet or isinstance(node, no_event))


def _kink(node, args, mode):
    """abs, sign, min or max of the (rebuilt) ``args`` as an if-expression on the
    relation(s) of its kink, each given by ``mode(relation)`` (a relation, or the
    symbol of its frozen value); None for any other node."""
    if isinstance(node, sp.Abs):
        x = args[0]
        return sp.Piecewise((x, mode(x >= 0)), (-x, True))
    if isinstance(node, sp.sign):
        x = args[0]
        return sp.Piecewise((1, mode(x > 0)), (-1, mode(x < 0)), (0, True))
    if isinstance(node, (sp.Min, sp.Max)):
        op = (lambda u, v: u <= v) if isinstance(node, sp.Min) else (lambda u, v: u >= v)
        return _fold(args, lambda u, v: sp.Piecewise((u, mode(op(u, v))), (v, True)))
    return None


def _if_expression(args):
    return sp.Piecewise(*IfExpr(*args).pairs()) if args else sp.S.Zero


def _rebuilt(node, args):
    """``node`` with its arguments replaced by ``args`` (itself when they are its own)."""
    if all(a is b for a, b in zip(args, node.args)):
        return node
    return node.func(*args)


def _fold(args, pair):
    out = args[0]
    for a in args[1:]:
        out = pair(out, a)
    return out


class FrozenSymbols:
    """Symbols whose values change only at events (``symbols``), and among them those
    that make a relation of them a discrete one (``discrete``: Booleans, Integers, held
    values; not parameters alone, whose relations stay items of the discrete state)."""

    def __init__(self, symbols, discrete):
        self.symbols, self.discrete = frozenset(symbols), frozenset(discrete)

    def covers(self, free) -> bool:
        return free <= self.symbols and not self.discrete.isdisjoint(free)


def extract_relations(exprs: list, frozen=None) -> tuple[list, list, dict, list]:
    """Replace relations by mode symbols: their values frozen between events.

    Every relation -- in a condition, or at the kink of abs, min, max and sign -- gets
    its own mode ``_mK``, in the expressions and in the sides of the other relations
    alike: a relation whose side holds an abs or an if-expression stays *one* relation,
    its zero-crossing function ``lhs - rhs`` evaluated in the frozen modes of the
    relations inside it (Modelica's semantics; sympy would fold an if-expression inside a
    condition into a product of branches, ``components/ifexpr.py``).  Relations inside
    ``no_event(...)`` stay as they are and are evaluated directly, and so do the
    relations of values that change only at events (every symbol in ``frozen``:
    parameters, Boolean and Integer variables, held and frozen values), which cannot
    cross zero between events (``==`` and ``<>`` among them).  The expressions are
    walked as DAGs, without recursion (:mod:`acausal.compiler.dag`).

    Returns (new exprs, zero-crossing expressions, {mode symbol: relation as written},
    origin) where ``origin[k]`` is the index of the first expression that relation k
    occurs in.
    """
    exprs = [sp.sympify(e) for e in exprs]
    # Why the screening walk: most expressions of a large model hold no if-expression,
    # relation or anything that becomes one; one walk over the nodes of all of them (a
    # subtree shared by several is walked once) sets those aside, returned unchanged
    eventful = _eventful(exprs, (sp.Abs, sp.Min, sp.Max, sp.sign, no_event, sp.Piecewise,
                                 IfExpr, sp.core.relational.Relational))
    modes, order, written, origin = {}, [], [], []
    current = [0]

    def mode(rel, as_written=None):
        """The mode symbol of a (rebuilt: its sides frozen) relation."""
        if isinstance(rel, (sp.Eq, sp.Ne)):
            raise ValueError(f"equality relation {rel} cannot generate an event; "
                             "use <, <=, > or >=")
        if isinstance(rel, sp.logic.boolalg.BooleanAtom):
            return rel
        m = modes.get(rel)
        if m is None:
            m = modes[rel] = sp.Symbol(f"_m{len(order)}")
            order.append(rel)
            written.append(rel if as_written is None else as_written)
            origin.append(current[0])
        return m

    def rebuild(node, args, quiet):
        if quiet:
            return _rebuilt(node, args)
        if isinstance(node, no_event):
            return args[0]                      # its inside read directly
        if isinstance(node, sp.core.relational.Relational):
            rel = _rebuilt(node, args)
            if frozen is not None and (frozen.covers(rel.free_symbols) or (
                    isinstance(rel, (sp.Eq, sp.Ne)) and rel.free_symbols <= frozen.symbols)):
                # constant between events (an equality of parameters alone among them,
                # which no event could follow): evaluated where it is read
                return rel
            return mode(rel, node)
        kink = _kink(node, args, mode)
        if kink is not None:
            return kink
        if isinstance(node, IfExpr):
            return _if_expression(args)
        return _rebuilt(node, args)

    memo, new = {}, list(exprs)
    for i in eventful:
        current[0] = i
        new[i] = transform(exprs[i], rebuild, memo, context=False,
                           descend=lambda node, quiet: quiet or isinstance(node, no_event))
    order, written, origin = _canonical_order(order, written, origin, new, eventful)
    crossings = [rel.lhs - rel.rhs for rel in order]
    # the relations as written (abs, if_else and all) name the modes: texts and scales
    return new, crossings, {sp.Symbol(f"_m{k}"): w for k, w in enumerate(written)}, origin


_SORTED_UP_TO = 4000     # relations up to this many nodes each are numbered in text order


def _canonical_order(order, written, origin, new, eventful):
    """The relations numbered in the order of their texts (``srepr``), as the compiler
    always numbered them, where they are small enough to print; the modes renamed in the
    expressions accordingly.  (The walk finds them children first, which is as
    deterministic; printing a huge relation is what the order by text would cost.)"""
    if not order or any(tree_reaches(r, _SORTED_UP_TO + 1) for r in order):
        return order, written, origin
    perm = sorted(range(len(order)), key=lambda k: sp.srepr(order[k]))
    if perm == list(range(len(order))):
        return order, written, origin
    rename = {sp.Symbol(f"_m{old}"): sp.Symbol(f"_m{k}") for k, old in enumerate(perm)}
    for i in eventful:
        new[i] = xreplace(new[i], rename)
    return ([xreplace(order[k], rename) for k in perm], [written[k] for k in perm],
            [origin[k] for k in perm])


def _eventful(exprs, kinds) -> list:
    """Indices of the expressions with a node of one of the classes ``kinds``; a node
    found free of them is not walked again."""
    clean, out = set(), []
    for i, e in enumerate(exprs):
        seen, stack, found = [], [e], False
        while stack:
            node = stack.pop()
            if node.is_Atom or node in clean:     # no atom is of those classes
                continue
            if isinstance(node, kinds):
                found = True
                break
            seen.append(node)
            stack.extend(node.args)
        if found:
            out.append(i)
        else:
            clean.update(seen)
    return out


def generate(residuals: list, y_syms: list, params: list, n_modes: int = 0,
             crossings: list | None = None, assignments=(), outputs=None, discretes=(),
             scales=None) -> GeneratedCode:
    """Generate residual, Jacobian and root functions (Python; see :func:`plan`)."""
    return python_code(plan(residuals, y_syms, params, n_modes, crossings, assignments,
                            outputs, discretes, scales))


@dataclass
class Program:
    """What the generated functions compute, independent of the target language.

    ``refs[symbol]`` is where a symbol's value lives: ``("y", k)`` z, ``("p", k)`` a
    parameter, ``("m", k)`` the discrete state, ``("a", k)`` the k-th assigned variable,
    ``("t",)`` time.  ``assigned[k]`` is the expression of assigned variable k and
    ``reads[k]`` the assigned variables it reads.  ``functions[name]`` lists the output
    expressions of each generated function; ``grads[k]`` the forward-mode gradient of a
    needed assigned variable, ``{j: [(partial, source)]}`` with ``source`` None (d z_j /
    d z_j = 1) or the assigned variable b whose gradient entry j it multiplies; ``jac`` the
    Jacobian entries in the same form, in the order of ``jac_rows``/``jac_cols``.
    """

    refs: dict
    assigned: list
    reads: list
    functions: dict
    grads: dict
    jac: list
    jac_rows: list
    jac_cols: list
    n_modes: int

    def needed(self, exprs) -> list:
        """The assigned variables exprs depend on, in the order they are computed (a
        root function must not evaluate sqrt(1 - p) that only the residual needs)."""
        need, stack = set(), [k for e in exprs for k in self._direct(e)]
        while stack:
            k = stack.pop()
            if k not in need:
                need.add(k)
                stack.extend(self.reads[k])
        return sorted(need)

    def _direct(self, e):
        refs = self.refs
        if type(e) in SYMBOLS:        # an output that is a variable (expand)
            w = refs.get(e)
            return [w[1]] if w is not None and w[0] == "a" else []
        return [refs[q][1] for q in symbols_of(e) if refs.get(q, ("",))[0] == "a"]


def plan(residuals, y_syms, params, n_modes=0, crossings=None, assignments=(), outputs=None,
         discretes=(), scales=None) -> Program:
    """The functions to generate, with the Jacobian by the chain rule through the
    assignments (forward mode): each needed assigned symbol a carries the sparse gradient
    d a/dz = sum_b  da/db * db/dz, and row i's entries are dG_i/dz the same way.
    ``y_syms`` are the unknowns the solver holds (z); ``assignments`` is an ordered list
    of (symbol, expression) computed from z before the rows (the BLT's solved blocks);
    ``outputs``: symbols that ``expand`` returns; ``discretes``: frozen floor values,
    read from ``m[n_modes + j]``; ``scales``: relation magnitudes."""
    refs = {s: ("y", k) for k, s in enumerate(y_syms)}
    refs.update({a: ("a", k) for k, (a, _) in enumerate(assignments)})
    refs.update({s: ("p", k) for k, s in enumerate(params)})
    refs.update({s: ("m", n_modes + j) for j, s in enumerate(discretes)})
    refs.update({sp.Symbol(f"_m{k}"): ("m", k) for k in range(n_modes)})
    refs[time] = ("t",)
    res = _sympified(residuals)
    assigned = _sympified(e for _, e in assignments)
    prog = Program(refs, assigned, [], {}, {}, [], [], [], n_modes)
    prog.reads = [prog._direct(e) for e in assigned]
    prog.functions = {"residual": res, "roots": _sympified(crossings or []),
                      "scales": _sympified(scales or [])}
    if outputs is not None:
        prog.functions["expand"] = _sympified(outputs)
    for k in prog.needed(res):
        prog.grads[k] = _chain(assigned[k], refs, prog.grads)
    for i, r in enumerate(res):
        for j, terms in sorted(_chain(r, refs, prog.grads).items()):
            prog.jac_rows.append(i)
            prog.jac_cols.append(j)
            prog.jac.append(terms)
    return prog


def _sympified(items) -> list:
    """``[sympify(x) for x in items]``; an expression is its own (most items are)."""
    basic = sp.Basic
    return [x if isinstance(x, basic) else sp.sympify(x) for x in items]


def _chain(e, refs, grads) -> dict:
    """{j: [(partial, source)]}: the gradient of e with respect to z."""
    g = {}
    for q, d in _partials(e, refs).items():
        kind, k = refs[q]
        if kind == "y":
            g.setdefault(k, []).append((d, None))
        else:
            for j in grads[k]:
                g.setdefault(j, []).append((d, k))
    return dict(sorted(g.items()))


def _partials(e, refs) -> dict:
    """The non-zero partial derivatives of e with respect to the z and assigned symbols
    it reads, in one pass over a sum's terms (a node balance of n terms costs n, not
    n squared)."""
    wanted = sorted((q for q in symbols_of(e) if refs.get(q, ("",))[0] in "ya"),
                    key=lambda q: refs[q])
    if not wanted:
        return {}
    simple = simple_partials(e, wanted)
    if simple is not None:
        return simple
    if e.is_Add and len(e.args) > 8:
        by_symbol = {q: [] for q in wanted}
        for term in e.args:
            for q in symbols_of(term):
                if q in by_symbol:
                    by_symbol[q].append(term)
        out = {}
        for q, terms in by_symbol.items():
            d = sp.Add(*[_partial(term, q) for term in terms])
            if not d.is_Number or d != 0:
                out[q] = d
        return out
    out = {}
    for q in wanted:
        d = _partial(e, q)
        # only a number can equal 0 (sympy's == is structural), and comparing anything
        # else with 0 costs a sympify
        if not d.is_Number or d != 0:
            out[q] = d
    return out


def _python_ref(refs):
    def ref(q):
        try:
            where = refs[q]
        except KeyError:
            raise ValueError(f"generated code reads {q}, which is neither an unknown, a "
                             "parameter nor an assigned variable") from None
        if where[0] == "t":
            return "t"
        if where[0] == "a":
            return f"_a{where[1]}"
        return f"{where[0]}[{where[1]}]"
    return ref


def python_code(prog: Program) -> GeneratedCode:
    """The Python module of a program: functions ``f(t, y, p, m, out)`` on floats.

    Its source is printed (:func:`python_source`) and compiled when first needed, by
    the first call of one of its functions or a reader of ``source``: behind the C
    backend or the numpy backend's array code the Python functions are the fallback for
    an output that is not finite, which most runs never call (printing is a third of
    the code generation of a large model)."""
    res = prog.functions["residual"]
    names = ["residual", "jacobian"] + [n for n in ("roots", "scales", "expand")
                                        if n in prog.functions]
    module = GeneratedModule(functools.partial(python_source, prog), names=names)
    fn = module.function
    return GeneratedCode(module, fn("residual"), fn("jacobian"), fn("roots"),
                         np.array(prog.jac_rows, dtype=np.int64),
                         np.array(prog.jac_cols, dtype=np.int64),
                         len(res), len(prog.functions["roots"]),
                         fn("scales"), fn("expand"), prog)


def python_source(prog: Program) -> str:
    """The text of :func:`python_code`'s module (the same program gives the same text)."""
    em = Emitter("py", _python_ref(prog.refs))
    assign_lines = {}

    def prologue(ks):
        lines = []
        for k in ks:
            if k not in assign_lines:
                assign_lines[k] = em.assign(f"_a{k}", prog.assigned[k])
            lines += assign_lines[k]
        return lines

    lines = ["import math", "", ""]
    res = prog.functions["residual"]
    lines += _py_function("residual", prologue(prog.needed(res)),
                          _py_rows(em, res))
    aliases = {}
    grads = _py_grads(em, prog, aliases)
    entries = []
    for lo, hi in row_groups(prog):
        entries += combinations(em, prog.jac[lo:hi], [f"out[{n}]" for n in range(lo, hi)],
                                prog.jac_cols[lo:hi], lambda b, j: _grad(aliases, b, j))
    lines += _py_function("jacobian", prologue(prog.needed(res)) + grads, entries)
    for name in ("roots", "scales", "expand"):
        if name in prog.functions:
            exprs = prog.functions[name]
            if name == "expand":
                lines += _py_function(name, prologue(prog.needed(exprs)), _py_rows(em, exprs))
                continue
            # a relation's side may be read in modes where it has no value (abs(x) as -x
            # under a root, before the modes are settled): NaN for that relation alone,
            # as the C library computes it, not an error for all of them
            needed = prog.needed(exprs)
            body = [ln for k in needed for ln in _guarded(prologue([k]), f"_a{k}")]
            for k, e in enumerate(exprs):
                body += _guarded(em.assign(f"out[{k}]", e), f"out[{k}]")
            lines += _py_function(name, [], body)
    return "\n".join(lines) + "\n"


def _guarded(statement: list, target: str) -> list:
    """The lines of one statement, computing NaN into ``target`` where it fails."""
    return (["try:"] + ["    " + ln for ln in statement]
            + ["except (ValueError, ZeroDivisionError, OverflowError):",
               f"    {target} = math.nan"])


def _list(a):
    return a.tolist() if hasattr(a, "tolist") else list(a)


def _py_function(name, prologue, body) -> list:
    head = [f"def {name}(t, y, p, m, out):"]
    if not body:
        return head + ["    return out", "", ""]
    lines = ["    " + ln for ln in prologue + body]
    # an input is made a list of floats only when read: for a zero-crossing function
    # of a large model, converting its thousands of unknowns would be most of the call
    text = "\n".join(lines)
    head += [f"    {a} = _list({a})" for a in ("y", "p", "m") if _READS[a].search(text)]
    return head + lines + ["    return out", "", ""]


_READS = {a: re.compile(rf"(?<![\w.]){a}\[") for a in ("y", "p", "m")}


def _py_rows(em, exprs) -> list:
    lines = []
    for k, e in enumerate(exprs):
        lines += em.assign(f"out[{k}]", e)
    return lines


def _py_grads(em, prog, aliases) -> list:
    lines = []
    for k, g in prog.grads.items():
        lines += combinations(em, list(g.values()), [f"_g{k}_{j}" for j in g], list(g),
                              lambda b, j: _grad(aliases, b, j), aliases)
    return lines


def row_groups(prog):
    """(first, past-the-end) index ranges of the Jacobian entries of each row."""
    rows = prog.jac_rows
    lo = 0
    for n in range(1, len(rows) + 1):
        if n == len(rows) or rows[n] != rows[lo]:
            yield lo, n
            lo = n


def _negate(text: str) -> str:
    if _plain(text):
        return text[1:] if text.startswith("-") else "-" + text
    return f"(-{text})"


def _grad(aliases, b, j):
    name = f"_g{b}_{j}"
    return aliases.get(name, name)


def combinations(em, entries, targets, cols, grad_ref, aliases=None) -> list:
    """``target = sum of partial * gradient`` for each entry of one group (one row, one
    assigned variable; both targets use this); a partial used by several entries of the
    group is named once, and so is a subexpression several partials share."""
    uses = {}
    for terms in entries:
        for d, _ in terms:
            uses[d] = uses.get(d, 0) + 1
    lines = []
    partials = list(uses)
    named = dict(zip(partials, em.expressions(partials, lines,
                                              [uses[d] > 1 for d in partials])))
    for n, (terms, target, j) in enumerate(zip(entries, targets, cols)):
        parts = []
        for d, src in terms:
            c = named[d]
            g = "1.0" if src is None else grad_ref(src, j)
            if g == "1.0" or c == "1.0":
                parts.append(c if g == "1.0" else g)
            elif g == "-1.0" or c == "-1.0":
                parts.append(_negate(c if g == "-1.0" else g))
            else:
                parts.append(f"{c}*{g}")
        text = em.join_sum(parts)
        if aliases is not None and _plain(text) and not text.lstrip("-").startswith("_c"):
            aliases[target] = text      # a copy or a constant: read where it is used
        else:
            lines.append(em.store(target, text))
    return lines
