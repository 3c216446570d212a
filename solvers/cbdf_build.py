"""The compiled step loop's library built in the background: once per machine, into the
C backend's cache, in a process of its own (:func:`build_in_background`).

The build takes about a second and a half of gcc, longer than a small model's whole
first run, so a run does not wait for it where it need not (:mod:`acausal.solvers.cbdf`
says when the library is used, and loads it: :func:`acausal.solvers.cbdf.library`).
"""
from __future__ import annotations

import contextlib
import os
import subprocess
import sys
import threading
import time

__all__ = ["build_in_background", "build_if_long"]

_builder = None          # the process started by build_in_background
_spawning = threading.Lock()
_MARKER = "cbdf-building"    # in the cache while a process builds the library
_MARKER_AGE = 120.0      # s after which a marker is taken for that of a killed build


def build_in_background() -> None:
    """Start building the step loop's library in a process of its own, unless it is
    built, being built, or no C compiler works.

    Why a process: compiling it takes about a second and a half of gcc, longer than a
    small model's whole first run.  A thread would overlap the model's compile, but the
    interpreter waits for its threads at exit, so the first script would still end only
    when the build does.  The process outlives this one if need be; its library appears
    in the cache atomically (:func:`acausal.compiler.backends.cbackend.build` compiles in a
    temporary directory and renames the result), so a build that is interrupted leaves
    no library rather than a broken one, and the next process starts it again.  While
    it runs, the cache holds a marker file, so concurrent processes start one build.
    It runs at a lower priority (nice 10).  :func:`acausal.simulate` starts it after a
    run, and :func:`acausal.compile` during a compile that takes longer than a small
    model's (:func:`build_if_long`): a long compile then overlaps the build and finds
    the library for its first run, while a small model's first run does not share the
    processors with it."""
    global _builder
    from .cbdf import library
    with _spawning:
        if _builder is not None or library(cached_only=True) is not None:
            return
        from ..compiler.backends.cbackend import cache_dir, compiler_available
        if compiler_available() is None or _building(os.path.join(cache_dir(), _MARKER)):
            return
        _builder = _spawn_builder()


@contextlib.contextmanager
def build_if_long(seconds: float | None):
    """A block during which :func:`build_in_background` is called if the block is still
    running after ``seconds`` (None: never)."""
    from .cbdf import library
    timer = None
    if seconds is not None and _builder is None and library(cached_only=True) is None:
        timer = threading.Timer(seconds, build_in_background)
        timer.name = "acausal-loop-build-timer"   # acausal's own (compiler.sidejobs)
        timer.daemon = True         # nothing started while it waits: no reason to wait
        timer.start()
    try:
        yield
    finally:
        if timer is not None:
            timer.cancel()


def _spawn_builder():
    """The process of :func:`build_in_background` (a ``subprocess.Popen``), or None when
    no interpreter can be started (the first run that needs the library builds it)."""
    package = __name__.rsplit(".", 2)[0]
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    code = (f"import sys; sys.path.insert(0, {root!r}); "
            f"from {package}.solvers.cbdf_build import _build_detached; _build_detached()")
    try:
        # its own session: a Ctrl-C meant for the script does not reach the build
        return subprocess.Popen([sys.executable, "-c", code], stdin=subprocess.DEVNULL,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
    except OSError:
        return None


def _building(marker: str) -> bool:
    """Whether a process is building the library: ``marker`` exists, the process whose
    number it holds is alive, and it is younger than :data:`_MARKER_AGE` (a marker
    whose process is gone, or an older one, is left by a build that was killed)."""
    try:
        if time.time() - os.stat(marker).st_mtime >= _MARKER_AGE:
            return False
        with open(marker) as f:
            text = f.read().strip()
    except OSError:
        return False
    if text.isdigit():         # empty: the builder has not written its number yet
        try:
            os.kill(int(text), 0)
        except ProcessLookupError:
            return False
        except OSError:        # alive, another user's
            pass
    return True


def _build_detached() -> None:
    """The body of the process of :func:`build_in_background`: build the library unless
    another process holds the marker.  A termination signal ends the build as an
    exception does, so its temporary directory and the marker are removed."""
    import signal
    signals = [getattr(signal, name) for name in ("SIGTERM", "SIGHUP", "SIGINT")
               if hasattr(signal, name)]

    def stop(signum, frame):
        for sig in signals:
            signal.signal(sig, signal.SIG_IGN)
        if hasattr(os, "killpg") and os.getpgrp() == os.getpid():
            os.killpg(os.getpgrp(), signal.SIGTERM)    # the compiler, in this build's group
        raise SystemExit(128 + signum)

    for sig in signals:
        signal.signal(sig, stop)
    if hasattr(os, "nice"):   # idle processor time only: the run it overlaps goes first
        try:
            os.nice(10)
        except OSError:
            pass
    from ..compiler.backends.cbackend import cache_dir
    marker = os.path.join(cache_dir(), _MARKER)
    for _ in range(2):
        try:
            fd = os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
            break
        except FileExistsError:
            if _building(marker):
                return
            try:                 # a killed build's marker
                os.remove(marker)
            except OSError:
                return
    else:
        return
    try:
        os.write(fd, str(os.getpid()).encode())
        os.close(fd)
        from .cbdf import library
        library()
    finally:
        try:
            os.remove(marker)
        except OSError:
            pass
