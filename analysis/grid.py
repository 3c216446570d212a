"""Linear models over a grid of parameter values, on the engine of :mod:`acausal.sweeps`.

``linearize_grid(model, {"load.J": [...], "shaft.c": [...]}, inputs=[...],
outputs=[...], at="steady")`` linearizes the model (:func:`acausal.linearize`) once per
point of the grid -- every combination (``grid="product"``) or the lists side by side
(``"zip"``) -- serially, on local processes or on a dask cluster (``executor``, as for
:func:`acausal.sweep`), and gathers A, B, C, D and the poles into one
``xarray.Dataset`` with dimensions ``run``, ``state``, ``input``, ``output`` (and
``pole``), the swept parameters as coordinates along ``run``, and per run ``success``
and ``message``: a point where no operating point is found keeps NaN and its reason,
and never loses the others.  The operating point is the same description at every
point (``None``: the start values, ``"steady"``, or a dict of states and inputs); a
simulated ``(result, t)`` belongs to one parameter set and is refused.
"""
from __future__ import annotations

import itertools
import warnings

import numpy as np

__all__ = ["linearize_grid"]


def linearize_grid(model, parameters: dict, *, inputs=(), outputs=(), at=None,
                   t: float = 0.0, grid: str = "product", executor=None,
                   progress: bool | None = None, max_workers: int | None = None):
    """A Dataset of the linearizations of ``model`` over a parameter grid (module
    docstring)."""
    from ..simulation import compile
    from ..sweeps import _execute
    if isinstance(at, tuple):
        raise ValueError("linearize_grid: 'at' must be None, 'steady' or a dict: a "
                         "simulated (result, t) holds for one set of parameters only")
    runs = _grid(parameters, grid)
    compiled = compile(model)
    unknown = sorted({k for r in runs for k in r} - set(compiled.param_names))
    if unknown:                       # a mistake in the call: the model's own error
        compiled.set_parameters({unknown[0]: 1.0})
    # the shapes and names, from the model at its own values (also checks the names)
    from .linearize import linearize
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            probe = linearize(compiled, inputs, outputs, at, t=t)
        except (ValueError, ArithmeticError):
            probe = None
    job = {"task": _linearize_one, "inputs": list(inputs), "outputs": list(outputs),
           "at": at, "t": float(t)}
    outcomes = _execute(compiled, runs, job, executor, progress, max_workers)
    ok = [o for o in outcomes if o[1]]
    if probe is None and not ok:
        raise ValueError("linearize_grid: no point of the grid could be linearized; "
                         f"the first says: {outcomes[0][2]}")
    shape = probe if probe is not None else ok[0][0]
    return _dataset(compiled, runs, outcomes, shape)


def _grid(parameters, grid) -> list:
    if not isinstance(parameters, dict) or not parameters:
        raise ValueError("linearize_grid: parameters must be a non-empty dict {name: values}")
    keys = list(parameters)
    columns = [np.atleast_1d(np.asarray(parameters[k], dtype=float)) for k in keys]
    if grid == "product":
        combos = itertools.product(*columns)
    elif grid == "zip":
        if len({len(c) for c in columns}) != 1:
            raise ValueError("linearize_grid: grid='zip' needs lists of equal length")
        combos = zip(*columns)
    else:
        raise ValueError(f"linearize_grid: grid must be 'product' or 'zip', not {grid!r}")
    return [{k: float(v) for k, v in zip(keys, combo)} for combo in combos]


def _linearize_one(compiled, values, job):
    """(StateSpace or None, success, message, 0) at one point of the grid."""
    from .linearize import linearize
    try:
        compiled.set_parameters(values)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ss = linearize(compiled, job["inputs"], job["outputs"], job["at"], t=job["t"])
    except Exception as err:  # noqa: BLE001 - any failure of one point is that point's result
        return None, False, f"{type(err).__name__}: {err}", 0
    return ss, True, "", 0


def _dataset(compiled, runs, outcomes, shape):
    import xarray as xr
    n, m, q = len(shape.states), len(shape.inputs), len(shape.outputs)
    arrays = {k: np.full((len(runs),) + dims, np.nan) for k, dims in
              (("A", (n, n)), ("B", (n, m)), ("C", (q, n)), ("D", (q, m)))}
    poles = np.full((len(runs), n), np.nan + 0j)
    for i, (ss, ok, _, _) in enumerate(outcomes):
        if ok:
            for k in arrays:
                arrays[k][i] = getattr(ss, k)
            poles[i] = np.sort_complex(np.linalg.eigvals(ss.A)) if n else poles[i]
    data = {"A": (("run", "state", "state_from"), arrays["A"]),
            "B": (("run", "state", "input"), arrays["B"]),
            "C": (("run", "output", "state_from"), arrays["C"]),
            "D": (("run", "output", "input"), arrays["D"]),
            "poles": (("run", "pole"), poles),
            "success": ("run", np.array([o[1] for o in outcomes], dtype=bool)),
            "message": ("run", np.array([o[2] for o in outcomes], dtype=object))}
    base = dict(zip(compiled.param_names, compiled.p))
    coords = {"run": np.arange(len(runs)), "state": list(shape.states),
              "state_from": list(shape.states), "input": list(shape.inputs),
              "output": list(shape.outputs), "pole": np.arange(n)}
    for k in sorted({k for r in runs for k in r}):
        coords[k] = ("run", np.array([float(r.get(k, base.get(k, np.nan))) for r in runs]))
    return xr.Dataset(data, coords=coords,
                      attrs={"n_runs": len(runs),
                             "n_failed": int(sum(not o[1] for o in outcomes))})
