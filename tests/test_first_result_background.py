"""The first run in a new process with an empty compile cache: what it waits for.

The compiled step loop's library (``solvers/cbdf*.c``, about a second and a half of gcc)
is built in a process of its own that the first run starts when it ends (or a long
compile while it runs): the first run takes the Python loop, the process ends without
waiting, and the next process finds the library.
A build that is interrupted leaves neither a library nor its temporary files, and the
numpy backend's first run of a small model needs no scipy.linalg (nor its next, in the
compiled loop).  Every run is checked
against the RC circuit's closed form v_C = V (1 - exp(-t/RC)); no time is asserted
(benchmarks/first_result.py measures them).
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time

import pytest

from acausal.compiler.backends.cbackend import compiler_available
from acausal.solvers import cbdf_build
from acausal.tests.rc_script import RC_CLASS

needs_cc = pytest.mark.skipif(compiler_available() is None, reason="no C compiler")

RC_SCRIPT = '''
import json, math, sys
from acausal.solvers import cbdf_build
''' + RC_CLASS + '''

compiled = ac.compile(RC(), backend=sys.argv[1])
res = ac.simulate(compiled, t_end=5.0e-3, rtol=1e-6, step_loop=sys.argv[2])
exact = 1.0 - math.exp(-5.0)
print(json.dumps({"error": abs(float(res["C1.v"][-1]) - exact) / exact,
                  "backend": compiled.backend, "step_loop": res.stats["step_loop"],
                  "builder": getattr(cbdf_build._builder, "pid", None),
                  "scipy.linalg": "scipy.linalg" in sys.modules}))
'''


def _run(script, cache, backend="auto", step_loop="auto") -> dict:
    env = dict(os.environ, ACAUSAL_CACHE=str(cache))
    out = subprocess.run([sys.executable, str(script), backend, step_loop], capture_output=True,
                         text=True, check=True, env=env, timeout=300).stdout
    return json.loads(out.strip().splitlines()[-1])


def _wait_gone(path, pid=None, timeout=240.0) -> None:
    """Wait until ``path`` is gone and, given, process ``pid`` has ended."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        alive = False
        if pid is not None:
            try:
                os.kill(pid, 0)
                alive = True
            except ProcessLookupError:
                pass
        if not alive and not os.path.exists(path):
            return
        time.sleep(0.05)
    raise AssertionError(f"{path} still there after {timeout} s")


@pytest.fixture
def script(tmp_path):
    path = tmp_path / "rc_first.py"
    path.write_text(RC_SCRIPT)
    return path


@needs_cc
def test_the_first_run_takes_the_python_loop_and_the_next_the_compiled_one(script,
                                                                            tmp_path):
    cache = tmp_path / "cache"
    first = _run(script, cache)
    assert first["error"] < 1e-4
    assert first["backend"] == "c" and first["step_loop"] == "python"
    assert first["builder"] is not None and not first["scipy.linalg"]
    # the first process has ended; its build goes on, then leaves the library
    _wait_gone(cache / cbdf_build._MARKER, first["builder"])
    second = _run(script, cache)
    assert second["error"] < 1e-4
    assert second["step_loop"] == "c" and second["builder"] is None


@needs_cc
def test_asking_for_the_compiled_loop_builds_it_or_waits_for_its_build(script, tmp_path):
    cache = tmp_path / "cache"
    found = _run(script, cache, backend="c", step_loop="c")
    assert found["error"] < 1e-4 and found["step_loop"] == "c"
    # a build started in the background is waited for, not repeated
    probe = ("from acausal.solvers import cbdf, cbdf_build as b; import json; "
             "b.build_in_background(); pid = b._builder.pid; lib = cbdf.library(); "
             "print(json.dumps([pid, b._builder.returncode, lib is not None]))")
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "other"))
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         check=True, env=env, timeout=300).stdout
    pid, returncode, loaded = json.loads(out.strip().splitlines()[-1])
    assert pid is not None and returncode == 0 and loaded
    assert not (tmp_path / "other" / cbdf_build._MARKER).exists()


@needs_cc
def test_a_long_compile_starts_the_build_and_a_short_one_does_not(tmp_path):
    probe = """
import json, time
from acausal.solvers import cbdf_build
with cbdf_build.build_if_long(30.0):
    pass
short = cbdf_build._builder
with cbdf_build.build_if_long(0.01):
    time.sleep(2.0)          # a compile far longer than the delay
print(json.dumps([short is None, cbdf_build._builder is not None]))
"""
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "cache"))
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         check=True, env=env, timeout=300).stdout
    assert json.loads(out.strip().splitlines()[-1]) == [True, True]


@needs_cc
def test_an_interrupted_build_leaves_nothing_and_the_next_one_works(tmp_path,
                                                                    monkeypatch):
    cache = tmp_path / "cache"
    monkeypatch.setenv("ACAUSAL_CACHE", str(cache))
    proc = cbdf_build._spawn_builder()
    marker = cache / cbdf_build._MARKER
    end = time.monotonic() + 120
    while not marker.exists() and proc.poll() is None and time.monotonic() < end:
        time.sleep(0.02)
    assert marker.exists(), "the build did not start"
    time.sleep(0.3)                      # into the compiler's run
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=120) == 128 + signal.SIGTERM      # ended by the signal
    # no library, no marker, no temporary directory: nothing a later process could load
    assert sorted(os.listdir(cache)) in ([], ["models"])
    probe = ("from acausal.solvers import cbdf; import json; "
             "print(json.dumps(cbdf.library(cached_only=True) is not None))")
    env = dict(os.environ)

    def built() -> bool:
        out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                             check=True, env=env, timeout=120).stdout
        return json.loads(out.strip().splitlines()[-1])

    assert not built()
    proc = cbdf_build._spawn_builder()
    assert proc.wait(timeout=240) == 0
    assert not marker.exists()
    assert built()


def test_the_numpy_backend_runs_a_small_model_without_scipy_linalg(script, tmp_path):
    cache = tmp_path / "cache"
    first = _run(script, cache, backend="numpy")
    assert first["error"] < 1e-4 and first["backend"] == "numpy"
    assert first["step_loop"] == "python" and not first["scipy.linalg"]
    if compiler_available() is None:
        assert first["builder"] is None
        return
    # its model runs in the compiled loop too (solvers/cbdf_callbacks.py), once built
    assert first["builder"] is not None
    _wait_gone(cache / cbdf_build._MARKER, first["builder"])
    second = _run(script, cache, backend="numpy")
    assert second["error"] < 1e-4 and second["step_loop"] == "c"
    assert not second["scipy.linalg"] and second["builder"] is None


def test_a_marker_whose_build_was_killed_does_not_hold_back_the_next(tmp_path):
    """The marker holds the builder's process number: a build killed without cleaning
    up (SIGKILL) leaves a marker that the next process recognises at once."""
    marker = tmp_path / cbdf_build._MARKER
    marker.write_text(str(os.getpid()))
    assert cbdf_build._building(str(marker))
    ended = subprocess.Popen([sys.executable, "-c", "pass"])
    ended.wait()
    marker.write_text(str(ended.pid))
    assert not cbdf_build._building(str(marker))
    marker.write_text("")                  # created, its number not written yet
    assert cbdf_build._building(str(marker))
    os.utime(marker, (time.time() - 2 * cbdf_build._MARKER_AGE,) * 2)
    assert not cbdf_build._building(str(marker))
