"""Units of parameters and variables: Modelica's unit strings, their dimensions and scales.

Declarations write units as Modelica does (specification, section 19.1): factors joined
by ``.``, integer exponents written after the unit, one ``/``, parentheses:
``"N.m/rad"``, ``"kg.m2"``, ``"m3/(s.Pa)"``, ``"1/s"``, ``"rad/s2"``, ``"Ohm"``; SI
prefixes apply (``"kOhm"``, ``"mA"``, ``"MPa"``).  ``^`` and ``*`` are accepted too.

A unit string is translated into an expression of ``sympy.physics.units`` quantities
(the only home-made part is that translation: Modelica's ``.`` and exponent syntax, and
the few names that differ, ``Ohm``, ``degC``, ``rev``, ``min``), and sympy's SI system
gives its dimension and its scale.  The dimension is kept as a vector of exponents of
the SI base dimensions (radian and other angles are dimensionless, as in SI), so that
the compiler's unit check works on small tuples; parsed units are cached.

``sympy.physics.units`` rather than pint: sympy is a dependency already, and pint's
import plus its registry cost 2-3 s here before the first compile (it imports dask when
that is installed).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import NamedTuple

from .component import ModelError

__all__ = ["UnitError", "UnitWarning", "Unit", "UnitCheck", "MODES", "output_tables",
           "parse_unit", "dimension_text", "has_unit", "convert_value", "BASE_DIMENSIONS",
           "DIMENSIONLESS"]

# check_units= of acausal.compile (the check itself: compiler/frontend/unitcheck.py)
MODES = ("error", "warn", "off")


class UnitError(ModelError):
    """An equation whose sides or terms have different dimensions, a function of a
    quantity with a dimension, or a unit string that cannot be read."""


class UnitWarning(UserWarning):
    """A dimensional inconsistency found with ``check_units="warn"``."""


BASE_DIMENSIONS = ("mass", "length", "time", "current", "temperature",
                   "amount_of_substance", "luminous_intensity")
_BASE_SYMBOLS = ("kg", "m", "s", "A", "K", "mol", "cd")
DIMENSIONLESS = (0,) * len(BASE_DIMENSIONS)

# derived SI units by dimension, to name a dimension the way a reader knows it
_NAMED = ("N", "N.m", "W", "V", "Ohm", "Pa", "H", "F", "S", "C", "m/s", "m/s2", "m3/s",
          "kg.m2", "N.s/m", "N.m.s", "N/m", "W/K", "J/K")


class Unit(NamedTuple):
    """A parsed unit: ``dims`` (exponents of BASE_DIMENSIONS), ``scale`` (the factor to
    sympy's canonical units; ratios of scales convert values) and ``offset`` (degC)."""

    text: str
    dims: tuple
    scale: float
    offset: float = 0.0


_TOKEN = re.compile(r"\s*(?:(?P<name>[A-Za-z_%][A-Za-z_]*)(?P<exp>[+-]?\d+)?"
                    r"|(?P<num>\d+(?:\.\d+)?)|(?P<pow>\*\*|\^)(?P<powexp>\(?[+-]?\d+\)?)"
                    r"|(?P<op>[.*/()]))")


def _units_module():
    import sympy.physics.units as u
    return u


@lru_cache(maxsize=None)
def _special() -> dict:
    import sympy as sp
    u = _units_module()
    return {"Ohm": (u.ohm, 0.0), "ohm": (u.ohm, 0.0), "degC": (u.kelvin, 273.15),
            "rev": (2 * sp.pi * u.radian, 0.0), "min": (u.minute, 0.0),
            "rpm": (2 * sp.pi * u.radian / u.minute, 0.0), "l": (u.liter, 0.0),
            "deg": (u.degree, 0.0), "%": (u.percent, 0.0), "1": (sp.Integer(1), 0.0)}


def _quantity(name: str):
    """The sympy expression of one unit name, with an SI prefix if it has one."""
    found = _special().get(name)
    if found is not None:
        return found
    u = _units_module()
    q = getattr(u, name, None)
    if isinstance(q, u.Quantity):
        return q, 0.0
    for prefix in sorted(u.prefixes.PREFIXES, key=len, reverse=True):
        rest = name[len(prefix):]
        if name.startswith(prefix) and rest:
            try:
                base, offset = _quantity(rest)
            except KeyError:
                continue
            if offset:
                continue          # no prefixes on an offset unit
            return u.prefixes.PREFIXES[prefix].scale_factor * base, 0.0
    raise KeyError(name)


def _translate(text: str):
    """The sympy expression of a Modelica unit string, and its offset."""
    pos, out, names, offset = 0, [], [], 0.0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            raise ValueError(f"cannot read {text[pos:]!r}")
        pos = m.end()
        if m["name"]:
            try:
                q, off = _quantity(m["name"])
            except KeyError:
                raise ValueError(f"unknown unit {m['name']!r}") from None
            offset = offset or off
            names.append(q)
            out.append(f"_q[{len(names) - 1}]" + (f"**({m['exp']})" if m["exp"] else ""))
        elif m["num"]:
            out.append(m["num"])
        elif m["pow"]:
            out.append(f"**{m['powexp']}")
        else:
            out.append("*" if m["op"] == "." else m["op"])
    expr_text = "".join(out)
    if not expr_text:
        raise ValueError("empty unit")
    try:   # the text holds only _q[i], numbers and * / ( ) **: nothing else to evaluate
        expr = eval(expr_text, {"__builtins__": {}}, {"_q": names})  # noqa: S307
    except Exception:
        raise ValueError(f"cannot read the unit expression {text!r}") from None
    if offset and len(names) != 1:
        raise ValueError(f"{text!r}: an offset unit (degC) cannot be combined")
    return expr, offset


# The units the library declares, as parse_unit reads them with sympy.physics.units:
# text -> (dims, scale).  A model whose units are all here is checked without importing
# sympy.physics.units (~0.15 s per process, most of the unit check of a small model);
# tests/components/test_units.py compares every entry with the sympy reading.
_KNOWN = {
    '1': ((0, 0, 0, 0, 0, 0, 0), 1.0),
    '1/K': ((0, 0, 0, 0, -1, 0, 0), 1.0),
    '1/s': ((0, 0, -1, 0, 0, 0, 0), 1.0),
    'A': ((0, 0, 0, 1, 0, 0, 0), 1.0),
    'A/V3': ((-3, -6, 9, 4, 0, 0, 0), 1e-09),
    'C': ((0, 0, 1, 1, 0, 0, 0), 1.0),
    'F': ((-1, -2, 4, 2, 0, 0, 0), 0.001),
    'H': ((1, 2, -2, -2, 0, 0, 0), 1000.0),
    'Hz': ((0, 0, -1, 0, 0, 0, 0), 1.0),
    'J': ((1, 2, -2, 0, 0, 0, 0), 1000.0),
    'J/(kg.K)': ((0, 2, -2, 0, -1, 0, 0), 1.0),
    'J/K': ((1, 2, -2, 0, -1, 0, 0), 1000.0),
    'K': ((0, 0, 0, 0, 1, 0, 0), 1.0),
    'K/W': ((-1, -2, 3, 0, 1, 0, 0), 0.001),
    'N': ((1, 1, -2, 0, 0, 0, 0), 1000.0),
    'N.m': ((1, 2, -2, 0, 0, 0, 0), 1000.0),
    'N.m.s': ((1, 2, -1, 0, 0, 0, 0), 1000.0),
    'N.m.s/rad': ((1, 2, -1, 0, 0, 0, 0), 1000.0),
    'N.m/A': ((1, 2, -2, -1, 0, 0, 0), 1000.0),
    'N.m/rad': ((1, 2, -2, 0, 0, 0, 0), 1000.0),
    'N.s/m': ((1, 0, -1, 0, 0, 0, 0), 1000.0),
    'N/m': ((1, 0, -2, 0, 0, 0, 0), 1000.0),
    'N/m2': ((1, -1, -2, 0, 0, 0, 0), 1000.0),
    'Ohm': ((1, 2, -3, -2, 0, 0, 0), 1000.0),
    'Pa': ((1, -1, -2, 0, 0, 0, 0), 1000.0),
    'Pa.s': ((1, -1, -1, 0, 0, 0, 0), 1000.0),
    'S': ((-1, -2, 3, 2, 0, 0, 0), 0.001),
    'V': ((1, 2, -3, -1, 0, 0, 0), 1000.0),
    'W': ((1, 2, -3, 0, 0, 0, 0), 1000.0),
    'W/K': ((1, 2, -3, 0, -1, 0, 0), 1000.0),
    'Wb': ((1, 2, -2, -1, 0, 0, 0), 1000.0),
    'kg': ((1, 0, 0, 0, 0, 0, 0), 1000.0),
    'kg.m': ((1, 1, 0, 0, 0, 0, 0), 1000.0),
    'kg.m2': ((1, 2, 0, 0, 0, 0, 0), 1000.0),
    'kg/(s.Pa)': ((0, 1, 1, 0, 0, 0, 0), 1.0),
    'kg/m3': ((1, -3, 0, 0, 0, 0, 0), 1000.0),
    'kg/s': ((1, 0, -1, 0, 0, 0, 0), 1000.0),
    'm': ((0, 1, 0, 0, 0, 0, 0), 1.0),
    'm/s': ((0, 1, -1, 0, 0, 0, 0), 1.0),
    'm/s2': ((0, 1, -2, 0, 0, 0, 0), 1.0),
    'm2': ((0, 2, 0, 0, 0, 0, 0), 1.0),
    'm2/s': ((0, 2, -1, 0, 0, 0, 0), 1.0),
    'm3': ((0, 3, 0, 0, 0, 0, 0), 1.0),
    'm3/(s.Pa)': ((-1, 4, 1, 0, 0, 0, 0), 0.001),
    'm3/rad': ((0, 3, 0, 0, 0, 0, 0), 1.0),
    'm3/s': ((0, 3, -1, 0, 0, 0, 0), 1.0),
    'rad': ((0, 0, 0, 0, 0, 0, 0), 1.0),
    'rad/m': ((0, -1, 0, 0, 0, 0, 0), 1.0),
    'rad/s': ((0, 0, -1, 0, 0, 0, 0), 1.0),
    'rad/s2': ((0, 0, -2, 0, 0, 0, 0), 1.0),
    's': ((0, 0, 1, 0, 0, 0, 0), 1.0),
}


@lru_cache(maxsize=None)
def parse_unit(text: str) -> Unit | None:
    """The parsed unit, or None for "" (no unit declared: unknown).  Raises UnitError
    for a string that is not a unit."""
    if not isinstance(text, str):
        raise UnitError(f"a unit is a string such as 'N.m/rad', not {text!r}")
    if not text.strip():
        return None
    known = _KNOWN.get(text)
    if known is not None:
        return Unit(text, known[0], known[1], 0.0)
    return _parse_with_sympy(text)


def _parse_with_sympy(text: str) -> Unit:
    try:
        expr, offset = _translate(text.strip())
    except ValueError as err:
        raise UnitError(f"unit {text!r}: {err}") from None
    from sympy.physics.units.systems.si import SI, dimsys_SI
    from sympy.physics.units.dimensions import Dimension
    u = _units_module()
    import sympy as sp
    deps = dimsys_SI.get_dimensional_dependencies(Dimension(SI.get_dimensional_expr(expr)))
    exps = {str(d.name): Fraction(str(e)) for d, e in deps.items()}
    unknown = set(exps) - set(BASE_DIMENSIONS)
    if unknown:
        raise UnitError(f"unit {text!r} has dimensions outside SI ({sorted(unknown)})")
    dims = tuple(_plain(exps.get(b, 0)) for b in BASE_DIMENSIONS)
    scale = sp.sympify(expr).replace(lambda x: isinstance(x, u.Quantity),
                         lambda q: SI.get_quantity_scale_factor(q))
    return Unit(text, dims, float(sp.sympify(scale)), offset)


def _plain(x: Fraction):
    return int(x) if x.denominator == 1 else x


def dimension_text(dims) -> str:
    """``kg.m2/(A.s3)`` for a dimension vector; with its usual name when it has one:
    ``V (kg.m2/(A.s3))``; ``1`` for dimensionless."""
    if dims is None:
        return "unknown"
    num = [_power(s, e) for s, e in zip(_BASE_SYMBOLS, dims) if e > 0]
    den = [_power(s, -e) for s, e in zip(_BASE_SYMBOLS, dims) if e < 0]
    base = ".".join(num) or "1"
    if den:
        base += "/" + (den[0] if len(den) == 1 else f"({'.'.join(den)})")
    name = _named().get(tuple(dims))
    return f"{name} ({base})" if name and name != base else base


def _power(symbol: str, e) -> str:
    return symbol if e == 1 else f"{symbol}{e}" if isinstance(e, int) else f"{symbol}^({e})"


@lru_cache(maxsize=None)
def _named() -> dict:
    out = {}
    for text in _NAMED:
        out.setdefault(parse_unit(text).dims, text)
    return out


_VALUE = re.compile(r"^\s*(?P<num>[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(?P<unit>.*)$")


def has_unit(value) -> bool:
    """True for a string that is a number followed by a unit (``"2 kOhm"``); other
    strings are no values (the caller's type check says so)."""
    if not isinstance(value, str):
        return False
    m = _VALUE.match(value)
    return m is not None and bool(m["unit"].strip())


def convert_value(value: str, declared: str, what: str, name: str | None = None) -> float:
    """``"2 kOhm"`` given for a parameter declared in ``"Ohm"``: 2000.0.  Raises
    ValueError (naming ``what``) for a string that is not a number with a unit, a unit of
    another dimension, or a declaration without a unit (``name``: the declaration's, by
    default the last word of ``what``)."""
    name = name or what.split()[-1]
    m = _VALUE.match(value)
    if m is None:
        raise ValueError(f"{what} = {value!r} is not a real number (nor a number with a "
                         "unit, such as '2 kOhm')")
    number = float(m["num"])
    if not m["unit"].strip():
        return number
    if not declared:
        raise ValueError(f"{what} = {value!r} gives a unit, but {name} declares none "
                         "to convert it to")
    try:
        given, target = parse_unit(m["unit"]), parse_unit(declared)
    except UnitError as err:
        raise ValueError(f"{what} = {value!r}: {err}") from None
    if given.dims != target.dims:
        raise ValueError(f"{what} = {value!r} has dimension {dimension_text(given.dims)}, "
                         f"but {name} is declared in {declared!r} "
                         f"({dimension_text(target.dims)})")
    si = (number + given.offset) * given.scale
    return si / target.scale - target.offset


@dataclass
class UnitCheck:
    """What the compiler's unit check found (kept here, without sympy, so that a
    compiled model loads without it): ``checked`` equations, ``mismatches`` (messages),
    ``unitless_variables``/``unitless_parameters`` (names declared without a unit),
    ``seconds`` spent."""

    mode: str = "off"
    checked: int = 0
    mismatches: list = field(default_factory=list)
    unitless_variables: list = field(default_factory=list)
    unitless_parameters: list = field(default_factory=list)
    seconds: float = 0.0

    def as_dict(self) -> dict:
        return dict(self.__dict__)

    def summary(self) -> str:
        if self.mode == "off":
            return "units: not checked (check_units='off')"
        text = (f"units: {self.checked} equations checked, "
                f"{len(self.mismatches)} inconsistent")
        if self.unitless_variables:
            text += (f"; {len(self.unitless_variables)} variable(s) without a unit (any "
                     f"dimension): {', '.join(self.unitless_variables)}")
        return text


# -- the units and descriptions of a result's names ------------------------------------
def output_tables(units: dict, descriptions: dict, names) -> tuple[dict, dict]:
    """(unit, description) by each of ``names`` (a model's outputs and parameters), from
    the declared ones by dotted name; ``der(x)`` has x's unit per second."""
    return (with_derivatives({n: units.get(n, "") for n in names
                              if not n.startswith("der(")}, names),
            {n: descriptions.get(n, "") if not n.startswith("der(") else
             f"derivative of {n[4:-1]}" for n in names})


def with_derivatives(units: dict, names) -> dict:
    """``units`` completed with ``der(x)`` for each such name: x's unit per second."""
    out = dict(units)
    for n in names:
        if n.startswith("der(") and n.endswith(")") and n not in out:
            out[n] = per_second(units.get(n[4:-1], ""))
    return out


def per_second(unit: str) -> str:
    """A unit divided by seconds, in Modelica's unit syntax ("m/s" -> "m/s2")."""
    if not unit:
        return "1/s"
    if unit.endswith("/s"):
        return unit + "2"
    return f"{unit}/s" if "/" not in unit else f"({unit})/s"
