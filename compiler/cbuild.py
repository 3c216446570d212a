"""Compiling generated C into a shared library: one translation unit for a small source,
several compiled side by side for a large one.

The generated source (:mod:`acausal.compiler.cbackend`) marks with :data:`UNIT` the
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
  at ``-O1`` when it has looped programs (:mod:`acausal.compiler.cloops`, marked
  :data:`LOOPED`).  Their loops read index arrays, and on those ``-O1`` gives what
  ``-O2`` gives for less of the compiler's time.  The 1000-section RLC ladder's looped
  source, 43.6 kB with its index arrays read at run time, compiles in 0.08-0.12 s at
  ``-O0``, 0.13-0.19 s at ``-O1`` and 0.22-0.28 s at ``-O2``; the model simulates to
  0.1 s (rtol 1e-6) in a median of 37-45 ms, 17-20 ms and 16-20 ms of 7 runs;
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
           "flags_for", "jobs", "split", "compile_library", "last_build"]

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
    t0 = time.perf_counter()
    n_jobs = min(jobs(), len(units))
    objects = [os.path.join(out_dir, f"model{k}.o") for k in range(len(units))]
    todo = list(range(len(units)))[::-1]
    lock = threading.Lock()
    running, errors = {}, []

    def worker():
        while True:
            with lock:
                if errors or not todo:
                    return
                k = todo.pop()
            src = os.path.join(out_dir, f"model{k}.c")
            with open(src, "w") as f:
                f.write(units[k])
            with lock:
                if errors:
                    return
                try:
                    proc = subprocess.Popen([cc, *flags, "-c", "-o", objects[k], src],
                                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                            text=True)
                except OSError as exc:
                    errors.append(f"the C compiler {cc} could not be started: {exc}")
                    _stop(running)
                    return
                running[k] = proc
            _, err = proc.communicate()
            with lock:
                del running[k]
                if proc.returncode != 0 and not errors:
                    errors.append(_failure(cc, err, k, len(units)))
                    _stop(running)        # what they compile would be thrown away

    threads = [threading.Thread(target=worker, name=f"acausal-cc-{k}", daemon=True)
               for k in range(n_jobs)]
    try:
        for th in threads:
            th.start()
        for th in threads:
            th.join()
    except BaseException:
        # interrupted: no compiler outlives the build directory
        with lock:
            errors.append("interrupted")
            _stop(running)
        raise
    if errors:
        raise BackendError(errors[0])
    t1 = time.perf_counter()
    lib = os.path.join(out_dir, "model.so")
    proc = subprocess.run([cc, "-shared", "-o", lib, *objects, "-lm"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise BackendError(f"linking the generated model failed:\n{proc.stderr[-2000:]}")
    last_build.clear()
    last_build.update(units=len(units), jobs=n_jobs, flags=" ".join(flags),
                      characters=sum(map(len, units)), compile_s=t1 - t0,
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
