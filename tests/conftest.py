"""The suite's own compile cache: a temporary directory for the whole session, so no test
reads or fills the user's ``~/.cache/acausal`` and every session starts cold, as CI does."""
import os
import shutil
import tempfile

_CACHE = tempfile.mkdtemp(prefix="acausal-test-cache-")
os.environ["ACAUSAL_CACHE"] = _CACHE


def pytest_sessionfinish(session, exitstatus):
    shutil.rmtree(_CACHE, ignore_errors=True)
