"""Which equation failed: a generated function that raised, traced back to a row; and
the outputs that are not finite at an output point.

The generated residual is one Python function; when it raises (``sqrt`` of a negative
start value, a division by zero), the traceback's line in the generated source says which
statement failed: an ``out[k] = ...`` line is row k, an assignment ``_aK = ...`` is the
variable the BLT computes there, and a common subexpression ``_cK = ...`` is charged to
the first row or assignment that uses it.

:class:`OutputCheck` checks, at every output point, the outputs the integrator does not
see (those :func:`acausal.compiler.backends.domains.output_checks` lists): one that is
NaN or inf there ends the run, naming the variable, its equation and the time (runtime
contract item 11).
"""
from __future__ import annotations

import re
import traceback

import numpy as np

__all__ = ["DOMAIN_ERRORS", "failing_statement", "OutputCheck"]

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


class OutputCheck:
    """``check(t, z, m, every=False)``: None, or a sentence naming the first output of
    the model's ``output_checks`` that is not finite at (t, z) in the discrete state
    ``m`` (the model's own when None), with its equation and the time; ``every``: any
    output (the first point of a run, where what depends on parameters alone is found).
    ``every_point``: whether some outputs need the check at every point."""

    def __init__(self, model, checks):
        self.model = model
        self.columns = np.array([c[0] for c in checks], dtype=np.int64)
        self.checks = checks
        self.every_point = bool(checks)

    @classmethod
    def of(cls, model):
        """The check of ``model``, or None when it has no outputs of its own."""
        if model.code.expand is None:
            return None
        return cls(model, model.meta.get("output_checks") or [])

    def __call__(self, t, z, m=None, every=False):
        model = self.model
        if not (every or self.every_point):
            return None
        saved = None
        if m is not None:
            saved = model.discrete_state()
            model.set_discrete_state(m)
        seen = len(model.evaluation_errors)
        try:
            values = model.expand(t, z)
        finally:
            if saved is not None:
                model.set_discrete_state(saved)
        if every:
            bad = np.flatnonzero(~np.isfinite(values))
        else:
            bad = self.columns[~np.isfinite(values[self.columns])]
        if not len(bad):
            return None
        why = model.evaluation_errors[seen:]
        del model.evaluation_errors[seen:]      # said here, with the variable
        # the checked outputs that are not finite, in the order they are computed
        found = [j for j, c in enumerate(self.columns) if c in set(bad.tolist())]
        if why and found:
            # the Python code raised (every output is NaN then): the statement it names
            m = re.match(r"computing (.+?) failed", why[0])
            found = [j for j in found if m and self.checks[j][1] == m.group(1)] or found
        tail = f"; {why[0]}" if why else ""
        if not found:         # an output that is not checked at every point
            return f"{self._name_of(bad[0])} = {values[bad[0]]} at t = {t:.10g}{tail}"
        column, name, equation = self.checks[found[0]]
        return f"{name} = {values[column]} at t = {t:.10g} (equation {equation}){tail}"

    def _name_of(self, column) -> str:
        """The output names of a column of ``expand`` (aliases too, a few)."""
        names = sorted(n for n, (sign, k) in self.model.outputs.items()
                       if sign is not None and k == column)
        return " = ".join(names[:3]) or f"output {column}"
