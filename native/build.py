"""Compiling generated C into a shared library: one translation unit for a small source,
several compiled side by side for a large one.

The generated source (:mod:`acausal.compiler.backends.cbackend`) marks with :data:`UNIT` the
places where it may be cut: between the pieces of its functions, each piece a function
of a bounded number of statements that reads and writes only its arguments (the work
array among them), with a prototype of every piece it calls.  So a cut changes nothing
that is computed, only where the compiler sees it.

Measured with gcc 12 on x86-64 (processor time, on a shared 2-core machine): at
``-O0`` the compiler takes about 3 us per character of generated C, whatever the size
of the pieces (an RLC ladder of 1000 sections, 0.87 MB: 2.4 s; of 5556 sections,
100k flat equations, 5 MB: 16.5 s, a third of it register allocation); at ``-O1`` and
``-O2`` 2.6 and 4.6 times that with pieces of 400 lines, 1.6 and 2.4 times with pieces
of 100.  The simulation gains from optimization (``-O2`` against ``-O0``, medians of 11
runs' processor time: the motor drive of ``benchmarks/families.py`` M3 3.7 against
6.2 ms, the 1000-section ladder M1 22 against 33 ms), but on a large model the build is
what costs (M1 at ``-O2``: some 15 s more of the compiler).  Hence:

* a source of at most :data:`LARGE` characters is one translation unit at ``-O2``, or
  at ``-O1`` when it has looped programs (:mod:`acausal.compiler.backends.cloops`, marked
  :data:`LOOPED`).  Their loops read index arrays, and on those ``-O1`` gives what
  ``-O2`` gives for less of the compiler's time.  The 1000-section RLC ladder's looped
  source, 12.7 kB with its index arrays read at run time and its ground's current (a
  sum of 1001 terms) a loop over coefficients, compiles in 0.06-0.07 s at ``-O0``,
  0.09-0.13 s at ``-O1`` and 0.13-0.15 s at ``-O2`` (means of 8), and the model
  simulates to 0.1 s (rtol 1e-6) in a median of 26 ms at ``-O0`` and 17-18 ms at
  ``-O1`` of 9 runs (with a 43.6 kB source that printed the sum term by term: 0.08-0.12,
  0.13-0.19 and 0.22-0.28 s of gcc; 37-45, 17-20 and 16-20 ms);
* a larger one is compiled at ``-O0`` in units of at most about :data:`UNIT_SIZE`
  characters, their number a multiple of the processors this process may use, that
  many compilers at a time, and linked into one library (a few units per processor
  let a free processor take the next unit while another is held by other work, and
  bound the compilers' memory: gcc needs 124 MB for a unit of 430 kB, 356 MB for one
  of 2.5 MB, half of a 100k-equation ladder).

The library is written under a temporary name in the cache directory and renamed into
place when it is whole: a process that finds the name finds the complete library.
"""
from __future__ import annotations

import os
import subprocess
import tempfile
import threading
import time

from ..errors import BackendError

__all__ = ["LARGE", "LOOPED", "UNIT", "UNIT_SIZE", "FLAGS", "FLAGS_LARGE", "FLAGS_LOOPED",
           "flags_for", "jobs", "split", "compile_library", "Compilation", "last_build"]

FLAGS = ["-O2", "-fPIC", "-ffp-contract=off"]
FLAGS_LARGE = ["-O0", "-fPIC", "-ffp-contract=off"]
FLAGS_LOOPED = ["-O1", "-fPIC", "-ffp-contract=off"]
LOOPED = "/* looped */"    # in the header of a source with looped programs (cloops)
LARGE = 200_000            # characters of C above which -O0 and parallel units are used
UNIT_SIZE = 500_000        # characters per translation unit of a large source, at most
UNIT = "/* unit */\n"      # where the source may be split into translation units

#: how the last library was built: units, parallel compilers, flags, seconds
last_build: dict = {}


def flags_for(source: str) -> list:
    if len(source) > LARGE:
        return FLAGS_LARGE
    return FLAGS_LOOPED if LOOPED in source else FLAGS


def jobs() -> int:
    """How many compilers run at once: the processors this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def split(source: str, size: int = UNIT_SIZE, n_jobs: int = 1) -> list:
    """The source cut at its :data:`UNIT` marks into translation units of at most about
    ``size`` characters, their number a multiple of ``n_jobs`` (so that the last round
    of compilers is full), each unit consecutive segments of the source (at least one)
    opened by the source's header (what comes before the first mark)."""
    header, *segments = source.split(UNIT)
    body = len(source) - len(header)
    if len(segments) < 2 or body <= size:
        return [source]
    rounds = -(-body // (max(1, n_jobs) * size))
    n = min(len(segments), max(1, n_jobs) * rounds)
    # cut near equal shares of the characters
    total = sum(len(s) for s in segments)
    units, current, done = [], [], 0
    for seg in segments:
        current.append(seg)
        done += len(seg)
        if done >= total * (len(units) + 1) / n and len(units) < n - 1:
            units.append(current)
            current = []
    if current:
        units.append(current)
    return [header + "".join(u) for u in units]


def compile_library(cc: str, units: list, flags: list, out_dir: str) -> str:
    """Compile ``units`` (C sources) with ``flags``, at most :func:`jobs` at a time, and
    link them into ``out_dir/model.so``; returns that path.  The first compiler that
    fails stops the others and raises :class:`BackendError` with its message."""
    return Compilation(cc, units, flags, out_dir).wait()


class Compilation:
    """:func:`compile_library` in two steps: the compilers of the first units are
    started when this is made (by the caller's thread: a thread of its own would wait
    for the interpreter's lock while the caller runs Python, 30-45 ms on the 1000-section
    ladder), and :meth:`wait` compiles the rest and links (it may run in another
    thread: the compilers are processes, waited for without the lock)."""

    def __init__(self, cc: str, units: list, flags: list, out_dir: str):
        self.t0 = time.perf_counter()
        self.cc, self.units, self.flags, self.out_dir = cc, units, flags, out_dir
        self.n_jobs = min(jobs(), len(units))
        self.objects = [os.path.join(out_dir, f"model{k}.o") for k in range(len(units))]
        self.todo = list(range(len(units)))[::-1]
        self.lock = threading.Lock()
        self.running, self.errors = {}, []
        self.first = []
        for _ in range(self.n_jobs):
            started = self._launch(self.todo.pop())
            if started is None:
                break
            self.first.append(started)
        if self.errors:
            raise BackendError(self.errors[0])

    def _launch(self, k):
        """Start the compiler of unit k: (k, process), or None (the error recorded and
        the other compilers stopped)."""
        src = os.path.join(self.out_dir, f"model{k}.c")
        with open(src, "w") as f:
            f.write(self.units[k])
        with self.lock:
            if self.errors:
                return None
            try:
                proc = subprocess.Popen([self.cc, *self.flags, "-c", "-o", self.objects[k],
                                         src], stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True)
            except OSError as exc:
                self.errors.append(f"the C compiler {self.cc} could not be started: {exc}")
                _stop(self.running)
                return None
            self.running[k] = proc
        return k, proc

    def _worker(self, started) -> None:
        """Wait for one compiler, then start the next unit, until none is left."""
        k, proc = started
        while True:
            _, err = proc.communicate()
            with self.lock:
                del self.running[k]
                if proc.returncode != 0 and not self.errors:
                    self.errors.append(_failure(self.cc, err, k, len(self.units)))
                    _stop(self.running)       # what they compile would be thrown away
                if self.errors or not self.todo:
                    return
                k = self.todo.pop()
            started = self._launch(k)
            if started is None:
                return
            k, proc = started

    def wait(self) -> str:
        """Compile what is left, link, and return the library's path."""
        threads = [threading.Thread(target=self._worker, args=(s,), name=f"acausal-cc-{k}",
                                    daemon=True) for k, s in enumerate(self.first[1:])]
        try:
            for th in threads:
                th.start()
            if self.first:
                self._worker(self.first[0])
            for th in threads:
                th.join()
        except BaseException:
            # interrupted: no compiler outlives the build directory
            with self.lock:
                self.errors.append("interrupted")
                _stop(self.running)
            raise
        if self.errors:
            raise BackendError(self.errors[0])
        t1 = time.perf_counter()
        lib = os.path.join(self.out_dir, "model.so")
        proc = subprocess.run([self.cc, "-shared", "-o", lib, *self.objects, "-lm"],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            raise BackendError(f"linking the generated model failed:\n{proc.stderr[-2000:]}")
        last_build.clear()
        last_build.update(units=len(self.units), jobs=self.n_jobs, flags=" ".join(self.flags),
                          characters=sum(map(len, self.units)), compile_s=t1 - self.t0,
                          link_s=time.perf_counter() - t1)
        return lib


def _stop(running: dict) -> None:
    for proc in running.values():
        proc.terminate()


def _failure(cc, err, k, n) -> str:
    where = f" (translation unit {k + 1} of {n})" if n > 1 else ""
    return (f"the C compiler {cc} failed on the generated model{where}:\n"
            + (err or "").strip()[-2000:])


def temporary_dir(root: str):
    """A directory for one build, inside the cache directory (same file system: the
    library is renamed from it into place)."""
    return tempfile.TemporaryDirectory(dir=root, prefix="build_")
