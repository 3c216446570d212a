"""Texts of bounded length for errors, records and reprs.

A message names what it is about; it does not print a model.  An equation of a few
thousand characters (a friction law's piecewise definition) is shortened to its first
characters and "..."; a list of names (the unclassified components of a large model) to
its first few and "and N more".  The whole texts stay in the data (``Event.relations``,
``EnergyBalance.roles``, the index report): only what is printed is bounded.
"""
from __future__ import annotations

__all__ = ["shortened", "listed", "TEXT", "ITEMS"]

TEXT = 160          # characters of one equation or relation in a message
ITEMS = 8           # names of a list in a message


def shortened(text, limit: int = TEXT) -> str:
    """``text`` as one line of at most ``limit`` characters (cut with "...")."""
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[:max(limit - 3, 1)].rstrip() + "..."


def listed(items, n: int = ITEMS, limit: int = TEXT) -> str:
    """``a, b, c and 5 more``: the first ``n`` items (each :func:`shortened`)."""
    items = [shortened(x, limit) for x in items]
    head = ", ".join(items[:n])
    return head + (f" and {len(items) - n} more" if len(items) > n else "")
