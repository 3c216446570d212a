"""Dimensional consistency of the flat equations (the ``units`` step after flattening).

Each symbol of the flat model has the dimension of its declared unit
(``components.units``); a variable or parameter declared without a unit is *unknown*:
it takes whatever dimension it meets and is never the cause of an error (the report
lists them).  Dimensions propagate bottom-up through each residual:

* a sum's terms, both sides of an equation, the branches of ``if_else``, the sides of a
  relation, the arguments of ``min``/``max``/``atan2``/``mod`` have one dimension;
* a product multiplies dimensions, ``x**n`` (n a number) raises them to n;
* ``exp``, ``log``, ``sin`` and the other transcendental functions, and a symbolic
  exponent, take dimensionless arguments and return dimensionless values;
* ``der(x)`` has x's dimension per second; ``time`` is in seconds;
* a number is dimensionless as a factor (``2*x`` has x's dimension), and a number
  standing alone as a term or a side (``x = 1``, ``T - 273.15``) takes the dimension of
  the sum, as Modelica tools treat literals;
* an expression containing an unknown factor is unknown.

A mismatch raises ``UnitError`` (``check_units="error"``) or warns (``"warn"``) naming
the equation (with its label), its component and the two dimensions.  The check works
once on the flat equations, with the dimension of each symbol computed once; it never
changes the model.
"""
from __future__ import annotations

import time
import warnings
from fractions import Fraction

import sympy as sp

from ...components.symbols import Equation, der, no_event
from ...components.symbols import Pre as pre
from ...components.units import DIMENSIONLESS, MODES, UnitCheck, dimension_text, parse_unit
from ...errors import UnitError, UnitWarning
from ...words import TEXT, shortened

__all__ = ["check_units", "complain", "UnitCheck", "MODES"]

_TIME = (0, 0, 1, 0, 0, 0, 0)

# functions whose arguments and value are dimensionless
_TRANSCENDENTAL = (sp.exp, sp.log, sp.sin, sp.cos, sp.tan, sp.asin, sp.acos, sp.atan,
                   sp.sinh, sp.cosh, sp.tanh, sp.asinh, sp.acosh, sp.atanh, sp.cot,
                   sp.sec, sp.csc, sp.erf)


class _Literal:
    """The dimension of a bare number: dimensionless as a factor, adopted as a term."""

    def __repr__(self):
        return "number"


LITERAL = _Literal()


class _Mismatch(Exception):
    def __init__(self, what: str, a, da, b=None, db=None):
        super().__init__(what)
        self.what, self.a, self.da, self.b, self.db = what, a, da, b, db

    def describe(self) -> str:
        first = f"'{sp.sstr(self.a)}' is {dimension_text(self.da)}"
        if self.b is None:
            return f"{self.what}: {first}"
        return f"{self.what}: {first} but '{sp.sstr(self.b)}' is {dimension_text(self.db)}"


def check_units(flat, mode: str = "warn", known: UnitCheck | None = None,
                quiet: bool = False) -> UnitCheck:
    """Check every equation of ``flat`` (a FlatModel); see the module docstring.

    ``known``: the check of the same flat model found in the compile cache (the flat key
    covers every unit and expression the check reads); its findings are reported in this
    ``mode`` without checking again, so a cache hit does not load sympy's units.
    ``quiet``: the findings are returned, not reported (:func:`complain` reports them
    where the check ran in a side job, :mod:`acausal.compiler.pipeline`)."""
    if mode not in MODES:
        raise ValueError(f"check_units must be one of {MODES}, not {mode!r}")
    result = UnitCheck(mode=mode)
    result.unitless_variables = [v.name for v in flat.variables if not v.attrs.unit]
    result.unitless_parameters = [p.name for p in flat.parameters if not p.unit]
    if mode == "off":
        return result
    if known is not None and known.mode != "off":
        result.checked, result.mismatches = known.checked, list(known.mismatches)
        complain(result, mode)
        return result
    t0 = time.perf_counter()
    dims = _symbol_dimensions(flat)
    walker = _Walker(dims)
    for eq in flat.equations + flat.initial_equations:
        try:
            _check_equation(eq, walker)
        except _Mismatch as m:
            result.mismatches.append(_message(eq, m))
        result.checked += 1
    for w in flat.whens:          # the relations of the condition; reinit(x, expr)
        try:
            walker.condition(w.condition)
            for act in w.actions:
                walker.same([act.variable, act.value], "reinit changes the dimension")
        except _Mismatch as m:
            result.mismatches.append(f"when {sp.sstr(w.condition)} in {w.origin or '(model)'}"
                                     f" ({w.origin_class}): {m.describe()}")
        result.checked += 1
    for p in flat.parameters:
        if isinstance(p.value, sp.Basic) and not p.value.is_number and p.unit:
            _check_binding(p, walker, dims, result)
    result.seconds = time.perf_counter() - t0
    if not quiet:
        complain(result, mode)
    return result


def complain(result: UnitCheck, mode: str) -> UnitCheck:
    """Raise (``"error"``) or warn at the mismatches found; returns ``result``."""
    if result.mismatches:
        more = len(result.mismatches) - 1
        text = result.mismatches[0] + (f" (and {more} more inconsistent equation(s): "
                                       + "; ".join(result.mismatches[1:]) + ")" if more else "")
        if mode == "error":
            raise UnitError(text + ". Fix the units, or compile with check_units='warn'")
        for msg in result.mismatches:
            warnings.warn(msg, UnitWarning, stacklevel=5)
    return result


def _check_equation(eq, walker) -> None:
    """Both sides as written, where the equation was written as ``Eq(lhs, rhs)`` (the
    message then shows them as the user wrote them); else the residual's terms."""
    src = eq.source
    if isinstance(src, Equation):
        walker.same([src.lhs, src.rhs], "the sides differ")
    elif eq.unmade is None or not _one_dimension(eq.unmade, walker):
        walker.dim(eq.residual)


def _one_dimension(terms, walker) -> bool:
    """Whether the terms {q: +-1} of a sum not made yet have one dimension, where they are
    known (then the sum would pass; else it is made, and walked for the message)."""
    found = None
    for q in terms:
        d = walker.dim(q)
        if _known(d):
            if found is None:
                found = d
            elif d != found:
                return False
    return True


def _message(eq, m: _Mismatch) -> str:
    return (f"equation '{shortened(eq.text)}' in {eq.where}: "
            f"{shortened(m.describe(), 2 * TEXT)}")


def _check_binding(p, walker, dims, result) -> None:
    declared = dims.get(p.symbol)
    try:
        got = walker.dim(p.value)
    except _Mismatch as m:
        result.mismatches.append(f"{p.describe()} = {sp.sstr(p.value)}: {m.describe()}")
        return
    if _known(got) and declared is not None and got != declared:
        result.mismatches.append(
            f"{p.describe()} = {sp.sstr(p.value)}: the binding is {dimension_text(got)} "
            f"but the parameter is declared in '{p.unit}' ({dimension_text(declared)})")


def _symbol_dimensions(flat) -> dict:
    """symbol -> dimension tuple (None: unknown) for variables, parameters, derivatives
    and time."""
    dims = {}
    for v in flat.variables:
        dims[v.symbol] = _parsed(v.attrs.unit, v.name)
    for p in flat.parameters:
        dims[p.symbol] = _parsed(p.unit, p.name)
    pending = dict(flat.derivatives)
    while pending:            # der(der(x)) after der(x): follow the chains
        for x, d in list(pending.items()):
            if x in dims:
                dims[d] = _per_second(dims[x])
                del pending[x]
            elif x not in pending.values():
                dims[d] = None
                del pending[x]
    dims[sp.Symbol("time", real=True)] = _TIME
    return dims


def _parsed(unit: str, name: str):
    try:
        u = parse_unit(unit)
    except UnitError as err:
        raise UnitError(f"{name}: {err}") from None
    return None if u is None else u.dims


def _per_second(d):
    return None if d is None else _sub(d, _TIME)


def _add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def _sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def _known(d) -> bool:
    return d is not None and d is not LITERAL


def _scaled(d, n):
    return tuple(_plain(Fraction(x) * n) for x in d)


def _plain(x: Fraction):
    return int(x) if x.denominator == 1 else x


class _Walker:
    """Dimension of an expression (see the module docstring); raises _Mismatch."""

    def __init__(self, dims: dict):
        self.dims = dims
        self.cache = {}

    def dim(self, e):
        if e.is_Symbol:
            return self.dims.get(e)
        if e.is_Number or e.is_NumberSymbol:
            return LITERAL
        found = self.cache.get(e)
        if found is None:
            found = self.cache[e] = self._compound(e)
        return found

    def _compound(self, e):
        if e.is_Add:
            return self.same(e.args, "terms of a sum differ")
        if e.is_Mul:
            return self._product(e.args)
        if e.is_Pow:
            return self._power(e)
        if isinstance(e, der):
            return _per_second(self._value(e.args[0]))
        if isinstance(e, (pre, no_event, sp.Abs, sp.floor, sp.ceiling)):
            return self.dim(e.args[0])
        if isinstance(e, sp.sign):
            self.dim(e.args[0])
            return DIMENSIONLESS
        if isinstance(e, (sp.Min, sp.Max, sp.Mod)):
            return self.same(e.args, f"the arguments of {type(e).__name__} differ")
        if isinstance(e, sp.atan2):
            self.same(e.args, "the arguments of atan2 differ")
            return DIMENSIONLESS
        if isinstance(e, _TRANSCENDENTAL):
            for a in e.args:
                self._dimensionless(a, f"the argument of {type(e).__name__}")
            return DIMENSIONLESS
        if isinstance(e, sp.Piecewise):
            for _, cond in e.args:
                self.condition(cond)
            return self.same([v for v, _ in e.args], "the branches of if_else differ")
        if isinstance(e, sp.Derivative):
            d = self._value(e.expr)
            n = sum(count for _, count in e.variable_count)
            return None if d is None else _sub(d, _scaled(_TIME, n))
        for a in e.args:          # another function (a table, a user's): check inside
            if isinstance(a, sp.Expr):
                self.dim(a)
        return None

    def _value(self, e):
        d = self.dim(e)
        return DIMENSIONLESS if d is LITERAL else d

    def same(self, args, what: str):
        first, first_dim, literal = None, None, False
        for a in args:
            d = self.dim(a)
            if d is LITERAL:
                literal = True
            elif d is not None:
                if first_dim is None:
                    first, first_dim = a, d
                elif d != first_dim:
                    raise _Mismatch(what, first, first_dim, a, d)
        if first_dim is not None:
            return first_dim
        return LITERAL if literal and all(self.dim(a) is LITERAL for a in args) else None

    def _product(self, args):
        total, unknown = DIMENSIONLESS, False
        for a in args:
            d = self.dim(a)
            if d is None:
                unknown = True
            elif d is not LITERAL:
                total = _add(total, d)
        if unknown:
            return None
        return total

    def _power(self, e):
        base, exp = e.args
        db = self.dim(base)
        if exp.is_Number:
            if not _known(db):
                return db if db is None else LITERAL
            return _scaled(db, Fraction(str(exp)) if not exp.is_Float
                           else Fraction(float(exp)).limit_denominator(1000))
        self._dimensionless(exp, "an exponent")
        if _known(db) and db != DIMENSIONLESS:
            raise _Mismatch("a variable exponent needs a dimensionless base", base, db)
        return db if db is None else DIMENSIONLESS

    def _dimensionless(self, a, what: str) -> None:
        d = self.dim(a)
        if _known(d) and d != DIMENSIONLESS:
            raise _Mismatch(f"{what} must be dimensionless", a, d)

    def condition(self, cond) -> None:
        if isinstance(cond, sp.core.relational.Relational):
            self.same(cond.args, "the sides of a relation differ")
        elif isinstance(cond, sp.logic.boolalg.BooleanFunction):
            for c in cond.args:
                self.condition(c)
