"""A variable's or a parameter's symbol: ``Symbol(name, real=True)``."""
from __future__ import annotations

import sympy as sp

__all__ = ["real_symbol"]


def real_symbol(name: str) -> sp.Symbol:
    """The symbol of a model's variable or parameter, named by its dotted path: real, as
    Modelica's Real is."""
    return sp.Symbol(name, real=True)
