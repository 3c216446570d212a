"""What to write instead, when a component's equations() fails on a model variable.

Equations are built from sympy symbols, so the Python idioms of numerical code fail on
them with messages about sympy or numpy internals.  :func:`advice` recognises the three
usual ones and names acausal's notation.
"""
from __future__ import annotations

__all__ = ["advice", "failed_reading"]


def advice(err: Exception) -> str:
    """A sentence for the error ``equations()`` raised, or '' if it is not a known idiom."""
    text = str(err)
    if "truth value of Relational" in text:
        # `if v > 0:`, `and`/`or`, np.where, max() of a variable: a branch needs a value
        return ("; a Python if, and/or, max/min or np.where cannot branch on a model "
                "variable: write ac.if_else(condition, a, b) (an event), ac.max, ac.min")
    if "ufunc" in text or "has no callable" in text:
        return ("; numpy functions take numbers, not model variables: use ac.sin, ac.cos, "
                "ac.exp, ac.log, ac.sqrt, ac.tanh, ... in equations")
    if "convert expression to float" in text:
        return ("; the math module takes numbers, not model variables: use ac.sin, "
                "ac.exp, ac.sqrt, ... in equations")
    return ""


def failed_reading(method: str, where: str, err: Exception) -> str:
    """The message for an exception raised by a component's ``method`` (equations,
    initial_equations, ...), with :func:`advice`."""
    return (f"while reading the {method.replace('_', ' ')} of {where}: "
            f"{type(err).__name__}: {err}{advice(err)}")
