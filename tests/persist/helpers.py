"""Shared checks of the persistence tests."""
import os
import subprocess
import sys

import numpy as np


def assert_same_run(a, b, rel=1e-12):
    """Two results of the same model agree on every variable to ``rel`` of its own size."""
    assert a.success and b.success
    assert np.array_equal(a.t, b.t)
    for name in a.compiled.outputs:
        x, y = np.asarray(a[name]), np.asarray(b[name])
        scale = max(float(np.max(np.abs(x))), np.finfo(float).tiny)
        assert np.max(np.abs(x - y)) <= rel * scale, name


def run_python(code: str, cache_dir, timeout=300) -> str:
    """Run ``code`` in a fresh interpreter with the compile cache in ``cache_dir``;
    returns its standard output (fails the test on a non-zero exit)."""
    env = dict(os.environ, ACAUSAL_CACHE=str(cache_dir))
    env.pop("ACAUSAL_COMPILE_CACHE", None)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=env, timeout=timeout)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return proc.stdout
