"""Parameter sweeps and ensembles: one compile, many runs, one ``xarray.Dataset``.

``sweep(compiled, {"R1.R": [...], "C1.C": [...]}, grid="product" | "zip", ...)`` makes
the runs of a grid (every combination, or the lists side by side); ``ensemble(compiled,
[{"R1.R": 1.0}, ...], ...)`` takes them as given.  Every run starts from the model's
compiled parameter values with its own changed (nothing carries over from the run
before) and is simulated on a common output grid (``t_eval`` or ``n_points``, required),
so the results stack into a Dataset with dimensions ``run`` and ``time``, one variable
per name, the swept parameters as coordinates along ``run``, and per run ``success``
and ``message``.  A run that fails keeps what it computed (NaN after the failure) and
never loses the others.

Executors: ``None`` (serial, in this process), ``"processes"`` (local worker processes,
:mod:`acausal.sweepworkers`: new interpreters, never forked), a
:class:`concurrent.futures.Executor`, or a ``dask.distributed.Client`` (any cluster).
The compiled model travels to the workers by ``pickle``, once per worker, not once per
run.  A worker that dies (killed, out of memory, a crash) costs only its own runs: they
come back failed with the reason (``message`` starts with ``WorkerDied:`` for local
processes), the others with their data; ``retries=n`` runs a lost run again, up to n
times.  On dask the model is scattered under a key of its own per sweep, so sweeps one
after another on one Client never share (and never lose) it.
"""
from __future__ import annotations

import itertools
import os
import pickle
import threading

import numpy as np

from .errors import InvalidArgument
from . import simulation
from .sweepworkers import failed, run_on_processes, run_one
from .words import suggestion

__all__ = ["sweep", "ensemble"]

_CHUNKS_PER_WORKER = 4     # tasks per worker: few enough to keep overhead low, enough to
                           # balance runs of unequal length


def sweep(model, parameters: dict, *, grid: str = "product", t_end: float,
          t_eval=None, n_points: int | None = None, executor=None, names=None,
          progress: bool | None = None, max_workers: int | None = None, retries: int = 0,
          **simulate_kwargs):
    """Simulate ``model`` over a grid of parameter values; see the module docstring.

    ``parameters``: ``{name: values}``; ``grid="product"``: every combination (the last
    name varies fastest), ``"zip"``: the i-th value of each (equal lengths).  ``names``:
    the variables to keep (default: all).  ``retries``: how often a run whose worker
    died is run again.  Other keywords go to :func:`acausal.simulate`.  Returns an
    ``xarray.Dataset``."""
    if not isinstance(parameters, dict) or not parameters:
        raise InvalidArgument("sweep: parameters must be a non-empty dict {name: values}")
    keys = list(parameters)
    columns = [np.atleast_1d(np.asarray(parameters[k], dtype=float)) for k in keys]
    if grid == "product":
        combos = list(itertools.product(*columns))
    elif grid == "zip":
        lengths = {len(c) for c in columns}
        if len(lengths) != 1:
            raise InvalidArgument(f"sweep: grid='zip' needs lists of equal length, got "
                             f"{dict(zip(keys, (len(c) for c in columns)))}")
        combos = list(zip(*columns))
    else:
        raise InvalidArgument(f"sweep: grid must be 'product' or 'zip', not {grid!r}")
    runs = [{k: float(v) for k, v in zip(keys, combo)} for combo in combos]
    return ensemble(model, runs, t_end=t_end, t_eval=t_eval, n_points=n_points,
                    executor=executor, names=names, progress=progress,
                    max_workers=max_workers, retries=retries, **simulate_kwargs)


def ensemble(model, runs, *, t_end: float, t_eval=None, n_points: int | None = None,
             executor=None, names=None, progress: bool | None = None,
             max_workers: int | None = None, retries: int = 0, **simulate_kwargs):
    """Simulate ``model`` once per parameter dict in ``runs``; see the module docstring."""
    runs = [dict(r) for r in runs]
    if not runs:
        raise InvalidArgument("ensemble: no runs")
    if t_eval is None and n_points is None:
        raise InvalidArgument("ensemble: give t_eval or n_points (the common output grid)")
    t_start = simulation._time("t_start", simulate_kwargs.pop("t_start", 0.0))
    times = simulation._output_times(t_eval, n_points, t_start,
                                     simulation._time("t_end", t_end))
    for key in ("parameters", "raise_on_failure", "n_points", "t_eval", "store"):
        if key in simulate_kwargs:
            raise InvalidArgument(f"ensemble: {key} is set per run, not as a keyword")
    # a mistake in the call is said now, not by every run
    simulation.check_arguments(t_end, t_start, simulate_kwargs.get("rtol", 1e-6),
                               simulate_kwargs.get("atol"))
    compiled = simulation.compile(model, simulate_kwargs.pop("backend", "auto"))
    # a top-level input is swept as a parameter is: a number per run (or, in an
    # ensemble, a function of time or a table), given with the run's other inputs
    # (a parameter found by initialization, fixed=False, is not tunable: refused now)
    found = set((compiled.meta.get("free_parameters") or {}).get("names", ()))
    unknown = sorted({k for r in runs for k in r} - (set(compiled.param_names) - found)
                     - set(compiled.input_names))
    if unknown:                  # a mistake in the call, not a failed run: say it now
        compiled.set_parameters({unknown[0]: 1.0})
    names = sorted(compiled.outputs) if names is None else list(names)
    missing = [n for n in names if n not in compiled.outputs]
    if missing:
        raise KeyError(f"ensemble: no variable {missing[0]!r} in the model"
                       f"{suggestion(missing[0], compiled.outputs)}"
                       + (f" (and {len(missing) - 1} more)" if len(missing) > 1 else ""))
    job = {"t_end": float(t_end), "t_start": t_start, "t_eval": times, "names": names,
           "kwargs": simulate_kwargs}
    outcomes = _execute(compiled, runs, job, executor, progress, max_workers, retries)
    return _dataset(compiled, runs, times, names, outcomes)


# -- one run, anywhere (sweepworkers.run_one) -----------------------------------------------
def _run_chunk(compiled, base, chunk, job):
    return [(index, *run_one(compiled, base, values, job)) for index, values in chunk]


_WORKER = {}     # on a dask worker: the models it was given, by key
_KEPT = 16       # models a long-lived dask worker keeps between sweeps


def _dask_chunk(blob, base, chunk, job):
    """On a dask worker: the model unpickled once per worker thread and sweep, kept by
    the hash of its bytes and the thread (a run changes the model's parameters and
    discrete state, so threads of one worker never share a copy)."""
    key = (hash(blob), threading.get_ident())
    if key not in _WORKER:
        while len(_WORKER) >= _KEPT:
            _WORKER.pop(next(iter(_WORKER)))
        _WORKER[key] = pickle.loads(blob)
    return _run_chunk(_WORKER[key], base, chunk, job)


def _fresh_chunk(blob, base, chunk, job):
    """For any Executor (threads, perhaps): a copy of the model per task."""
    return _run_chunk(pickle.loads(blob), base, chunk, job)


# -- executors ------------------------------------------------------------------------------
def _execute(compiled, runs, job, executor, progress, max_workers, retries=0) -> list:
    if isinstance(retries, bool) or not isinstance(retries, (int, np.integer)) or retries < 0:
        raise InvalidArgument(f"ensemble: retries must be a whole number >= 0, "
                              f"got {retries!r}")
    if max_workers is not None and (isinstance(max_workers, bool) or not isinstance(
            max_workers, (int, np.integer)) or max_workers < 1):
        raise InvalidArgument(f"ensemble: max_workers must be a whole number >= 1, "
                         f"got {max_workers!r}")
    base = compiled.p.copy()
    indexed = list(enumerate(runs))
    bar = _RunsBar.make(progress, len(runs))
    try:
        if executor is None:
            results = []
            for item in indexed:
                results += _run_chunk(compiled, base, [item], job)
                bar.update(1)
        elif _is_dask(executor):
            results = _on_dask(executor, compiled, base, indexed, job, bar, retries)
        elif executor == "processes":
            workers = int(max_workers or os.cpu_count() or 1)
            results = run_on_processes(_blob(compiled), base, job, indexed, workers,
                                       int(retries), bar.update)
        elif hasattr(executor, "submit"):
            results = _on_futures(executor, compiled, base, indexed, job, bar, retries)
        else:
            raise InvalidArgument(f"ensemble: executor must be None, 'processes', a "
                             f"concurrent.futures Executor or a dask Client, "
                             f"not {executor!r}")
    finally:
        compiled.p[:] = base
        bar.close()
    results.sort(key=lambda r: r[0])
    return [r[1:] for r in results]


def _chunks(indexed, workers):
    n = max(1, min(len(indexed), workers * _CHUNKS_PER_WORKER))
    return [indexed[k::n] for k in range(n)]


def _blob(compiled):
    try:
        return pickle.dumps(compiled, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception as err:  # noqa: BLE001 - whatever pickle raises, say what it needs
        raise TypeError(f"ensemble: this executor ships the compiled model by pickle, "
                        f"which failed: {type(err).__name__}: {err}") from err


def _on_futures(executor, compiled, base, indexed, job, bar, retries):
    from concurrent.futures import wait
    blob = _blob(compiled)
    workers = getattr(executor, "_max_workers", None) or os.cpu_count() or 1

    def submit(chunk):
        return executor.submit(_fresh_chunk, blob, base, chunk, job)
    return _gather(submit, _chunks(indexed, workers), lambda fs: wait(
        fs, return_when="FIRST_COMPLETED")[0], job, bar, retries)


_RESENT = 3      # times a run is sent again because the cluster lost what it needed


def _gather(submit, chunks, completed, job, bar, retries, refresh=None) -> list:
    """The (index, outcome) records of ``chunks`` submitted by ``submit(chunk)``, as
    they complete (``completed(futures)``: some that have), counted on the bar.  A chunk
    whose future fails (its worker died, the cluster lost it) costs only its own runs;
    the other chunks' results are kept.  The lost runs are run again up to ``retries``
    times, one at a time (a run that kills its worker then takes no other run with it),
    and then come back failed with the reason.  A chunk cancelled because the cluster
    lost the model (the workers that held it died) is no fault of its runs: the model is
    sent again (``refresh()``) and they are run again, up to :data:`_RESENT` times."""
    results, lost, resent = [], [], {}
    running = {submit(c): c for c in chunks}
    while running:
        for fut in completed(list(running)):
            chunk = running.pop(fut)
            part = _outcome(fut, chunk, lost)
            if part is None and refresh is None:
                lost += [(item, "the executor lost it") for item in chunk]
            elif part is None:
                again = [item for item in chunk
                         if resent.setdefault(item[0], 0) < _RESENT]
                for item in again:
                    resent[item[0]] += 1
                refresh()
                running.update({submit([item]): [item] for item in again})
                lost += [(item, "the cluster lost the model") for item in chunk
                         if item not in again]
                continue
            results += part or []
            bar.update(len(part or []))
    for _ in range(retries):
        again, lost = lost, []
        for item, _reason in again:
            while True:
                fut = submit([item])
                completed([fut])
                part = _outcome(fut, [item], lost)
                if part is not None or refresh is None or resent.get(item[0], 0) >= _RESENT:
                    break
                resent[item[0]] = resent.get(item[0], 0) + 1
                refresh()
            if part is None:
                lost.append((item, "the cluster lost the model"))
            results += part or []
            bar.update(len(part or []))
    for item, reason in lost:
        results.append((item[0], *failed(job, reason)))
        bar.update(1)
    return results


def _outcome(fut, chunk, lost):
    """The chunk's records; or [] with its runs added to ``lost`` with the reason; or
    None when the cluster cancelled it for lost dependencies (no fault of its runs)."""
    try:
        return fut.result()
    except Exception as err:  # noqa: BLE001 - one chunk's loss is its runs' result
        if "lost dependencies" in str(err):
            return None
        reason = f"{type(err).__name__}: {str(err)[:300]}"
        lost += [(item, reason) for item in chunk]
        return []


def _is_dask(executor) -> bool:
    return type(executor).__module__.startswith("distributed") and \
        hasattr(executor, "scatter")


def _on_dask(client, compiled, base, indexed, job, bar, retries):
    from distributed import wait
    data = _blob(compiled)
    # a key of its own (hash=False): scattered under the hash of its bytes, a model
    # swept twice shared one key, which the scheduler could release for the first sweep
    # while the second's tasks depended on it ("lost dependencies")
    blob = [client.scatter(data, broadcast=True, hash=False)]

    def refresh():
        # the workers that held it may have died with the runs that killed them
        if blob[0].status != "finished":
            blob[0].release()
            blob[0] = client.scatter(data, broadcast=True, hash=False)

    def submit(chunk):
        return client.submit(_dask_chunk, blob[0], base, chunk, job, pure=False)

    def completed(futures):
        try:
            return wait(futures, return_when="FIRST_COMPLETED").done
        except Exception:  # noqa: BLE001 - a cancelled future: its result says why
            return [f for f in futures if f.done()] or futures
    try:
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        return _gather(submit, _chunks(indexed, workers), completed, job, bar, retries,
                       refresh)
    finally:
        blob[0].release()


class _RunsBar:
    """Runs done, as a tqdm bar (``progress=None``: only when stderr is a terminal)."""

    def __init__(self, bar=None):
        self.bar = bar

    @classmethod
    def make(cls, progress, total, desc="runs"):
        """``total=None``: a count without an end (an optimizer's simulations)."""
        import sys
        if progress is False or (progress is None and not sys.stderr.isatty()):
            return cls()
        try:
            from tqdm.auto import tqdm
        except ImportError as err:
            raise ImportError("progress bars need tqdm: pip install 'acausal[progress]'") \
                from err
        return cls(tqdm(total=total, unit="run", desc=desc, leave=False))

    def update(self, n):
        if self.bar is not None:
            self.bar.update(n)

    def close(self):
        if self.bar is not None:
            self.bar.close()


# -- the Dataset ----------------------------------------------------------------------------
def _dataset(compiled, runs, times, names, outcomes):
    import xarray as xr
    meta = compiled.meta
    units, descriptions = meta.get("units", {}), meta.get("descriptions", {})
    data = {}
    for i, n in enumerate(names):
        data[n] = (("run", "time"), np.array([o[0][i] for o in outcomes]),
                   {"units": units.get(n, ""), "description": descriptions.get(n, "")})
    data["success"] = ("run", np.array([o[1] for o in outcomes], dtype=bool))
    data["message"] = ("run", np.array([o[2] for o in outcomes], dtype=object))
    data["steps"] = ("run", np.array([o[3] for o in outcomes], dtype=np.int64))
    swept = sorted({k for r in runs for k in r}, key=lambda k: (
        compiled.param_names.index(k) if k in compiled.param_names else 1 << 30, k))
    base = dict(zip(compiled.param_names, compiled.p))
    coords = {"run": np.arange(len(runs)), "time": ("time", times, {"units": "s"})}
    for k in swept:
        if not all(isinstance(r.get(k, 0.0), (int, float, np.number)) for r in runs):
            continue             # an input given as a function or a table: no coordinate
        coords[k] = ("run", np.array([float(r.get(k, base.get(k, np.nan))) for r in runs]),
                     {"units": units.get(k, "")})
    return xr.Dataset(data, coords=coords, attrs={"n_runs": len(runs),
                                                  "n_failed": int(sum(not o[1] for o in
                                                                      outcomes))})
