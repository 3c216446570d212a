"""The Port base class and the signal-port arithmetic.

A port declares across variables (equal at a node) and through variables (summing to
zero at a node, positive into the component); ``effort``/``flow`` name the pair whose
product is the power into the component (ARCHITECTURE, connection semantics).
"""
from __future__ import annotations

from ..components.component import Port

__all__ = ["Port", "SignalPort"]


class SignalPort(Port):
    """A causal signal port: one value, usable directly in equations (``self.k*self.u``)."""

    def _sympy_(self):
        return self.signal

    def __add__(self, o): return self.signal + _v(o)
    def __radd__(self, o): return _v(o) + self.signal
    def __sub__(self, o): return self.signal - _v(o)
    def __rsub__(self, o): return _v(o) - self.signal
    def __mul__(self, o): return self.signal * _v(o)
    def __rmul__(self, o): return _v(o) * self.signal
    def __truediv__(self, o): return self.signal / _v(o)
    def __rtruediv__(self, o): return _v(o) / self.signal
    def __pow__(self, o): return self.signal ** _v(o)
    def __neg__(self): return -self.signal
    def __pos__(self): return self.signal
    def __lt__(self, o): return self.signal < _v(o)
    def __le__(self, o): return self.signal <= _v(o)
    def __gt__(self, o): return self.signal > _v(o)
    def __ge__(self, o): return self.signal >= _v(o)
    # Boolean signals: &, |, ^ and ~ are and, or, xor and not (Python's own ``and``,
    # ``or`` and ``not`` cannot be given a meaning for symbols)
    def __and__(self, o): return _logical(self) & _logical(o)
    def __rand__(self, o): return _logical(o) & _logical(self)
    def __or__(self, o): return _logical(self) | _logical(o)
    def __ror__(self, o): return _logical(o) | _logical(self)
    def __xor__(self, o): return _logical(self) ^ _logical(o)
    def __rxor__(self, o): return _logical(o) ^ _logical(self)
    def __invert__(self): return ~_logical(self)
    __hash__ = Port.__hash__


def _v(o):
    return o._sympy_() if isinstance(o, SignalPort) else o


def _logical(o):
    """A signal or value as a condition (a Boolean's symbol as ``y > 1/2``)."""
    from ..components.logic import as_condition   # sympy: first at a condition
    return as_condition(_v(o))
