"""The compiled step loop's state as Python sees it: ``cbdf_state`` read from ``cbdf.h``.

The struct is declared once, in C (``cbdf.h``, one field a line with its comment); this
module reads that declaration and makes the :class:`ctypes.Structure` of it, so the two
views cannot drift apart by an edit to one of them.  ctypes lays the fields out by the
platform's C rules, as the compiler does; ``tests/solvers/test_cbdf_layout.py`` checks
the offset of every field and the size against the compiler's own ``offsetof``.
"""
from __future__ import annotations

import ctypes
import os
import re

__all__ = ["CbdfState", "FIELDS", "parse"]

_HEADER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cbdf.h")
_TYPES = {"double": ctypes.c_double, "int64_t": ctypes.c_int64}
_POINTERS = {"double": ctypes.POINTER(ctypes.c_double),
             "int64_t": ctypes.POINTER(ctypes.c_int64), "void": ctypes.c_void_p}
_FIELD = re.compile(r"^\s*(const\s+)?(double|int64_t|void)\s*(\*?)\s*(\w+)"
                    r"(?:\[(\w+)\])?\s*;\s*/\*.*\*/\s*$")


def parse(text: str) -> list:
    """``[(name, C type text, ctypes type)]`` of the fields of ``struct cbdf_state`` in
    the header's text, in order; ValueError at a line of the struct it cannot read."""
    constants = dict(re.findall(r"#define\s+(\w+)\s+(\d+)", text))
    body = text[text.index("typedef struct cbdf_state {") + 27:text.index("} cbdf_state;")]
    fields = []
    for line in body.splitlines():
        if not line.strip() or line.strip().startswith("/*"):
            continue
        m = _FIELD.match(line)
        if m is None:
            raise ValueError(f"cbdf.h: cannot read the field {line.strip()!r}")
        const, base, star, name, size = m.groups()
        kind = _POINTERS[base] if star else _TYPES[base]
        if size is not None:
            kind = kind * int(constants.get(size, size))
        ctext = f"{const or ''}{base} {star}".replace(" *", " *").strip()
        fields.append((name, ctext, kind))
    return fields


with open(_HEADER) as _f:
    FIELDS = parse(_f.read())


class CbdfState(ctypes.Structure):
    """``cbdf_state`` of ``cbdf.h`` (every field's meaning is in its comment there)."""

    _fields_ = [(name, kind) for name, _, kind in FIELDS]
