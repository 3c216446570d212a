"""A result exported: the MAT file of Dymola and OpenModelica, HDF5, a plot.

What :meth:`Result.to_mat`, :meth:`Result.save` and :meth:`Result.plot` write (the
formats are described in :mod:`acausal.results_io`, which reads them back).  These read
a result through its public face only (``res.t``, ``res[name]``, its units and events),
so a result of a run and a loaded one are written alike.
"""
from __future__ import annotations

import json

import numpy as np

from .results_store import h5py_module, write

__all__ = ["write_mat", "save_result", "plot_result", "FORMAT", "VERSION_1"]

# the HDF5 file of a loaded result (no model to compute its outputs from): version 1,
# values (points x names); a result of a run is written in results_store's version 2
FORMAT = "acausal-result"
VERSION_1 = 1


# -- the Dymola / OpenModelica result file ------------------------------------------------
def _char_columns(strings) -> np.ndarray:
    """Strings as a transposed char matrix (one string per column, padded with blanks).
    A level-4 char is one byte: text is stored as its UTF-8 bytes, as Modelica tools
    write it (readers decode the bytes as UTF-8)."""
    strings = [s.encode("utf-8").decode("latin-1") for s in strings]
    width = max([len(s) for s in strings] + [1])
    rows = np.full((len(strings), width), " ", dtype="<U1")
    for i, s in enumerate(strings):
        rows[i, :len(s)] = list(s)
    return rows.T.copy()


def _mat_layout(res, names):
    """(entries, data_1, data_2): entries are (name, description, matrix, signed
    column) with time first; aliases share their original's column."""
    t = res.t
    series, constants, entries = [t], [np.array([t[0], t[-1]])], [("time", "Time [s]", 0, 1)]
    by_key = {}
    outputs = res.compiled.outputs if res.compiled is not None else None
    res._prefetch(names)
    for name, value in res.parameter_values.items():
        constants.append(np.array([value, value]))
        entries.append((name, _description(res, name), 1, len(constants)))
    for name in names:
        desc = _description(res, name)
        sign, key = (outputs[name] if outputs is not None else (1.0, name))
        values = np.asarray(res[name], dtype=float)    # Booleans as 0/1, as Dymola
        if sign is None:                       # a constant of the model: data_1
            constants.append(np.array([values[0], values[-1]]))
            entries.append((name, desc, 1, len(constants)))
            continue
        if key not in by_key:                  # store the solver's column once:
            series.append(sign * values)       # values = sign * column, sign = +-1
            by_key[key] = len(series)
        entries.append((name, desc, 2, int(by_key[key] * sign)))
    return entries, np.array(constants), np.array(series)


def _description(res, name) -> str:
    """"description [unit]"; a Boolean's or Integer's with Dymola's type mark
    ``[:#(type=Boolean)]``, which its readers use to restore the type."""
    text, unit = res.descriptions.get(name, ""), res.units.get(name, "")
    text = f"{text} [{unit}]" if unit else text
    kind = res.value_types.get(name)
    return f"{text} [:#(type={kind})]".lstrip() if kind else text


def write_mat(res, path, names=None) -> None:
    """Write ``res`` as a Dymola/OpenModelica result file (module docstring); ``names``:
    the variables (default: all)."""
    from scipy.io import savemat
    names = res.names if names is None else list(names)
    if not len(res.t):
        raise ValueError("write_mat: the result has no points")
    entries, data_1, data_2 = _mat_layout(res, names)
    info = np.array([[m, c, 0, -1 if m != 1 else 0] for _, _, m, c in entries],
                    dtype=np.int32)
    info[0] = (0, 1, 0, -1)                     # time: the abscissa of every matrix
    aclass = np.array([list(s.ljust(11)) for s in ("Atrajectory", "1.1", "", "binTrans")],
                      dtype="<U1")
    savemat(path, {"Aclass": aclass,
                   "name": _char_columns([e[0] for e in entries]),
                   "description": _char_columns([e[1] for e in entries]),
                   "dataInfo": info.T.copy(),
                   "data_1": data_1,
                   "data_2": data_2},
            format="4", oned_as="row")


# -- HDF5 ------------------------------------------------------------------------------
def save_result(res, path) -> None:
    """Everything :func:`load_result` needs, in one HDF5 file: a result of a compiled
    model in :mod:`acausal.results_store`'s layout (one row per series, written a block
    of points at a time, read one variable at a time); a loaded one as it holds it."""
    if res.compiled is not None:
        write(res, path)
        return
    h5py = h5py_module()
    names = res.names
    values = np.column_stack([res[n] for n in names]) if names else \
        np.zeros((len(res.t), 0))
    text = h5py.string_dtype()
    with h5py.File(path, "w") as fh:
        fh.attrs["format"], fh.attrs["version"] = FORMAT, VERSION_1
        fh.create_dataset("time", data=res.t)
        fh.create_dataset("values", data=values)
        fh.create_dataset("names", data=np.array(names, dtype=object), dtype=text)
        fh.create_dataset("units", data=np.array([res.units.get(n, "") for n in names],
                                                 dtype=object), dtype=text)
        fh.create_dataset("descriptions", dtype=text, data=np.array(
            [res.descriptions.get(n, "") for n in names], dtype=object))
        fh.create_dataset("types", dtype=text, data=np.array(       # Real, Boolean, Integer
            [res.value_types.get(n, "Real") for n in names], dtype=object))
        fh.create_dataset("parameter_names", dtype=text,
                          data=np.array(res.parameter_names, dtype=object))
        # the named parameters only (a model with delays keeps its delayed values after them)
        fh.create_dataset("parameter_values",
                          data=np.asarray(res.parameters, float)[:len(res.parameter_names)])
        fh.attrs["states"] = json.dumps(res.states)
        fh.attrs["events"] = json.dumps([e.as_dict() for e in res.events])
        fh.attrs["state_switches"] = json.dumps([e.as_dict() for e in res.state_switches])
        fh.attrs["parameter_units"] = json.dumps(
            {n: res.units.get(n, "") for n in res.parameter_names})
        fh.attrs["parameter_descriptions"] = json.dumps(
            {n: res.descriptions.get(n, "") for n in res.parameter_names})
        fh.attrs["stats"] = json.dumps(res.stats, default=_jsonable)
        fh.attrs["success"] = bool(res.success)
        fh.attrs["message"] = str(res.message)


def _jsonable(x):
    if isinstance(x, np.generic):
        return x.item()
    return str(x)


# -- plots -------------------------------------------------------------------------------
def plot_result(res, names, ax=None, path=None, events=True, subplots=False):
    """See :meth:`acausal.Result.plot`."""
    try:
        import matplotlib
        if path is not None and ax is None:
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as err:
        raise ImportError("Result.plot needs matplotlib: pip install 'acausal[plot]'") from err
    groups = {}
    for n in names:
        groups.setdefault(res.units.get(n, ""), []).append(n)
    if subplots and len(groups) > 1:
        if ax is not None:
            raise ValueError("Result.plot: give ax or subplots=True, not both")
        fig, axes = plt.subplots(len(groups), 1, sharex=True,
                                 figsize=(7, 2.2 + 1.6 * len(groups)))
        axes = list(np.atleast_1d(axes))
    else:
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 4))
        axes = [ax] + [ax.twinx() for _ in list(groups)[1:]]
        for k, extra in enumerate(axes[2:], start=1):
            extra.spines["right"].set_position(("axes", 1.0 + 0.14 * k))
    colors = plt.rcParams["axes.prop_cycle"].by_key().get("color", ["C0"])
    lines = []
    for k, ((unit, members), a) in enumerate(zip(groups.items(), axes)):
        for n in members:
            lines += a.plot(res.t, res[n], label=n, color=colors[len(lines) % len(colors)])
        label = ", ".join(members) if len(members) <= 3 else f"{len(members)} variables"
        a.set_ylabel(f"{label} [{unit or '1'}]")
    if events:
        for a in (axes if subplots else axes[:1]):
            for te in res.event_times:
                a.axvline(te, color="0.6", lw=0.7, ls="--", zorder=0)
    axes[-1 if subplots else 0].set_xlabel("time [s]")
    axes[0].legend(lines, [ln.get_label() for ln in lines], loc="best", fontsize="small")
    axes[0].grid(True, alpha=0.3)
    if path is not None:
        axes[0].figure.savefig(path, dpi=120, bbox_inches="tight")
    return axes[0] if len(axes) == 1 else axes
