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

What a large compile keeps (the generated code, the report, the model's expressions)
is then walked by the collector three times once it runs again: by the young
collection, by the middle one its survivors move to, and by the full collection that
follows when they outnumber a quarter of the old objects (CPython's rule); a
100 000-equation model kept about 4 million objects, 4-6 s of walks.
:func:`collect_after_pause` does that full collection at once, one walk.

When what the compile keeps is to be frozen right after it (``gc.freeze``: the first
compile of a script, :func:`acausal.simulation.compile`), even that walk is saved: the
caller collects before the compile, while the heap is small, keeps the collector paused
(:func:`paused`) until the freeze, and the compile's own garbage cycles (a few hundred
objects of any model's compile: recursive closures, local classes of the modules it
imports) are frozen with the rest, once per process.  On the 18 000-equation RLC
ladder the walk took 0.4-0.6 s.
"""
from __future__ import annotations

import contextlib
import functools
import gc

__all__ = ["gc_paused", "paused", "collect_after_pause"]


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


@contextlib.contextmanager
def paused():
    """The collector disabled within (and then restored as it was)."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()


# below this many new objects the collector's own schedule costs little
YOUNG_ENOUGH = 100_000


def collect_after_pause() -> None:
    """A full collection now, when the objects made while the collector was paused are
    so many that CPython's schedule would soon run one anyway (more than a quarter of
    the old objects: then its young and middle collections walking them first are
    saved); else nothing."""
    global collected
    young = gc.get_count()[0]
    if young > YOUNG_ENOUGH and 4 * young > len(gc.get_objects(generation=2)):
        gc.collect()
        collected = True


#: whether :func:`collect_after_pause` has collected since the flag was last cleared
#: (acausal.simulation.compile then need not collect again before freezing)
collected = False
