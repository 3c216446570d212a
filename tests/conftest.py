"""The suite's own compile cache: a temporary directory for the whole session, so no test
reads or fills the user's ``~/.cache/acausal`` and every session starts cold, as CI does.

``ACAUSAL_TEST_NO_FORK=1`` runs the suite as on a platform without ``fork`` (macOS and
Windows start processes by spawning): ``os.fork`` is removed from this process and
multiprocessing's start method is ``spawn``, so any code of acausal that would fork
fails the tests that reach it (``.ci/run`` runs the compile, simulate, sweep and cache
tests so)."""
import multiprocessing
import os
import shutil
import tempfile

_CACHE = tempfile.mkdtemp(prefix="acausal-test-cache-")
os.environ["ACAUSAL_CACHE"] = _CACHE

if os.environ.get("ACAUSAL_TEST_NO_FORK", "") not in ("", "0"):
    multiprocessing.set_start_method("spawn", force=True)
    for _name in ("fork", "forkpty"):
        if hasattr(os, _name):
            delattr(os, _name)


def pytest_sessionfinish(session, exitstatus):
    shutil.rmtree(_CACHE, ignore_errors=True)
