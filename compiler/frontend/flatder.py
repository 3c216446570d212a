"""Derivatives in flat equations: ``der(expr)`` replaced by derivative symbols ``der(x)``,
expanded by the chain rule where expr is not a variable (part of flattening).

A derivative of a derivative is the derivative symbol of the derivative symbol, so
``der(der(x))`` needs no intermediate variable; ``der()`` of something that cannot vary
is refused, naming the equation.
"""
from __future__ import annotations

import sympy as sp

from ...components.realsymbol import SYMBOLS
from ...components.symbols import der, time
from ..algebra.derivative import partial
from ..algebra.substitution import fast_xreplace
from ..algebra.symbolic import derivative_symbol, signed_sum, signed_terms, symbols_of
from ...errors import InvalidEquation

__all__ = ["expand_derivatives", "has_der", "check_der_arguments"]


def expand_derivatives(flat, with_der: set | None = None) -> None:
    """Replace der(expr) by symbols der(x), expanding der of expressions by the chain rule
    (``with_der``: the ids of the equations that have a der(), if known)."""
    var_syms = {v.symbol for v in flat.variables}
    der_syms = set(flat.derivatives.values())
    for eq in flat.equations + flat.initial_equations:
        found = has_der(eq.residual) if with_der is None else id(eq) in with_der
        if found:
            eq.residual = _replace_der(eq.residual, var_syms, flat.derivatives, der_syms)


def has_der(expr) -> bool:
    """``expr.has(der)``; a product or sum of symbols and numbers (most equations) is
    answered from its arguments without sympy's general pattern search."""
    if expr.is_Atom:
        return False
    stack, seen = [expr], set()
    while stack:                      # over the DAG: a shared part is walked once
        e = stack.pop()
        if isinstance(e, der):
            return True
        for a in e.args:
            if not a.is_Atom and a not in seen:
                seen.add(a)
                stack.append(a)
    return False


def _outer_ders(expr) -> list:
    """The der() nodes of expr that are not inside another der(), in the order of a
    depth-first walk over the arguments (the order sympy's ``replace`` visits them)."""
    out, stack, seen = [], [expr], set()
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, der):
            out.append(e)
        elif not e.is_Atom:
            stack.extend(reversed(e.args))
    return out


def _all_ders(expr) -> list:
    """Every der() node of expr, nested ones included (``expr.atoms(der)``, unsorted)."""
    out, stack, seen = [], [expr], set()
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, der):
            out.append(e)
        if not e.is_Atom:
            stack.extend(e.args)
    return out


def check_der_arguments(eq, var_syms: set) -> None:
    """der() of something that cannot vary (a number, a parameter) is always zero: the
    argument was meant to be a variable."""
    if all(type(d.args[0]) in SYMBOLS and d.args[0] in var_syms
           for d in _all_ders(eq.residual)):
        return      # der(x) of variables only (sorting the der() atoms is for the error)
    for d in sorted(eq.residual.atoms(der), key=sp.default_sort_key):
        arg = d.args[0]
        if not (arg.free_symbols & var_syms) and not arg.has(time):
            what = ("a number" if arg.is_number else
                    "a parameter" if isinstance(arg, sp.Symbol) else
                    "an expression of parameters")
            raise InvalidEquation(f"equation '{eq.text}' in {eq.where}: {d} is the "
                                  f"derivative of {what}, which is constant, so it is 0; "
                                  "der() applies to variables")


def _replace_der(expr, var_syms, derivatives, der_syms):
    """der_syms: the values of ``derivatives``, kept up to date here."""
    def der_symbol(x):
        d = derivative_symbol(x, derivatives)
        der_syms.add(d)
        return d

    def total_derivative(arg):
        arg = _replace_der(arg, var_syms, derivatives, der_syms) if arg.has(der) else arg
        from ...components.userfunctions import has_calls, time_derivative
        if has_calls(arg):          # a user-defined function: by its derivative function
            return time_derivative(arg, chain_rule)
        return chain_rule(arg)

    def chain_rule(arg):
        if arg in var_syms:
            return der_symbol(arg)
        out = partial(arg, time) if arg.has(time) else sp.Integer(0)
        for s in sorted((q for q in symbols_of(arg) if q in var_syms or q in der_syms),
                        key=lambda s: s.name):
            if s in var_syms:
                var_syms_d = der_symbol(s)
            else:  # s is already a derivative symbol: its derivative is the next one
                var_syms.add(s)
                var_syms_d = der_symbol(s)
            out += partial(arg, s) * var_syms_d
        return out

    coeffs = {}
    if signed_terms(expr, 1, coeffs):      # +-x +- der(y) ...: no chain rule needed
        out = {}
        for q, c in coeffs.items():
            if type(q) is der:
                if q.args[0] not in var_syms:
                    break
                q = der_symbol(q.args[0])
            if q in out:
                break
            out[q] = c
        else:
            return signed_sum(out)
    # der() nodes replaced in walk order (the der(x) symbols are created as a bottom-up
    # replacement would); total_derivative expands inner der() in an argument itself
    values = {}
    for d in _outer_ders(expr):
        if d not in values:
            values[d] = total_derivative(d.args[0])
    return fast_xreplace(expr, values)
