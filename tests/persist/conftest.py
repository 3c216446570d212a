"""Fixtures of the persistence tests."""
import pytest


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    """An empty compile cache of this test's own, with the cache switches at their
    defaults."""
    path = tmp_path / "cache"
    monkeypatch.setenv("ACAUSAL_CACHE", str(path))
    monkeypatch.delenv("ACAUSAL_COMPILE_CACHE", raising=False)
    monkeypatch.delenv("ACAUSAL_CACHE_SIZE", raising=False)
    return path
