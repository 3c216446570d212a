"""Work done beside the compile passes in a forked child (acausal.compiler.sidejobs): the
result is the one the process would compute itself, however the child ends, and a
compile that forks gives the same model, report and cache entry as one that does not.

The reference of every check is the same work run in the process itself.
"""
import os
import threading
import time

import pytest

import acausal as ac
from acausal.compiler.cache import entries as store
from acausal.compiler import pipeline, sidejobs
from acausal.compiler.index.reduction import as_written

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="no fork on this system")

PARENT = os.getpid()


def _work(n):
    return {"pid_was_parent": os.getpid() == PARENT, "squares": [k * k for k in range(n)]}


def test_the_child_returns_what_the_process_would():
    job = sidejobs.Beside(_work, 1000)
    assert job.running
    out = job.result()
    assert job.forked and not job.running
    assert out["squares"] == [k * k for k in range(1000)]
    assert out["pid_was_parent"] is False        # it did run in the child
    inline = sidejobs.Beside(_work, 1000, fork=False)
    assert not inline.running
    assert inline.result() == {"pid_was_parent": True, "squares": out["squares"]}
    assert not inline.forked


def _fails_in_the_child(how):
    if os.getpid() != PARENT:
        if how == "raise":
            raise ValueError("only in the child")
        if how == "exit":
            os._exit(3)
        if how == "unpicklable":
            return lambda: None
    return "done by the parent"


@pytest.mark.parametrize("how", ["raise", "exit", "unpicklable"])
def test_a_child_that_ends_without_a_result_leaves_the_work_to_the_parent(how):
    job = sidejobs.Beside(_fails_in_the_child, how)
    assert job.result() == "done by the parent"
    assert not job.forked


def _hangs_in_the_child():
    if os.getpid() != PARENT:
        time.sleep(3600)
    return "done by the parent"


def test_a_child_that_does_not_finish_is_stopped_and_its_work_done_here(monkeypatch):
    monkeypatch.setattr(sidejobs, "PATIENCE", (0.3, 0.0))
    job = sidejobs.Beside(_hangs_in_the_child)
    pid = job.pid
    # the child sleeps an hour: an answer at all means the parent stopped waiting
    assert job.result() == "done by the parent"
    assert not job.forked
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)       # stopped and reaped
    monkeypatch.setattr(sidejobs, "STORE_PATIENCE", 0.3)
    assert sidejobs.detach(_hangs_in_the_child)
    (pid, _), = sidejobs._detached
    sidejobs.settle()
    assert not sidejobs._detached
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)


def _raises():
    raise KeyError("the same error in both")


def test_an_error_of_the_work_reaches_the_caller_with_its_type():
    with pytest.raises(KeyError, match="the same error in both"):
        sidejobs.Beside(_raises).result()


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="reads /proc")
def test_a_child_with_a_large_result_ends_before_it_is_read():
    """A result larger than a pipe's default 64 kB (the index as written of a large
    model) fits the widened pipe: the child ends as soon as it has sent it, not when
    the parent reads it (a child that lives on makes every page the parent writes a
    copy), and the result is whole."""
    job = sidejobs.Beside(_work, 30_000)           # some 200 kB pickled
    deadline = time.monotonic() + 20
    state = ""
    while time.monotonic() < deadline:
        with open(f"/proc/{job.pid}/status") as f:
            state = next(line for line in f if line.startswith("State:"))
        if "Z" in state.split()[1]:                # ended, not yet reaped
            break
        time.sleep(0.05)
    assert "Z" in state.split()[1], state
    out = job.result()
    assert job.forked and out["squares"] == [k * k for k in range(30_000)]


def _slow(seconds):
    time.sleep(seconds)
    return "slept"


def test_ready_says_whether_the_result_would_wait():
    job = sidejobs.Beside(_slow, 0.5)
    assert not job.ready()                 # still sleeping
    deadline = time.monotonic() + 20
    while not job.ready() and time.monotonic() < deadline:
        time.sleep(0.02)
    assert job.ready() and job.result() == "slept" and job.forked
    assert sidejobs.Beside(_slow, 0.0, fork=False).ready()


def test_a_cancelled_job_leaves_no_child():
    job = sidejobs.Beside(_work, 10)
    pid = job.pid
    job.cancel()
    assert not job.running
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)       # reaped


def _write(path, text):
    with open(path, "w") as f:
        f.write(text)


def test_detached_work_is_done_by_the_time_the_process_settles(tmp_path):
    path = tmp_path / "out.txt"
    assert sidejobs.detach(_write, str(path), "written by the child")
    sidejobs.settle()
    assert path.read_text() == "written by the child"
    assert not sidejobs._detached


def test_a_foreign_thread_keeps_the_work_in_the_process(monkeypatch):
    monkeypatch.delenv("ACAUSAL_SIDE_JOBS", raising=False)
    assert sidejobs.available()
    stop = threading.Event()
    other = threading.Thread(target=stop.wait, name="someone-else", daemon=True)
    other.start()
    try:
        assert not sidejobs.available()
        job = sidejobs.Beside(_work, 5)
        assert not job.running and job.result()["pid_was_parent"]
        assert not sidejobs.detach(_write, os.devnull, "")
    finally:
        stop.set()
        other.join()
    assert sidejobs.available()
    stop = threading.Event()
    ours = threading.Thread(target=stop.wait, name="acausal-test", daemon=True)
    ours.start()
    try:        # acausal's own threads take no lock of the work
        assert sidejobs.available()
        assert sidejobs.Beside(_work, 5).result()["pid_was_parent"] is False
    finally:
        stop.set()
        ours.join()
    monkeypatch.setenv("ACAUSAL_SIDE_JOBS", "0")
    assert not sidejobs.available()


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("ACAUSAL_COMPILE_CACHE", raising=False)
    monkeypatch.delenv("ACAUSAL_SIDE_JOBS", raising=False)
    return tmp_path / "cache"


def test_a_compile_with_side_jobs_equals_one_without(fresh_cache, monkeypatch):
    """The Cartesian pendulum (index 3 as written): forced to fork at any size, its key,
    index as written, report and cache entry equal those of a compile that does not."""
    from acausal.compiler.frontend.flatten import flatten
    from acausal.library.examples.pendulum import Pendulum
    plain = pipeline.compile_model(Pendulum(), "numpy", cache=False)
    monkeypatch.setattr(pipeline, "SIDE_JOBS_FROM", 0)
    forked = pipeline.compile_model(Pendulum(), "numpy", cache=True)
    assert any("second process" in n for n in forked.report.notes)
    assert forked.report.sigma == plain.report.sigma == as_written(flatten(Pendulum()))
    assert forked.report.sigma["index_sigma"] == 3
    def text(report):       # all but the timings and the notes that name them
        return [line for line in str(report).splitlines()
                if "note:" not in line and "compile time" not in line]
    assert text(forked.report) == text(plain.report)
    key = store.flat_key(flatten(Pendulum()), "numpy")
    found = store.lookup(key)          # stored by the detached child, waited for
    assert found is not None
    again = pipeline.compile_model(Pendulum(), "numpy", cache=True)
    assert any("came from the compile cache" in n for n in again.report.notes)
    assert again.report.sigma == plain.report.sigma
    a = ac.simulate(ac.runtime.CompiledModel(plain), t_end=2.0, rtol=1e-9)
    b = ac.simulate(ac.runtime.CompiledModel(again), t_end=2.0, rtol=1e-9)
    for name in ("x", "y", "lam"):
        scale = max(abs(a[name]).max(), 1e-300)
        assert abs(a[name] - b[name]).max() <= 1e-12 * scale


def test_children_reaped_by_the_system_are_no_error(tmp_path):
    """With SIGCHLD ignored the system reaps the children itself (waitpid then has
    nothing to wait for)."""
    import signal
    old = signal.signal(signal.SIGCHLD, signal.SIG_IGN)
    try:
        job = sidejobs.Beside(_work, 50)
        assert job.result()["squares"] == [k * k for k in range(50)]
        path = tmp_path / "out.txt"
        assert sidejobs.detach(_write, str(path), "written")
        sidejobs.settle()
        assert not sidejobs._detached
    finally:
        signal.signal(signal.SIGCHLD, old)


def test_units_checked_beside_are_reported_as_in_a_compile_that_does_not_fork(
        fresh_cache, monkeypatch):
    """Forked, a large compile checks the units beside the front passes and alias
    elimination: the same mismatch is warned or raised, and a model that also has an
    error alias elimination finds (an equation that repeats a connection) still fails
    on its units first, as when the units are checked before the other passes."""
    import re
    import warnings

    from acausal.components.units import UnitError, UnitWarning
    from tests.components.test_units import WRONG, Oscillator

    class Repeated(Oscillator):
        def equations(self):
            return [ac.Eq(self.spring.flange_b.phi, self.mass.flange_a.phi)]

    def compile_(model, mode, forked):
        monkeypatch.setattr(pipeline, "SIDE_JOBS_FROM", 0 if forked else 10**9)
        return pipeline.compile_model(model, "numpy", cache=True, check_units=mode)

    outcomes = []
    for forked in (False, True):
        monkeypatch.setenv("ACAUSAL_CACHE", str(fresh_cache / str(forked)))
        with pytest.warns(UnitWarning, match=re.escape(WRONG)):
            out = compile_(Oscillator(), "warn", forked)
        assert out.report.units.mismatches == [WRONG]
        assert forked == any("units were checked in a second process" in n
                             for n in out.report.notes)
        with pytest.raises(UnitError, match=re.escape(WRONG)):
            compile_(Oscillator(), "error", forked)
        with pytest.raises(UnitError, match=re.escape(WRONG)):
            compile_(Repeated(), "error", forked)
        with warnings.catch_warnings(record=True) as seen:
            warnings.simplefilter("always")
            with pytest.raises(ac.ModelError, match="is redundant") as err:
                compile_(Repeated(), "warn", forked)
        assert not isinstance(err.value, UnitError)
        outcomes.append([str(w.message) for w in seen if w.category is UnitWarning])
    assert outcomes[0] == outcomes[1] == [WRONG]
