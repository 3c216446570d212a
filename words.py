"""Texts of bounded length for errors, records and reprs.

A message names what it is about; it does not print a model.  An equation of a few
thousand characters (a friction law's piecewise definition) is shortened to its first
characters and "..."; a list of names (the unclassified components of a large model) to
its first few and "and N more".  The whole texts stay in the data (``Event.relations``,
``EnergyBalance.roles``, the index report): only what is printed is bounded.
"""
from __future__ import annotations

import difflib
import re

__all__ = ["shortened", "listed", "suggestion", "zero_causes", "TEXT", "ITEMS"]

TEXT = 160          # characters of one equation or relation in a message
ITEMS = 8           # names of a list in a message


def shortened(text, limit: int = TEXT) -> str:
    """``text`` as one line of at most ``limit`` characters (cut with "..."); a trailing
    ``[component]`` tag, which says where the text comes from, is kept."""
    text = " ".join(str(text).split())
    if len(text) <= limit:
        return text
    k = text.rfind(" [")
    tag = text[k:] if text.endswith("]") and 0 < k and len(text) - k <= limit // 2 else ""
    return text[:max(limit - 3 - len(tag), 1)].rstrip() + "..." + tag


def listed(items, n: int = ITEMS, limit: int = TEXT) -> str:
    """``a, b, c and 5 more``: the first ``n`` items (each :func:`shortened`)."""
    items = [shortened(x, limit) for x in items]
    head = ", ".join(items[:n])
    return head + (f" and {len(items) - n} more" if len(items) > n else "")


def suggestion(name: str, known) -> str:
    """`` (did you mean 'R'?)`` for the closest known name, or ''."""
    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.5)
    if not close:
        lowered = {k.lower(): k for k in known}
        if name.lower() in lowered:
            close = [lowered[name.lower()]]
    return f" (did you mean '{close[0]}'?)" if close else ""


def zero_causes(zeros, components, flat=None) -> str:
    """A sentence naming the parameters given exactly 0 (structural zeros: the terms
    they multiply were removed, derivatives with them) of the ``components`` an error
    is about, or of the model when none of those has one; "" when there are none.
    With the flat model, only those that multiplied a derivative (a state lost: what
    changes the structure), not a temperature coefficient left at its default 0."""
    if flat is not None:
        zeros = [z for z in zeros if _multiplies_derivative(flat, z)]
    if not zeros:
        return ""
    places = {c for c in components if c}
    near = [z for z in zeros if z.rsplit(".", 1)[0] in places
            or any(z.startswith(c + ".") for c in places)]
    named = near or list(zeros)
    where = "of these components " if near else ""
    return (f"the parameters {where}given 0 are structural zeros, which removed the terms "
            f"they multiply (a derivative with them): {listed(named)}; give them a "
            "non-zero value if that is not meant")


def _multiplies_derivative(flat, zero: str) -> bool:
    """Whether the parameter ``zero`` stands in an equation of its component that has a
    derivative (as written: ``V/beta*der(p) = port.q``)."""
    component, _, local = zero.rpartition(".")
    # named in full (vol.V, as flattening prints it) or by its own name (V)
    word = re.compile(rf"(?<![\w.])({re.escape(zero)}|{re.escape(local)})(?![\w(])")
    for e in flat.equations:
        if e.component == component:
            text = str(e.source)
            if "der(" in text and word.search(text):
                return True
    return False
