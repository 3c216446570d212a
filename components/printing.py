"""The text of an expression as the user wrote it: sympy's str printer, faster on the
sums and products models are made of (:func:`text`; the index report, errors and the
compile cache print equations with it)."""
from __future__ import annotations

import sympy as sp
from sympy import S
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

from .longtext import shortened
from .realsymbol import SYMBOLS

__all__ = ["text"]


class _TextPrinter(StrPrinter):
    """sympy's str printer with fast paths for the order of terms and factors.

    sympy orders the terms of a sum lexicographically by their monomials, descending
    (``Expr.as_ordered_terms``), and builds that order through ``Expr.as_terms``, which
    converts every coefficient to a complex number: most of the time of printing a model.
    For sums of terms ``c * x1**k1 * x2**k2 ...`` (c a rational or float, x_i symbols of
    distinct names, k_i integers) the same order is computed here directly, on sparse
    monomials.  Factors of a product are ordered by their sort keys, and the key of a
    sum among them is again built through ``as_terms``; for products of a number,
    symbols and their integer powers, at most one sum and at most one function the
    order is known from the classes alone (numbers, symbols by name, the sum, the
    function).  Anything else takes sympy's path, so the text is always sympy's.
    """

    def _print(self, expr, **kwargs) -> str:
        if type(expr) in SYMBOLS:      # what the dispatch would find: _print_Symbol
            return expr.name
        return super()._print(expr, **kwargs)

    def _print_Mul(self, expr):
        ordered = _ordered_factors(expr) if self.order is None else None
        if ordered is None:
            return super()._print_Mul(expr)
        # StrPrinter._print_Mul from here on, for the factors it would have ordered so
        sign, items = ordered
        num, den = [], []
        for item in items:
            if item.is_Pow and item.exp < 0:
                den.append(item.base if item.exp is S.NegativeOne
                           else sp.Pow(item.base, -item.exp, evaluate=False))
            elif item.is_Rational:
                if item.p != 1:
                    num.append(sp.Rational(item.p))
                if item.q != 1:
                    den.append(sp.Rational(item.q))
            else:
                num.append(item)
        num = num or [S.One]
        # a symbol is never parenthesized (its precedence is an atom's), so the
        # product's precedence (a walk of its classes) is only found for other factors
        prec = None
        a_str, b_str = [], []
        for factors, texts in ((num, a_str), (den, b_str)):
            for x in factors:
                if type(x) in SYMBOLS:
                    texts.append(x.name)
                    continue
                if prec is None:
                    prec = precedence(expr)
                texts.append(self.parenthesize(x, prec, strict=False))
        if not den:
            return sign + "*".join(a_str)
        if len(den) == 1:
            return sign + "*".join(a_str) + "/" + b_str[0]
        return sign + "*".join(a_str) + "/(%s)" % "*".join(b_str)

    def _print_Add(self, expr, order=None):
        """StrPrinter._print_Add, with the precedence of a symbol or product term (an
        atom's; a product's is never below a sum's) not looked up."""
        terms = self._as_ordered_terms(expr, order=order)
        prec = precedence(expr)
        out = []
        for term in terms:
            t = self._print(term)
            if t.startswith("-") and not term.is_Add:
                sign, t = "-", t[1:]
            else:
                sign = "+"
            plain = type(term) in SYMBOLS or (term.is_Mul and prec <= PREC_ADD)
            if not plain and (precedence(term) < prec or term.is_Add):
                out += [sign, f"({t})"]
            else:
                out += [sign, t]
        sign = out.pop(0)
        return ("" if sign == "+" else sign) + " ".join(out)

    def _as_ordered_terms(self, expr, order=None):
        if (order or self.order) is None and expr.is_Add:
            terms = _lex_ordered_terms(expr.args)
            if terms is not None:
                return terms
        return super()._as_ordered_terms(expr, order=order)


_END = (1,)


def _lex_ordered_terms(args):
    """The terms in sympy's print order, or None if a term is not a monomial of symbols.

    Dense lexicographic order on the exponent vectors over the symbols sorted by name,
    descending, is reproduced on sparse (symbol rank, exponent) lists: at the first
    symbol where two monomials differ, the one with the larger exponent comes first
    (an absent symbol counts as exponent 0).  The key of a factor is (0, rank, -k) for
    k > 0 and (2, -rank, -k) for k < 0, and ``_END`` closes each list, which makes
    the tuple order of the keys that order.
    """
    if len(args) == 2 and any(a.is_Number for a in args):
        return None          # sympy's special case "c - x" for a number and a product
    monomials, gens = [], {}
    for term in args:
        coeff, rest = term.as_coeff_Mul()
        if not (coeff.is_Rational or coeff.is_Float):
            return None
        powers = []
        if rest is not S.One:
            for f in (rest.args if rest.is_Mul else (rest,)):
                if type(f) in SYMBOLS and f.is_commutative:
                    powers.append((f, 1))
                elif (f.is_Pow and type(f.base) in SYMBOLS and f.base.is_commutative
                      and f.exp.is_Integer):
                    powers.append((f.base, int(f.exp)))
                else:
                    return None
        if len({g for g, _ in powers}) < len(powers):
            return None
        for g, _ in powers:
            gens[g] = g.name
        monomials.append((term, powers))
    names = sorted(gens.values())
    if len(set(names)) < len(names):
        return None          # two symbols of one name: sympy's tie-break is its own
    rank = {n: k for k, n in enumerate(names)}
    keyed = []
    for term, powers in monomials:
        fac = sorted((rank[g.name], k) for g, k in powers)
        key = tuple((0, r, -k) if k > 0 else (2, -r, -k) for r, k in fac) + (_END,)
        keyed.append((key, term))
    keyed.sort(key=lambda kt: kt[0])
    if any(a[0] == b[0] for a, b in zip(keyed, keyed[1:])):
        return None          # equal monomials (an unevaluated sum): sympy's tie-break
    return [t for _, t in keyed]


def _ordered_factors(expr):
    """(sign, factors) as sympy's ``_print_Mul`` orders them, or None where the classes
    alone do not settle the order (see :class:`_TextPrinter`)."""
    args = expr.args
    if not expr.is_commutative or args[0] is S.One or any(
            a.is_Number or (a.is_Pow and all(x.is_Integer for x in a.args))
            for a in args[1:]):
        return None               # sympy prints an unevaluated product as it stands
    c, e = expr.as_coeff_Mul()
    if not (c.is_Rational or c.is_Float):
        return None
    sign = ""
    if (c.p < 0) if c.is_Rational else (c < 0):     # a Rational's sign without sympify
        c, sign = -c, "-"
    named, add, fn = [], None, None
    for f in (e.args if e.is_Mul else (e,)):
        if type(f) in SYMBOLS:
            named.append((f.name, f))
        elif f.is_Pow and type(f.base) in SYMBOLS and f.exp.is_Integer:
            named.append((f.base.name, f))
        elif f.is_Add and add is None:
            add = f
        elif isinstance(f, sp.Function) and fn is None and _class_group(f) == 4:
            fn = f
        else:
            return None
    if len({n for n, _ in named}) < len(named):
        return None
    named.sort(key=lambda nf: nf[0])
    items = ([] if c is S.One else [c]) + [f for _, f in named]
    return sign, items + [x for x in (add, fn) if x is not None]


_FUNCTION_CLASS_KEY = sp.Function.class_key.__func__


def _class_group(f) -> int:
    """``f.class_key()[0]``: 4 for a function class that keeps Function's class_key
    (which would otherwise build the set of its numbers of arguments to say so)."""
    if getattr(type(f).class_key, "__func__", None) is _FUNCTION_CLASS_KEY:
        return 4
    return f.class_key()[0]


PREC_ADD = PRECEDENCE["Add"]      # a product's precedence is a sum's or a product's
_PRINTER = _TextPrinter()


def text(expr) -> str:
    """``sympy.sstr(expr)``, the same text, faster on the sums models are made of (an
    expression too long to read is shortened: components/longtext.py)."""
    short = shortened(expr, _PRINTER)
    return _PRINTER.doprint(expr) if short is None else short
