"""The front passes run with Python's cyclic garbage collector paused.

Flattening, alias elimination, the cache key and the unit check create hundreds of
thousands of small sympy objects, almost none of them in reference cycles (they are
freed by reference counting).  The collector is nevertheless triggered every few hundred
allocations and then walks the young objects, and on large models about a third of
these passes' time went to it.  A pass wrapped here disables it while it runs and
restores it afterwards; garbage in cycles made meanwhile is collected at the next
collection after the pass, as it would have been a little later anyway.

The objects a paused pass keeps (the flat model) are still young when the collector
is enabled again, so the first collection after it walks them once: part of the time
saved here is spent by the next pass.  Pausing the collector around a whole compile
(the caller wrapping its entry point) saves that too.
"""
from __future__ import annotations

import functools
import gc

__all__ = ["gc_paused"]


def gc_paused(func):
    """``func`` with the cyclic garbage collector disabled while it runs (re-enabled
    afterwards only if it was enabled before: nested passes and callers that disabled it
    themselves keep their setting)."""
    @functools.wraps(func)
    def run(*args, **kwargs):
        if not gc.isenabled():
            return func(*args, **kwargs)
        gc.disable()
        try:
            return func(*args, **kwargs)
        finally:
            gc.enable()
    return run
