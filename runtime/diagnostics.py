"""Which equation failed: a generated function that raised, traced back to a row.

The generated residual is one Python function; when it raises (``sqrt`` of a negative
start value, a division by zero), the traceback's line in the generated source says which
statement failed: an ``out[k] = ...`` line is row k, an assignment ``_aK = ...`` is the
variable the BLT computes there, and a common subexpression ``_cK = ...`` is charged to
the first row or assignment that uses it.
"""
from __future__ import annotations

import re
import traceback

__all__ = ["DOMAIN_ERRORS", "failing_statement"]

_GENERATED = "<acausal generated>"


# what generated code raises outside a function's domain (sqrt(-1), 1/0, exp(1e3))
DOMAIN_ERRORS = (ValueError, ZeroDivisionError, OverflowError, TypeError)


def failing_statement(source: str, exc: BaseException, row_names, assigned_names):
    """A phrase naming what failed (``"evaluating equation 'R1.v = R1.R*R1.i' ..."``,
    ``"computing der(x)"``), or None."""
    line_no = None
    for frame in traceback.extract_tb(exc.__traceback__):
        if frame.filename == _GENERATED:
            line_no = frame.lineno
    if line_no is None:
        return None
    lines = source.splitlines()
    text = lines[line_no - 1].strip() if 0 < line_no <= len(lines) else ""
    m = re.match(r"out\[(\d+)\] = ", text)
    if m:
        return _row(int(m.group(1)), row_names)
    m = re.match(r"(_a(\d+)) = ", text)
    if m:
        k = int(m.group(2))
        name = assigned_names[k] if k < len(assigned_names) else m.group(1)
        return f"computing {name}"
    m = re.match(r"(_c\d+) = ", text)
    if m:
        sym = m.group(1)
        for later in lines[line_no:]:          # the rest of the same function
            if later.startswith("def "):
                break
            hit = re.match(r"\s*out\[(\d+)\] = .*\b" + sym + r"\b", later)
            if hit:
                return _row(int(hit.group(1)), row_names)
            hit = re.match(r"\s*_a(\d+) = .*\b" + sym + r"\b", later)
            if hit:
                k = int(hit.group(1))
                return f"computing {assigned_names[k] if k < len(assigned_names) else f'_a{k}'}"
    return None


def _row(k, row_names):
    name = row_names[k] if k < len(row_names) else f"row {k}"
    return f"evaluating equation {name}"
