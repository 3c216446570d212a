"""Code generation (numpy backend): sympy residuals -> Python functions.

The generated source is plain Python on floats with ``math`` functions, after common
subexpression elimination (sympy.cse), so nothing symbolic runs at simulation time.
Per model we generate

* ``residual(t, y, p, m, out)``: the residual rows G(t, y, p) = 0;
* ``jacobian(t, y, p, m, out)``: the values of dG/dy at the fixed sparsity pattern
  ``(rows, cols)`` taken from the structure (symbolic differentiation per non-zero);
* ``roots(t, y, p, m, out)``: the zero-crossing functions of the relations in
  discontinuous expressions, then the arguments of the frozen floor values;
* ``scales(t, y, p, m, out)``: the magnitude ``|lhs| + |rhs|`` of each relation, the
  scale on which its distance from zero is judged.

Relations inside ``if_else``/``sign`` are *frozen* between events (Modelica semantics):
in the generated code each relation reads a value ``m[k]`` (1.0 or 0.0) that only the
runtime changes at events; the corresponding zero-crossing function is ``lhs - rhs``.
Frozen floor values (:mod:`acausal.compiler.discrete`) follow the relations in ``m``.
"""
from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from .derivative import partial as _partial

__all__ = ["GeneratedCode", "generate", "extract_relations"]


class _Printer(PythonCodePrinter):
    """Python printer that emits math.* and keeps floats exact (repr)."""

    def _print_Float(self, expr):
        return repr(float(expr))

    def _print_Rational(self, expr):
        return repr(float(expr))

    def _print_Integer(self, expr):
        return str(int(expr))

    def _print_Pow(self, expr, rational=False):
        # Parenthesized, so that x/a**2 inside a product stays x/(a*a).
        base, e = expr.args
        if e == 2:
            b = self.parenthesize(base, 1000)
            return f"({b}*{b})"
        if e == -1:
            return f"(1.0/{self.parenthesize(base, 1000)})"
        return super()._print_Pow(expr, rational)


@dataclass
class GeneratedCode:
    source: str
    residual: object
    jacobian: object
    roots: object
    jac_rows: np.ndarray
    jac_cols: np.ndarray
    n_rows: int
    n_roots: int
    digest: str
    scales: object = None
    expand: object = None


def event_form(expr: sp.Expr) -> sp.Expr:
    """abs, min, max and sign as if-expressions, so their kinks generate events (as in
    Modelica, where only noEvent(...) suppresses them); inside no_event(...) they stay."""
    from ..components.symbols import no_event
    if not expr.has(sp.Abs, sp.Min, sp.Max, sp.sign, no_event):
        return expr
    quiet = {}
    for k, q in enumerate(expr.atoms(no_event)):
        quiet[q] = sp.Dummy(f"quiet{k}")
    e = expr.xreplace(quiet) if quiet else expr
    e = e.replace(sp.Abs, lambda x: sp.Piecewise((x, x >= 0), (-x, True)))
    e = e.replace(sp.sign, lambda x: sp.Piecewise((1, x > 0), (-1, x < 0), (0, True)))
    e = e.replace(sp.Min, lambda *a: _fold(a, lambda u, v: sp.Piecewise((u, u <= v), (v, True))))
    e = e.replace(sp.Max, lambda *a: _fold(a, lambda u, v: sp.Piecewise((u, u >= v), (v, True))))
    # the no_event wrappers go back in: _freeze unwraps them after relations are taken
    return e.xreplace({d: q for q, d in quiet.items()}) if quiet else e


def _fold(args, pair):
    out = args[0]
    for a in args[1:]:
        out = pair(out, a)
    return out


def extract_relations(exprs: list) -> tuple[list, list, dict, list]:
    """Replace relations inside Piecewise conditions by mode symbols.

    abs/min/max/sign are first written as if-expressions (:func:`event_form`); relations
    inside ``no_event(...)`` stay as they are and are evaluated directly.
    Returns (new exprs, zero-crossing expressions, {mode symbol: relation}, origin) where
    ``origin[k]`` is the index of the first expression that relation k occurs in.
    """
    from ..components.symbols import no_event
    exprs = [event_form(sp.sympify(e)) for e in exprs]
    relations = {}
    for i, e in enumerate(exprs):
        for pw in _event_piecewise(e, no_event):
            for _, cond in pw.args:
                for rel in _relations_in(cond):
                    relations.setdefault(rel, i)
    ordered = sorted(relations, key=sp.srepr)
    modes = {rel: sp.Symbol(f"_m{k}") for k, rel in enumerate(ordered)}
    new = [_freeze(e, modes, no_event) for e in exprs]
    crossings = [rel.lhs - rel.rhs for rel in ordered]
    return new, crossings, {modes[r]: r for r in ordered}, [relations[r] for r in ordered]


def _event_piecewise(e, no_event):
    """Piecewise sub-expressions of e that are not inside no_event(...)."""
    if isinstance(e, no_event):
        return []
    out = [e] if isinstance(e, sp.Piecewise) else []
    for a in e.args:
        out += _event_piecewise(a, no_event)
    return out


def _freeze(e, modes, no_event):
    """Relations -> mode symbols, except inside no_event(...), which is unwrapped."""
    if not modes and not e.has(no_event):
        return e
    quiet = {q: sp.Dummy() for q in e.atoms(no_event)}
    out = e.xreplace(quiet).xreplace(modes) if modes else e.xreplace(quiet)
    return out.xreplace({d: q.args[0] for q, d in quiet.items()})


def _relations_in(cond):
    if isinstance(cond, sp.core.relational.Relational):
        if isinstance(cond, (sp.Eq, sp.Ne)):
            raise ValueError(f"equality relation {cond} cannot generate an event; "
                             "use <, <=, > or >=")
        return [cond]
    if isinstance(cond, sp.logic.boolalg.BooleanFunction):
        return [r for a in cond.args for r in _relations_in(a)]
    return []


def generate(residuals: list, y_syms: list, params: list, n_modes: int = 0,
             crossings: list | None = None, assignments=(), outputs=None, discretes=(),
             scales=None) -> GeneratedCode:
    """Generate residual, Jacobian and root functions.

    ``y_syms`` are the unknowns the solver holds (the vector z); ``assignments`` is an
    ordered list of (symbol, expression) computed explicitly from z before the residual
    rows (the BLT's solved blocks).  The Jacobian of the rows with respect to z is
    generated by the chain rule through the assignments (forward mode): each assigned
    symbol carries the sparse gradient  d a/dz = sum_b  df/db * db/dz.
    ``outputs``: symbols whose values ``expand(t, z, p, m, out)`` returns (the full y).
    ``discretes``: the symbols of frozen floor values, read from ``m[n_modes + j]``;
    ``scales``: expressions for the ``scales`` function (relation magnitudes).
    """
    from ..components.symbols import time
    crossings = crossings or []
    sub = {s: sp.Symbol(f"_y{k}", real=True) for k, s in enumerate(y_syms)}
    n_z = len(y_syms)
    for k, (a, _) in enumerate(assignments):
        sub[a] = sp.Symbol(f"_a{k}", real=True)
    sub.update({s: sp.Symbol(f"_p{k}", real=True) for k, s in enumerate(params)})
    sub.update({s: sp.Symbol(f"_m{n_modes + j}") for j, s in enumerate(discretes)})
    sub[time] = sp.Symbol("t", real=True)
    res = [sp.sympify(r).xreplace(sub) for r in residuals]
    roots = [sp.sympify(g).xreplace(sub) for g in crossings]
    assigned = [(sub[a], sp.sympify(e).xreplace(sub)) for a, e in assignments]
    prologue = [f"    {a} = {_PRINTER.doprint(e)}" for a, e in assigned]
    grads, grad_lines = _gradients(assigned, n_z)
    rows, cols, jac = _jacobian_entries(res, grads)
    lines = ["import math", "", ""]
    lines += _function("residual", res, prologue)
    lines += _function("jacobian", jac, prologue + grad_lines, cse=not assigned)
    lines += _function("roots", roots, _needed(assigned, roots))
    scale_rows = [sp.sympify(g).xreplace(sub) for g in (scales or [])]
    lines += _function("scales", scale_rows, _needed(assigned, scale_rows))
    if outputs is not None:
        lines += _function("expand", [sp.sympify(o).xreplace(sub) for o in outputs], prologue,
                           cse=False)
    source = "\n".join(lines) + "\n"
    namespace = {"math": math}
    exec(compile(source, "<acausal generated>", "exec"), namespace)
    code = GeneratedCode(source, namespace["residual"], namespace["jacobian"],
                         namespace["roots"], np.array(rows, dtype=np.int64),
                         np.array(cols, dtype=np.int64), len(res), len(roots),
                         hashlib.sha1(source.encode()).hexdigest()[:16],
                         namespace["scales"], namespace.get("expand"))
    return code


def _needed(assigned, exprs) -> list:
    """The assignment lines that exprs depend on, in order (the others are left out: a
    root function must not evaluate sqrt(1 - p) that only the residual needs)."""
    need = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
    keep = []
    for a, e in reversed(assigned):
        if a in need:
            keep.append((a, e))
            need |= e.free_symbols
    return [f"    {a} = {_PRINTER.doprint(e)}" for a, e in reversed(keep)]


def _gradients(assigned, n_z):
    """Forward-mode gradients of the assigned symbols with respect to z (sparse)."""
    grads = {sp.Symbol(f"_y{j}", real=True): {j: sp.Integer(1)} for j in range(n_z)}
    lines = []
    for k, (a, e) in enumerate(assigned):
        g = {}
        for b in sorted((q for q in e.free_symbols if q in grads), key=lambda q: q.name):
            partial = _partial(e, b)
            if partial == 0:
                continue
            for j, gb in grads[b].items():
                g[j] = g.get(j, sp.Integer(0)) + partial * gb
        named = {}
        for j, expr in sorted(g.items()):
            sym = sp.Symbol(f"_g{k}_{j}", real=True)
            lines.append(f"    {sym} = {_PRINTER.doprint(expr)}")
            named[j] = sym
        grads[a] = named
    return grads, lines


def _jacobian_entries(res, grads):
    rows, cols, jac = [], [], []
    for i, r in enumerate(res):
        g = {}
        for b in sorted((q for q in r.free_symbols if q in grads), key=lambda q: q.name):
            partial = _partial(r, b)
            for j, gb in grads[b].items():
                g[j] = g.get(j, sp.Integer(0)) + partial * gb
        for j in sorted(g):
            rows.append(i)
            cols.append(j)
            jac.append(g[j])
    return rows, cols, jac


def _function(name: str, exprs: list, prologue=(), cse: bool = True) -> list:
    lines = [f"def {name}(t, y, p, m, out):"]
    if not exprs:
        return lines + ["    return out", "", ""]
    if cse:
        replacements, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("_c"), order="none")
    else:
        replacements, reduced = [], exprs
    used = set()
    for _, e in replacements:
        used |= e.free_symbols
    for e in reduced:
        used |= e.free_symbols
    body = [f"    {sym} = {_PRINTER.doprint(e)}" for sym, e in replacements]
    body += [f"    out[{k}] = {_PRINTER.doprint(e)}" for k, e in enumerate(reduced)]
    text = "\n".join(prologue) + "\n" + "\n".join(body)
    for line in prologue:
        used |= {sp.Symbol(w) for w in _identifiers(line)}
    lines += _unpack(used, text)
    lines += list(prologue) + body
    return lines + ["    return out", "", ""]


def _identifiers(line: str) -> list:
    import re
    return re.findall(r"\b_[ypm]\d+\b", line)


def _unpack(used: set, text: str) -> list:
    import re
    names = set(re.findall(r"\b_[ypm]\d+\b", text))
    out = []
    for n in sorted(names, key=lambda q: (q[:2], int(q[2:]))):
        src = {"_y": "y", "_p": "p", "_m": "m"}[n[:2]]
        out.append(f"    {n} = {src}[{n[2:]}]")
    return out


_PRINTER = _Printer({"standard": "python3", "fully_qualified_modules": True})
