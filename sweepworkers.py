"""Local worker processes for sweeps (``executor="processes"``): each a new interpreter,
given the model once, running one run at a time.

Why not :class:`concurrent.futures.ProcessPoolExecutor`: when one of its workers dies
(killed, out of memory, a crash in native code) the whole pool breaks and every future
fails, the finished ones included; and on Linux it forks, which copies a parent that
holds other libraries' threads (a dask cluster's, a notebook's) with their locks in
whatever state they were -- a forked worker then hangs or prints ``SystemError`` from
``threading._after_fork``.  Here:

* a worker is started as ``python -c`` (as a spawn context does, but without importing
  the user's ``__main__`` again, so a script need not guard its sweep with
  ``if __name__ == "__main__"``), with the parent's ``sys.path``; it receives the pickled
  model and the job once, then run after run, and sends each outcome back as soon as it
  is done.  Nothing of the parent is copied: no thread, no lock.
* a worker that dies costs only the run it was running: that run comes back failed with
  the reason (the signal or exit status), a new worker takes the runs not started yet,
  and with ``retries`` the lost run is run again (on a new worker) up to that many times.
* every worker ends with the call: at its end, on an error or an interrupt, the workers
  are told to stop, and those that do not are killed and waited for.

The messages go through two pipes per worker (:mod:`multiprocessing.connection`
framing, pickle), not through stdin/stdout, which the model's code may print to.
"""
from __future__ import annotations

import contextlib
import os
import pickle
import signal
import subprocess
import sys
import tempfile
import time
import warnings
from multiprocessing.connection import Connection, wait

import numpy as np

from .simulation import simulate

__all__ = ["run_on_processes", "serve", "run_one", "failed"]

_STOP_GRACE = 5.0          # s a worker has to end after it is told to, before it is killed
_PACKAGE = __name__.rsplit(".", 1)[0]


# -- one run, anywhere: here, on a local worker process, a pool's or a dask worker -------------
def run_one(compiled, base, values, job):
    """(values on the grid (NaN where not reached), success, message, steps); a job with
    a ``task`` (a module-level function, so that it pickles) runs that instead:
    ``task(compiled, values, job)`` with the model at its base parameters."""
    compiled.p[:] = base
    given = set(compiled.input_names)
    if given & set(values):
        inputs = {**job["kwargs"].get("inputs", {}), **{k: v for k, v in values.items()
                                                        if k in given}}
        values = {k: v for k, v in values.items() if k not in given}
        job = {**job, "kwargs": {**job["kwargs"], "inputs": inputs}}
    if job.get("task") is not None:
        try:
            return job["task"](compiled, values, job)
        finally:
            compiled.p[:] = base
    grid = job["t_eval"]
    out = np.full((len(job["names"]), len(grid)), np.nan)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")     # a failure is reported in the Dataset
            res = simulate(compiled, job["t_end"], t_start=job["t_start"], t_eval=grid,
                           parameters=values, progress=False, **job["kwargs"])
    except Exception as err:  # noqa: BLE001 - any failure of one run is that run's result
        return out, False, f"{type(err).__name__}: {err}", 0
    finally:
        compiled.p[:] = base
    k = len(res.t)              # output at t_eval: a failed run's points are the first k
    res._prefetch(job["names"])
    for i, n in enumerate(job["names"]):
        out[i, :k] = res[n]
    return out, bool(res.success), str(res.message), int(res.stats.get("steps", 0))


def failed(job, reason):
    """The outcome of a run that did not run (its worker died): NaN, and the reason."""
    if job.get("task") is not None:
        return None, False, reason, 0
    return np.full((len(job["names"]), len(job["t_eval"])), np.nan), False, reason, 0


# -- the local worker processes ---------------------------------------------------------------
class _Worker:
    """One worker process, its two pipes and a file for what it writes to stderr;
    ``task``: the run it is running, or None."""

    def __init__(self):
        r_task, w_task = os.pipe()      # parent -> worker
        r_out, w_out = os.pipe()        # worker -> parent
        code = (f"import sys; sys.path[:0] = {[p for p in sys.path if p]!r}; "
                f"from {_PACKAGE}.sweepworkers import serve; serve({r_task}, {w_out})")
        self.stderr = tempfile.TemporaryFile()
        try:
            self.proc = subprocess.Popen(
                [sys.executable, "-c", code], pass_fds=(r_task, w_out),
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=self.stderr)
        except BaseException:
            for fd in (w_task, r_out):
                os.close(fd)
            self.stderr.close()
            raise
        finally:
            os.close(r_task)
            os.close(w_out)
        self.send = Connection(w_task, readable=False)
        self.recv = Connection(r_out, writable=False)
        self.task = None
        self.ready = False      # it has loaded the model

    def begin(self, start: bytes) -> None:
        """Send the model and the job (a worker that died is noticed at its run)."""
        with contextlib.suppress(OSError):
            self.send.send_bytes(start)

    def give(self, task) -> bool:
        """Send a run; False when the worker is gone."""
        self.task = task
        try:
            self.send.send(task)
            return True
        except OSError:
            return False

    def why(self) -> str:
        """Why the worker ended, in words (its exit and the last line it wrote)."""
        code = self.proc.returncode
        if code is not None and code < 0:
            try:
                what = f"was killed ({signal.Signals(-code).name})"
            except ValueError:
                what = f"was killed (signal {-code})"
        else:
            what = f"exited with status {code}"
        self.stderr.seek(0)
        lines = [ln for ln in self.stderr.read()[-2000:].decode("utf-8", "replace")
                 .splitlines() if ln.strip()]
        return f"the worker process running it {what}" + \
            (f": {lines[-1].strip()[:200]}" if lines else "")

    def end(self, deadline: float | None = None) -> None:
        """Tell the worker to stop, wait for it until ``deadline``, then kill it."""
        with contextlib.suppress(OSError):
            self.send.send(None)
        for conn in (self.send, self.recv):
            with contextlib.suppress(OSError):
                conn.close()
        try:
            self.proc.wait(timeout=max(0.0, (deadline or time.monotonic() + _STOP_GRACE)
                                       - time.monotonic()))
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()

    def close(self) -> None:
        self.stderr.close()


def _started(start: bytes) -> _Worker:
    w = _Worker()
    w.begin(start)
    return w


def run_on_processes(blob: bytes, base, job: dict, indexed: list, workers: int,
                     retries: int, on_done) -> list:
    """Run ``indexed`` ([(index, values)]) on ``workers`` new processes that receive
    ``blob`` (the pickled model), ``base`` (its parameter values) and ``job`` once;
    returns [(index, *outcome)].  ``on_done(n)`` is called as outcomes arrive (a
    progress bar)."""
    start = pickle.dumps((blob, base, job), protocol=pickle.HIGHEST_PROTOCOL)
    pending = list(reversed(indexed))
    attempts = {index: 0 for index, _ in indexed}
    results, pool, gone = [], [], []
    try:
        # all started first, then given the model: they start up side by side
        pool += [_Worker() for _ in range(min(workers, len(indexed)))]
        for w in pool:
            w.begin(start)
        booted_not = 0          # workers that died before they were ready
        while pending or any(w.task is not None for w in pool):
            for w in pool:
                if w.task is None and pending:
                    w.give(pending.pop())
            busy = {w.recv: w for w in pool if w.task is not None}
            for conn in wait(list(busy)):
                w = busy[conn]
                try:
                    message = conn.recv()
                except (EOFError, OSError):
                    message = None
                if message == "ready":
                    w.ready = True
                    continue
                if message is not None:
                    index, outcome = message
                    w.task = None
                    results.append((index, *outcome))
                    on_done(1)
                    continue
                # the worker died: its run is lost (or run again), a new worker takes
                # its place while runs are left
                pool.remove(w)
                gone.append(w)
                w.end()
                index, values = w.task
                if not w.ready:       # it could not start: not the run's fault
                    booted_not += 1
                    if booted_not > workers:
                        raise RuntimeError(f"sweep: the worker processes cannot start; "
                                           f"the last: {w.why()}")
                    pending.append((index, values))
                else:
                    attempts[index] += 1
                    if attempts[index] <= retries:
                        pending.append((index, values))
                    else:
                        tried = f" (in {attempts[index]} attempts)" \
                            if attempts[index] > 1 else ""
                        results.append((index, *failed(job, f"WorkerDied: {w.why()}"
                                                             f"{tried}")))
                        on_done(1)
                if pending:
                    pool.append(_started(start))
        return results
    finally:
        deadline = time.monotonic() + _STOP_GRACE
        for w in pool:
            w.end(deadline)
        for w in pool + gone:
            w.close()


def serve(r_task: int, w_out: int) -> None:
    """The body of a worker process: the model and job, then runs until told to stop."""
    tasks = Connection(r_task, writable=False)
    out = Connection(w_out, readable=False)
    blob, base, job = pickle.loads(tasks.recv_bytes())
    compiled = pickle.loads(blob)
    out.send("ready")
    while True:
        try:
            task = tasks.recv()
        except EOFError:
            task = None
        if task is None:
            # nothing is left to flush (the outcomes went out whole), and the parent
            # waits for this process: skip the interpreter's teardown
            os._exit(0)
        index, values = task
        try:
            outcome = run_one(compiled, base, values, job)
        except Exception as exc:  # noqa: BLE001 - a task's own error is its run's result
            outcome = failed(job, f"{type(exc).__name__}: {exc}")
        out.send((index, outcome))
