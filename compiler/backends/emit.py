"""Expressions to statements of Python or C, linear in the size of the expression.

sympy's printers and ``cse`` work on the whole system at once and recurse on the
expression tree; on large models they dominate the build, and a sum of thousands of terms
printed as one ``a + b + c + ...`` exceeds what CPython's compiler accepts.  Here each
statement (one residual row, one assigned variable) is printed on its own, by an
explicit-stack walk:

* common subexpressions *within the statement* are named once (``_cK``); sharing across
  statements is what the BLT's assigned variables already provide;
* nothing is hoisted out of the branches of an if-expression, so a branch that is not
  taken is not evaluated (``sqrt(x)`` only where ``x >= 0``);
* sums and products of more than ``CHUNK`` operands are written as balanced groups, so
  the nesting depth grows with log(n) and any length compiles;
* numbers print exactly (``repr`` of the double); ``x**2`` is ``x*x``, other powers
  ``pow`` (``math.pow`` in Python: it raises outside its domain, as C's yields NaN), so
  both targets evaluate the same floating-point operations in the same order.

Operators sympy has and this printer does not are printed by sympy's own printer with
their arguments already named, so nothing is dropped; ``no_event(u)`` prints as ``u``.
"""
from __future__ import annotations

import re

import sympy as sp
from sympy.core.relational import Relational
from sympy.logic.boolalg import And, BooleanFalse, BooleanTrue, Not, Or

from ...components.ifexpr import IfExpr
from ...components.symbols import no_event

__all__ = ["Emitter", "CHUNK"]

CHUNK = 32

_FUNCS = {sp.sin: "sin", sp.cos: "cos", sp.tan: "tan", sp.asin: "asin", sp.acos: "acos",
          sp.atan: "atan", sp.sinh: "sinh", sp.cosh: "cosh", sp.tanh: "tanh",
          sp.exp: "exp", sp.log: "log", sp.atan2: "atan2", sp.floor: "floor",
          sp.ceiling: "ceil", sp.asinh: "asinh", sp.acosh: "acosh", sp.atanh: "atanh"}
_REL = {"StrictGreaterThan": ">", "GreaterThan": ">=", "StrictLessThan": "<",
        "LessThan": "<=", "Equality": "==", "Unequality": "!="}


class Emitter:
    """Statements ``target = expr`` for one target language.

    ``ref(symbol)`` gives the text that reads a symbol (``y[3]``, ``_a5``, ``w[12]``);
    ``lang`` is ``"py"`` or ``"c"``.  Temporaries are numbered across the whole function
    the emitter writes (``_c0``, ``_c1``, ...), so a failing line names its statement.
    """

    def __init__(self, lang: str, ref):
        self.lang = lang
        self.ref = ref
        self.n_temp = 0
        self._math = "math." if lang == "py" else ""

    # -- statements --------------------------------------------------------------------
    def assign(self, target: str, expr) -> list[str]:
        """Lines computing expr into target (temporaries first)."""
        lines = []
        shared = _shared(expr)
        names = {}
        text = self._print(expr, shared, names, lines)
        lines.append(self.store(target, text))
        return lines

    def expression(self, expr, lines, temp=False) -> str:
        """The text of expr, its temporaries appended to lines; ``temp``: name the whole
        expression too (it is used more than once)."""
        text = self._print(expr, _shared(expr), {}, lines)
        if temp and not _plain(text):
            return self._temp(text, lines)
        return text

    def expressions(self, exprs, lines, temps) -> list:
        """The texts of ``exprs``, their temporaries appended to lines: a subexpression
        that two of them contain (the cos(u) of several partial derivatives of sin(u))
        is computed once, as one within an expression is; ``temps[k]``: name the k-th
        whole expression too (it is used more than once)."""
        shared, names, texts = _shared(*exprs), {}, []
        for expr, temp in zip(exprs, temps):
            text = self._print(expr, shared, names, lines)
            if temp and not _plain(text):
                text = self._temp(text, lines)
            texts.append(text)
        return texts

    def join_sum(self, parts) -> str:
        return self._add(parts) if len(parts) > 1 else parts[0]

    def store(self, target, text):
        return f"{target} = {text}" + (";" if self.lang == "c" else "")

    def _temp(self, text, lines):
        name = f"_c{self.n_temp}"
        self.n_temp += 1
        lines.append(f"{name} = {text}" if self.lang == "py" else f"double {name} = {text};")
        return name

    # -- printing ------------------------------------------------------------------------
    def _print(self, root, shared, names, lines) -> str:
        """Post-order walk with an explicit stack; a shared node is printed once."""
        done = {}
        stack = [(root, False)]
        while stack:
            node, ready = stack.pop()
            if node in done or node in names:
                continue
            kids = self._children(node)
            if not ready and kids:
                stack.append((node, True))
                stack.extend((k, False) for k in kids if k not in done and k not in names)
                continue
            text = self._node(node, done, names, shared)
            if node in shared and kids:
                names[node] = self._temp(text, lines)
            else:
                done[node] = text
        return names.get(root) or done[root]

    def _children(self, node):
        if isinstance(node, (sp.Piecewise, IfExpr)):
            return []      # branches are printed inline, lazily (see _piecewise)
        if node.is_Atom:
            return []
        if node.is_Pow and node.exp.is_Number:
            return [node.base]
        if node.is_Mul:
            return _factors(node)
        return list(node.args)

    def _arg(self, a, done, names):
        text = names.get(a) or done.get(a)
        if text is None:      # an equal number sympy rebuilt (2 and 2.0 compare unequal)
            text = self._number(a) if a.is_Number else self._inline(a)
        return text

    def _node(self, e, done, names, shared) -> str:
        if e.is_Symbol:
            return self.ref(e)
        if e is sp.zoo or e is sp.nan:
            # an undefined value (1/0 in a branch of min/max, where its limit is 0):
            # NaN, which the solver reports with the equation if the branch is taken
            return "math.nan" if self.lang == "py" else "NAN"
        if e.is_Number or isinstance(e, sp.NumberSymbol):
            return self._number(e)
        if isinstance(e, (BooleanTrue, BooleanFalse)):
            true = isinstance(e, BooleanTrue)
            return ("True" if true else "False") if self.lang == "py" else ("1" if true else "0")
        if e.is_Add:
            return self._add([self._arg(a, done, names) for a in e.args])
        if e.is_Mul:
            return self._mul(e, done, names)
        if e.is_Pow:
            return self._pow(e, done, names)
        if isinstance(e, sp.Piecewise):
            return self._piecewise(e)
        if isinstance(e, IfExpr):            # an if-expression kept whole in a condition
            return self._piecewise(sp.Piecewise(*e.pairs()))
        if isinstance(e, Relational):
            op = _REL.get(type(e).__name__)
            if op is None:
                raise ValueError(f"relation {e} cannot be evaluated; use <, <=, > or >=")
            return f"({self._arg(e.lhs, done, names)} {op} {self._arg(e.rhs, done, names)})"
        if isinstance(e, (And, Or)):
            op = {And: " and ", Or: " or "} if self.lang == "py" else {And: " && ", Or: " || "}
            return "(" + op[type(e)].join(self._cond(a, done, names) for a in e.args) + ")"
        if isinstance(e, Not):
            c = self._cond(e.args[0], done, names)
            return f"(not {c})" if self.lang == "py" else f"(!{c})"
        if isinstance(e, no_event):
            # what is left of no_event(u) here is evaluated directly, as u: relations to
            # be frozen were replaced before (codegen.extract_relations)
            return self._arg(e.args[0], done, names)
        if isinstance(e, sp.Abs):
            return f"{'abs' if self.lang == 'py' else 'fabs'}({self._arg(e.args[0], done, names)})"
        if isinstance(e, (sp.Min, sp.Max)):
            return self._minmax(e, done, names)
        if isinstance(e, sp.sign):
            x = self._arg(e.args[0], done, names)
            return self._ternary(f"({x} > 0)", "1.0", self._ternary(f"({x} < 0)", "-1.0", "0.0"))
        f = _FUNCS.get(e.func)
        if f is not None:
            args = ", ".join(self._arg(a, done, names) for a in e.args)
            if self.lang == "py" and f in ("floor", "ceil"):
                return f"float({self._math}{f}({args}))"
            return f"{self._math}{f}({args})"
        return self._fallback(e, done, names)

    def _number(self, e) -> str:
        x = float(e)
        if x != x:
            return "math.nan" if self.lang == "py" else "NAN"
        if self.lang == "py":
            return repr(x) if not float(x).is_integer() or abs(x) >= 1e16 else repr(x)
        s = repr(x)
        if s in ("inf", "-inf"):
            return "HUGE_VAL" if x > 0 else "(-HUGE_VAL)"
        return s if any(c in s for c in ".e") else s + ".0"

    def _add(self, terms: list) -> str:
        if len(terms) > CHUNK:
            groups = [terms[k:k + CHUNK] for k in range(0, len(terms), CHUNK)]
            return self._add([self._add(g) for g in groups])
        out = terms[0]
        for t in terms[1:]:
            out += f" - {t.positive}" if isinstance(t, _Neg) else f" + {t}"
        return f"({out})"

    def _mul(self, e, done, names) -> str:
        coeff, factors = e.as_coeff_mul()
        num, den = [], []
        for f in factors:
            if f.is_Pow and f.exp.is_Number and f.exp < 0:
                if f.exp == -1:
                    den.append(self._arg(f.base, done, names))
                else:
                    den.append(self._power(self._arg(f.base, done, names), -f.exp))
            else:
                num.append(self._arg(f, done, names))
        sign = ""
        if coeff == -1:
            sign = "-"
        elif coeff != 1:
            num.insert(0, self._number(coeff))
        text = self._product(num) if num else "1.0"
        if den:
            text = f"{text}/{self._product(den)}"
        return _Neg(text) if sign else text

    def _product(self, factors):
        if len(factors) > CHUNK:
            groups = [factors[k:k + CHUNK] for k in range(0, len(factors), CHUNK)]
            return self._product([self._product(g) for g in groups])
        return factors[0] if len(factors) == 1 else "(" + "*".join(factors) + ")"

    def _pow(self, e, done, names) -> str:
        if e.exp.is_Number:
            b = self._arg(e.base, done, names)
            if e.exp < 0:
                return f"(1.0/{self._power(b, -e.exp)})"
            return self._power(b, e.exp)
        b, x = self._arg(e.base, done, names), self._arg(e.exp, done, names)
        if e.base == sp.E:
            return f"{self._math}exp({x})"
        return f"{'math.pow' if self.lang == 'py' else 'pow'}({b}, {x})"

    def _power(self, b: str, r) -> str:
        if r == 1:
            return b
        if r == 2:
            return f"({b}*{b})"
        if r == sp.Rational(1, 2):
            return f"{self._math}sqrt({b})"
        return f"{'math.pow' if self.lang == 'py' else 'pow'}({b}, {self._number(r)})"

    def _minmax(self, e, done, names) -> str:
        args = [self._arg(a, done, names) for a in e.args]
        if self.lang == "py":
            return f"{'min' if isinstance(e, sp.Min) else 'max'}({', '.join(args)})"
        f = "fmin" if isinstance(e, sp.Min) else "fmax"
        out = args[0]
        for a in args[1:]:
            out = f"{f}({out}, {a})"
        return out

    def _cond(self, c, done, names) -> str:
        text = self._arg(c, done, names) if c in done or c in names else self._inline(c)
        if c.is_Symbol and self.lang == "c":
            return f"({text} != 0.0)"
        return text

    def _ternary(self, cond, a, b) -> str:
        if self.lang == "py":
            return f"({a} if {cond} else {b})"
        return f"({cond} ? {a} : {b})"

    def _inline(self, e) -> str:
        """Print a sub-expression completely inline (inside a branch: nothing hoisted)."""
        return self._print(e, set(), {}, _NoLines())

    def _piecewise(self, e) -> str:
        pieces = list(e.args)
        out = None
        for value, cond in reversed(pieces):
            v = self._inline(value)
            if out is None and (cond is sp.true or isinstance(cond, BooleanTrue)):
                out = v
                continue
            if out is None:
                out = "math.nan" if self.lang == "py" else "NAN"
            c = self._inline(cond)
            if cond.is_Symbol and self.lang == "c":
                c = f"({c} != 0.0)"
            out = self._ternary(c, v, out)
        return out

    def _fallback(self, e, done, names) -> str:
        """An operator this printer does not know: sympy prints it, arguments named."""
        # imported here: sympy's code printers take 60 ms to import, for operators that
        # few models have
        from sympy.printing.c import C99CodePrinter
        from sympy.printing.pycode import PythonCodePrinter
        subs = [sp.Symbol(self._arg(a, done, names).replace(" ", "")) if a.is_Symbol
                else sp.Symbol(f"__arg{k}") for k, a in enumerate(e.args)]
        placeholder = e.func(*subs)
        printer = (PythonCodePrinter({"fully_qualified_modules": True}) if self.lang == "py"
                   else C99CodePrinter())
        text = printer.doprint(placeholder)
        for k, a in enumerate(e.args):
            text = text.replace(f"__arg{k}", f"({self._arg(a, done, names)})")
        return f"({text})"


class _NoLines(list):
    """Inside a branch nothing is hoisted: a temporary request is a logic error."""

    def append(self, item):       # pragma: no cover - _inline passes no shared nodes
        raise AssertionError("temporary inside a branch")


def _plain(text: str) -> bool:
    """A name, an indexed read or a number: nothing to gain by naming it."""
    return re.fullmatch(r"-?[\w.]+(\[\d+\])?", text) is not None


class _Neg(str):
    """The text ``(-x)`` of a negated product x, so that a sum can write ``a - x``."""

    def __new__(cls, positive):
        out = super().__new__(cls, f"(-{positive})")
        out.positive = positive
        return out


def _factors(mul) -> list:
    """The operands a product is printed from: a factor b**-r is printed as a division
    by b**r, so b (not the power) is what the product reads."""
    return [f.base if f.is_Pow and f.exp.is_Number and f.exp < 0 else f for f in mul.args]


def _shared(*roots) -> set:
    """Non-atomic nodes reached more than once from ``roots`` outside if-expression
    branches."""
    seen, shared = set(), set()
    stack = list(roots)
    while stack:
        node = stack.pop()
        if node.is_Atom:
            continue
        if node in seen:
            shared.add(node)
            continue
        seen.add(node)
        if isinstance(node, (sp.Piecewise, IfExpr)):
            continue
        if node.is_Pow and node.exp.is_Number:
            stack.append(node.base)
        elif node.is_Mul:
            stack.extend(_factors(node))
        else:
            stack.extend(node.args)
    # a negated copy -x of a shared x is cheap to print again
    return {n for n in shared if not (n.is_Mul and len(n.args) == 2 and n.args[0] == -1
                                     and n.args[1].is_Atom)}
