"""Work of a large compile done beside the passes, in a forked copy of the process.

Some parts of a large compile read what the passes have made but feed no later pass:
the compile cache's key of the flat model (:func:`acausal.compiler.cache.keys.flat_key`)
with the unit check and the report's table of modes (one child, beside the front passes
and alias elimination), the structural index of the equations as written
(:func:`acausal.compiler.index.reduction.as_written`, for the report) and the compile cache's
entry (:func:`acausal.compiler.cache.entries.store`, which pickles the model and prints its
equations' texts).  On a machine with a second processor they need not
wait for each other or for the passes (:mod:`acausal.compiler.pipeline` says when):

- :class:`Beside` runs a function in a forked child while the passes go on, and returns
  its result (pickled back through a pipe) where the pipeline needs it;
- :func:`detach` runs one whose result nobody waits for (the cache store); the process
  reaps it later (:func:`settle`, which a cache lookup calls first, so a process finds
  what it stored itself).

Why fork: the child starts as a copy-on-write image of the parent (a 200 MB compile
forks in a few milliseconds), so nothing is pickled on the way in; pickling the flat
model instead would cost more than the work it carries.  sweeps.py forks its workers
for the same reason.

The result does not depend on where the work ran.  It runs in the process itself, at
the point its result is needed, when

- the operating system cannot fork, or ``ACAUSAL_SIDE_JOBS=0``;
- a Python thread other than acausal's own runs: a lock such a thread holds at the fork
  would stay held in the child forever (acausal's threads, a timer and the C compiler's
  feeders, take no lock the child's work takes); threads of native libraries (the BLAS
  pool) hold no lock of the interpreter's;
- the child ends without a result (it raised, it was killed, its result would not
  pickle): the parent runs the function again, which raises the same error with its
  whole traceback, or returns the result.

A child that cannot finish must not hold up the compile: the parent waits for a result
at most five seconds plus three times as long as it went on without it, and for its own
cache store at most ``STORE_PATIENCE`` seconds, then stops the child (the work is
redone by the parent, or the entry is left to a later compile: it is written whole or
not at all).  A child also ends itself after ``LIMIT`` seconds (an alarm), so none
outlives its purpose.
"""
from __future__ import annotations

import os
import pickle
import select
import signal
import threading
import time
import warnings

__all__ = ["Beside", "available", "detach", "settle"]

LIMIT = 600                # s: a child's alarm
_OURS = "acausal-"         # the prefix of the names of acausal's own threads
_detached: list = []       # (pid, start) of the children of detach() not reaped yet


def available() -> bool:
    """True when work can be forked (see the module docstring)."""
    if not hasattr(os, "fork"):
        return False
    switch = os.environ.get("ACAUSAL_SIDE_JOBS", "1").strip().lower()
    if switch in ("0", "no", "off", "false"):
        return False
    main = threading.main_thread()
    return all(t is main or t.name.startswith(_OURS) for t in threading.enumerate())


def _fork() -> int:
    with warnings.catch_warnings():
        # Python 3.12+ warns at any fork of a process with more than one OS thread;
        # available() has checked the only ones that matter here (its docstring)
        warnings.simplefilter("ignore", DeprecationWarning)
        return os.fork()


def _child(fn, args, w: int | None) -> None:
    """The forked child: run fn, send (result, seconds) to w, end without cleanup
    (what the parent's exit handlers and buffers hold is the parent's)."""
    try:
        signal.signal(signal.SIGALRM, signal.SIG_DFL)
        signal.alarm(LIMIT)
        t0 = time.perf_counter()
        out = fn(*args)
        if w is not None:
            data = pickle.dumps((out, time.perf_counter() - t0),
                                protocol=pickle.HIGHEST_PROTOCOL)
            view = memoryview(data)
            while view:
                view = view[os.write(w, view):]
    except BaseException:      # noqa: BLE001 - the parent runs it again and sees why
        pass
    finally:
        os._exit(0)


# bytes a pipe holds before its writer waits for the reader (Linux: 64 kB by default,
# up to /proc/sys/fs/pipe-max-size, 1 MB by default, for a process without privileges)
PIPE_SIZE = 1 << 20


def _widen(fd: int) -> None:
    """Let the pipe hold a whole result of most compiles: a child whose result does
    not fit waits, alive, until the parent reads it, and every page the parent writes
    meanwhile is copied first (the index as written of an 18 000-equation ladder is
    108 kB, read after code generation: 0.1 s more of the parent's time).  Where the
    size cannot be set, the pipe stays as it is."""
    try:
        import fcntl
        fcntl.fcntl(fd, fcntl.F_SETPIPE_SZ, PIPE_SIZE)
    except (ImportError, AttributeError, OSError):
        pass


class Beside:
    """``fn(*args)`` run in a forked child from now on (``fork=False``: run by
    :meth:`result`); :meth:`result` returns what it returned.  ``seconds`` is then the
    time the work took where it ran, ``forked`` whether that was in the child."""

    def __init__(self, fn, *args, fork: bool = True):
        self.fn, self.args = fn, args
        self.pid = self.fd = None
        self.forked, self.seconds = False, 0.0
        if not (fork and available()):
            return
        r, w = os.pipe()
        _widen(w)
        try:
            pid = _fork()
        except OSError:
            os.close(r), os.close(w)
            return
        if pid == 0:
            os.close(r)
            _child(fn, args, w)
        os.close(w)
        self.pid, self.fd, self.started = pid, r, time.monotonic()

    @property
    def running(self) -> bool:
        """True while a forked child does the work."""
        return self.pid is not None

    def ready(self) -> bool:
        """Whether :meth:`result` would return without waiting for the child (it has
        begun to send its result, or ended, or there is none)."""
        return self.pid is None or bool(select.select([self.fd], [], [], 0)[0])

    def result(self):
        """What ``fn(*args)`` returned: the child's, or computed here when the child
        ended without it or has not sent it within ``PATIENCE`` (the time the caller
        went on meanwhile, times three, plus five seconds: a child that should have been
        done long ago is stopped; the work is the caller's again)."""
        if self.pid is not None:
            waited = time.monotonic() - self.started
            data = self._read(PATIENCE[0] + PATIENCE[1] * waited)
            if data:
                try:
                    out, self.seconds = pickle.loads(data)
                    self.forked = True
                    return out
                except Exception:       # noqa: BLE001 - run it here instead
                    pass
        t0 = time.perf_counter()
        out = self.fn(*self.args)
        self.seconds = time.perf_counter() - t0
        return out

    def _read(self, patience: float) -> bytes | None:
        """The child's whole message, or None (it ended without one, or ran out of
        patience); the child is reaped either way."""
        chunks, end = [], time.monotonic() + patience
        try:
            while True:
                left = end - time.monotonic()
                if left <= 0 or not select.select([self.fd], [], [], left)[0]:
                    return None
                chunk = os.read(self.fd, 1 << 20)
                if not chunk:           # sent: the child is ending (os._exit)
                    try:
                        os.waitpid(self.pid, 0)
                    except ChildProcessError:   # reaped already (SIGCHLD ignored)
                        pass
                    os.close(self.fd)
                    self.pid = None
                    return b"".join(chunks)
                chunks.append(chunk)
        finally:
            self.cancel()

    def cancel(self) -> None:
        """Stop the child if it still runs, and reap it (its result is not needed, or
        has been read)."""
        if self.pid is not None:
            _stop(self.pid)
            os.close(self.fd)
            self.pid = None


# how long a caller waits for a child beyond the time it went on without it:
# (seconds, factor) -- see Beside.result
PATIENCE = (5.0, 3.0)
STORE_PATIENCE = 60.0      # s a process waits for its own cache store (settle)


def detach(fn, *args) -> bool:
    """Run ``fn(*args)`` in a forked child and go on without its result; False (and
    nothing done) when work cannot be forked: the caller then runs it itself."""
    settle(block=False)
    if not available():
        return False
    try:
        pid = _fork()
    except OSError:
        return False
    if pid == 0:
        _child(fn, args, None)
    _detached.append((pid, time.monotonic()))
    return True


def settle(block: bool = True) -> None:
    """Reap the children of :func:`detach` that have ended; with ``block``, wait for
    the others, each until ``STORE_PATIENCE`` seconds after it started, and stop it
    then (a cache entry is written whole or not at all)."""
    for item in list(_detached):
        pid, started = item
        done = _ended(pid)
        while block and not done:
            if time.monotonic() - started > STORE_PATIENCE:
                _stop(pid)
                done = True
                break
            time.sleep(0.005)
            done = _ended(pid)
        if done:
            _detached.remove(item)


def _ended(pid: int) -> bool:
    """True when the child ``pid`` has ended (and is now reaped) or is not ours."""
    try:
        done, _ = os.waitpid(pid, os.WNOHANG)
    except ChildProcessError:
        return True
    return done != 0


def _stop(pid: int) -> None:
    """End the child ``pid`` (if it still runs) and reap it."""
    if not _ended(pid):
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
        try:
            os.waitpid(pid, 0)
        except ChildProcessError:
            pass
