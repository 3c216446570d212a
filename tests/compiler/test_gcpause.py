"""After a paused compile, the full collection is run at once only when the objects made
meanwhile would soon trigger one anyway (CPython's rule: more than a quarter of the old
objects); a small compile leaves the collector's schedule alone."""
import gc

from acausal.compiler import gcpause


def _full_collections() -> int:
    return gc.get_stats()[2]["collections"]


def test_full_collection_when_the_young_objects_dominate(monkeypatch):
    monkeypatch.setattr(gcpause, "YOUNG_ENOUGH", 1000)
    gc.collect()
    old = len(gc.get_objects(generation=2))
    was = gc.isenabled()
    gc.disable()
    try:
        kept = [[k] for k in range(old // 4 + 20_000)]      # young, tracked, alive
        before = _full_collections()
        gcpause.collect_after_pause()
        assert _full_collections() == before + 1
        assert len(gc.get_objects(generation=2)) >= len(kept)   # now old: walked once
    finally:
        if was:
            gc.enable()


def test_no_collection_for_a_few_young_objects():
    gc.collect()
    was = gc.isenabled()
    gc.disable()
    try:
        kept = [[k] for k in range(1000)]
        before = _full_collections()
        gcpause.collect_after_pause()
        assert _full_collections() == before and len(kept) == 1000
    finally:
        if was:
            gc.enable()
