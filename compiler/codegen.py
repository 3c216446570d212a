"""Code generation (numpy backend): sympy residuals -> Python functions.

The generated source is plain Python on floats with ``math`` functions, after common
subexpression elimination (sympy.cse), so nothing symbolic runs at simulation time.
Per model we generate

* ``residual(t, y, p, m, out)``: the residual rows G(t, y, p) = 0;
* ``jacobian(t, y, p, m, out)``: the values of dG/dy at the fixed sparsity pattern
  ``(rows, cols)`` taken from the structure (symbolic differentiation per non-zero);
* ``roots(t, y, p, m, out)``: the zero-crossing functions of the relations in
  discontinuous expressions.

Relations inside ``if_else``/``sign`` are *frozen* between events (Modelica semantics):
in the generated code each relation reads a boolean ``m[k]`` that only the event
handler changes; the corresponding zero-crossing function is ``lhs - rhs``.
"""
from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

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
        base, e = expr.args
        if e == 2:
            b = self.parenthesize(base, 1000)
            return f"{b}*{b}"
        if e == -1:
            return f"1.0/{self.parenthesize(base, 1000)}"
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


def extract_relations(exprs: list) -> tuple[list, list, dict]:
    """Replace relations inside Piecewise conditions by boolean mode symbols.

    Returns (new exprs, zero-crossing expressions, {mode symbol: relation}).
    """
    relations = {}
    for e in exprs:
        for pw in e.atoms(sp.Piecewise):
            for _, cond in pw.args:
                for rel in _relations_in(cond):
                    relations.setdefault(rel, None)
    ordered = sorted(relations, key=sp.srepr)
    modes = {rel: sp.Symbol(f"_m{k}") for k, rel in enumerate(ordered)}
    new = [e.xreplace(modes) if modes else e for e in exprs]
    crossings = [rel.lhs - rel.rhs for rel in ordered]
    return new, crossings, {modes[r]: r for r in ordered}


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
             crossings: list | None = None) -> GeneratedCode:
    """Generate residual, Jacobian and root functions for G(t, y, p) = 0."""
    from ..components.symbols import time
    crossings = crossings or []
    ysub = {s: sp.Symbol(f"_y{k}") for k, s in enumerate(y_syms)}
    psub = {s: sp.Symbol(f"_p{k}") for k, s in enumerate(params)}
    sub = {**ysub, **psub, time: sp.Symbol("t")}
    res = [sp.sympify(r).xreplace(sub) for r in residuals]
    roots = [sp.sympify(g).xreplace(sub) for g in crossings]
    yset = set(ysub.values())
    ynum = {v: k for k, v in enumerate(ysub.values())}
    rows, cols, jac = [], [], []
    for i, r in enumerate(res):
        for s in sorted(r.free_symbols & yset, key=lambda q: ynum[q]):
            rows.append(i)
            cols.append(ynum[s])
            jac.append(sp.diff(r, s))
    lines = ["import math", "", ""]
    lines += _function("residual", res)
    lines += _function("jacobian", jac)
    lines += _function("roots", roots)
    source = "\n".join(lines) + "\n"
    namespace = {"math": math}
    exec(compile(source, "<acausal generated>", "exec"), namespace)
    return GeneratedCode(source, namespace["residual"], namespace["jacobian"],
                         namespace["roots"], np.array(rows, dtype=np.int64),
                         np.array(cols, dtype=np.int64), len(res), len(roots),
                         hashlib.sha1(source.encode()).hexdigest()[:16])


def _function(name: str, exprs: list) -> list:
    printer = _Printer({"standard": "python3", "fully_qualified_modules": True})
    lines = [f"def {name}(t, y, p, m, out):"]
    if not exprs:
        return lines + ["    return out", "", ""]
    replacements, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("_c"),
                                   order="none")
    used = set()
    for _, e in replacements:
        used |= e.free_symbols
    for e in reduced:
        used |= e.free_symbols
    lines += _unpack(used)
    for sym, e in replacements:
        lines.append(f"    {sym} = {printer.doprint(e)}")
    for k, e in enumerate(reduced):
        lines.append(f"    out[{k}] = {printer.doprint(e)}")
    return lines + ["    return out", "", ""]


def _unpack(used: set) -> list:
    out = []
    for s in sorted(used, key=lambda q: (q.name[:2], int(q.name[2:]) if q.name[2:].isdigit() else 0)):
        n = s.name
        if n.startswith("_y"):
            out.append(f"    {n} = y[{n[2:]}]")
        elif n.startswith("_p"):
            out.append(f"    {n} = p[{n[2:]}]")
        elif n.startswith("_m"):
            out.append(f"    {n} = m[{n[2:]}]")
    return out
