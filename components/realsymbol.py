"""A variable's or a parameter's symbol: ``Symbol(name, real=True)``, made fast.

A model of 18 000 flat equations has some 21 000 such symbols, and sympy deduces the
same facts from ``real=True`` for each (2 of the 3 us a symbol takes).
"""
from __future__ import annotations

import sympy as sp

__all__ = ["real_symbol"]


def real_symbol(name: str) -> sp.Symbol:
    """The symbol ``Symbol.__xnew__(Symbol, name, real=True)`` makes -- a variable's or a
    parameter's, equal to ``Symbol(name, real=True)`` but not from sympy's symbol cache
    (each variable of a model has a name of its own, so a look-up would find nothing).

    Every symbol made with ``real=True`` has the same facts; sympy (1.13 and later)
    shares one table of them among all such symbols, older versions deduce a table for
    each.  Here the facts are taken from one symbol sympy made, shared or copied as
    that sympy does, which is 2 of the 3 us a symbol takes.  The first call checks the
    result against sympy's own symbols; where they differ, sympy makes every symbol."""
    global _make_real
    if _make_real is None:
        _make_real = _real_symbol_maker()
    return _make_real(name)


_make_real = None


def _real_symbol_maker():
    from sympy.core.assumptions import StdFactKB

    def slow(name):
        return sp.Symbol.__xnew__(sp.Symbol, name, real=True)

    template, other = slow("_"), slow("__")
    kb, orig, facts0 = template._assumptions, template._assumptions_orig, template._assumptions0
    shared = other._assumptions is kb
    if not shared and (type(kb) is not StdFactKB or set(vars(kb)) != {"rules", "_generator"}):
        return slow
    new_expr = sp.Expr.__new__

    def fast(name):
        obj = new_expr(sp.Symbol)
        obj.name = name
        if shared:
            obj._assumptions, obj._assumptions_orig = kb, orig
        else:           # a table of its own, holding the facts it learns
            own = StdFactKB.__new__(StdFactKB)
            own.rules, own._generator = kb.rules, dict(kb._generator)
            dict.update(own, kb)
            obj._assumptions, obj._assumptions_orig = own, dict(orig)
        obj._assumptions0 = facts0 if isinstance(facts0, tuple) else dict(facts0)
        return obj

    a, b = fast("x"), slow("x")
    same = (a == b and hash(a) == hash(b) and dict(a._assumptions) == dict(b._assumptions)
            and a._assumptions0 == b._assumptions0
            and a._assumptions_orig == b._assumptions_orig
            and (a._assumptions is b._assumptions) == shared
            and sp.srepr(a) == sp.srepr(b))
    return fast if same else slow
