"""Results in HDF5 written as they are computed, and read one variable at a time.

A run of a million points of a model with a thousand outputs is 8 GB of numbers: more
than is worth holding at once, and more than a reader of one variable needs.  So a
result file (format ``acausal-result`` version 2) keeps one row per distinct series of
values -- an alias ``a = b`` or ``a = -b`` points at its original's row with a sign, a
constant has its value -- in a dataset ``series`` of shape (rows, points), chunked as
(1, :data:`BLOCK`): a block of points is written as whole chunks, and one variable is
read as one row, in ``BLOCK``-point chunks, without touching the others.

* :class:`ResultWriter` computes the outputs of a block of points (only those kept:
  every output, or those ``simulate(..., outputs=[...])`` asked for) from the solver's
  unknowns (:func:`acausal.runtime.outputs.evaluate`) and appends them.  It is the sink
  of ``simulate(..., store="run.h5")``, fed by the driver as the run goes (memory: a
  block, not the run), and what ``Result.save`` writes with.
* :func:`read` gives a :class:`~acausal.Result` whose variables are read from the file
  when first asked for (``res["C1.v"]``), and kept.

Datasets: ``time`` (points), ``series`` (rows x points), ``names``, ``row`` (each name's
row, -1 for a constant), ``sign`` (+-1), ``constant``, ``units``, ``descriptions``,
``types`` (Real, Boolean or Integer: read as float, bool or int64 arrays),
``parameter_names``, ``parameter_values``; attributes as in version 1 (states, events,
state switches, parameter units and descriptions, stats, success, message).  Version 1
(``values``: points x names) is still read by :func:`acausal.load_result`.
"""
from __future__ import annotations

import json
from collections.abc import Mapping

import numpy as np

from .runtime.outputs import evaluate, expand_points

__all__ = ["ResultWriter", "read", "write", "h5py_module", "BLOCK", "VERSION"]

FORMAT, VERSION = "acausal-result", 2
BLOCK = 8192          # points per chunk of a series, and per block a writer computes


def h5py_module():
    """h5py (the ``io`` extra), or an ImportError that says how to install it."""
    try:
        import h5py
    except ImportError as err:
        raise ImportError("saving and loading results needs h5py: "
                          "pip install 'acausal[io]'") from err
    return h5py


class ResultWriter:
    """Writes a run of ``compiled`` to ``path`` block by block: :meth:`add` points as
    they come (the driver's sink), :meth:`finish` with what the run said.  ``names``:
    the outputs to keep (default: all)."""

    def __init__(self, path, compiled, names=None):
        h5py = h5py_module()
        self.path, self.compiled = str(path), compiled
        names = sorted(compiled.outputs) if names is None else list(names)
        self.names = names
        rows, self.cols, row, sign, const = {}, [], [], [], []
        for n in names:
            s, k = compiled.outputs[n]
            if s is None:
                row.append(-1)
                sign.append(1.0)
                const.append(float(k(compiled.p) if callable(k) else k))
                continue
            if k not in rows:
                rows[k] = len(self.cols)
                self.cols.append(k)
            row.append(rows[k])
            sign.append(float(s))
            const.append(0.0)
        self.file = fh = h5py.File(self.path, "w")
        text = h5py.string_dtype()
        fh.attrs["format"], fh.attrs["version"] = FORMAT, VERSION
        self.time = fh.create_dataset("time", shape=(0,), maxshape=(None,), dtype=float,
                                      chunks=(BLOCK,))
        self.series = fh.create_dataset("series", shape=(len(self.cols), 0),
                                        maxshape=(len(self.cols), None), dtype=float,
                                        chunks=(1, BLOCK) if self.cols else None)
        meta = compiled.meta
        units, descriptions = meta.get("units", {}), meta.get("descriptions", {})
        fh.create_dataset("names", data=np.array(names, dtype=object), dtype=text)
        fh.create_dataset("row", data=np.array(row, dtype=np.int64))
        fh.create_dataset("sign", data=np.array(sign, dtype=float))
        fh.create_dataset("constant", data=np.array(const, dtype=float))
        fh.create_dataset("units", dtype=text,
                          data=np.array([units.get(n, "") for n in names], dtype=object))
        fh.create_dataset("descriptions", dtype=text, data=np.array(
            [descriptions.get(n, "") for n in names], dtype=object))
        kinds = meta.get("value_types", {})        # Real, Boolean, Integer (read typed)
        fh.create_dataset("types", dtype=text, data=np.array(
            [kinds.get(n, "Real") for n in names], dtype=object))
        self.n = 0
        self._pending = []          # (t, z, m, delayed) blocks not written yet
        self._held = 0
        self.parameters = compiled.p.copy()

    # -- points in --------------------------------------------------------------------
    def add(self, t, z, index, values, snapshots) -> None:
        """Points of the run: times ``t``, unknowns ``z`` (a row each), the discrete
        state of each (``snapshots[index[k]]``), the delayed values recorded at each
        (``values``, for a model with delays)."""
        t = np.asarray(t, dtype=float)
        if not len(t):
            return
        if len(index):          # the snapshots these points were integrated in, only
            used, inverse = np.unique(np.asarray(index, dtype=np.int64), return_inverse=True)
            rows = np.array([snapshots[i] for i in used], dtype=float).reshape(len(used), -1)
            m = rows[inverse]
        else:
            m = np.zeros((len(t), 0))
        delayed = np.asarray(values, dtype=float) if len(values) else None
        self._pending.append((t, np.asarray(z, dtype=float).reshape(len(t), -1), m,
                              delayed))
        self._held += len(t)
        while self._held >= BLOCK:
            self._write(BLOCK)

    def _take(self, count):
        """The first ``count`` pending points as one block."""
        parts, left = [], count
        while left:
            t, z, m, d = self._pending[0]
            if len(t) <= left:
                parts.append(self._pending.pop(0))
                left -= len(t)
            else:
                parts.append((t[:left], z[:left], m[:left], None if d is None else d[:left]))
                self._pending[0] = (t[left:], z[left:], m[left:], None if d is None
                                    else d[left:])
                left = 0
        self._held -= count
        return (np.concatenate([p[0] for p in parts]), np.vstack([p[1] for p in parts]),
                np.vstack([p[2] for p in parts]),
                None if parts[0][3] is None else np.vstack([p[3] for p in parts]))

    def _write(self, count) -> None:
        t, z, m, delayed = self._take(count)
        lo, hi = self.n, self.n + len(t)
        self.time.resize((hi,))
        self.time[lo:hi] = t
        if self.cols:
            values = evaluate(self.compiled, self.cols, t, z, self.parameters, m,
                              np.arange(len(t)), delayed)
            self.series.resize((len(self.cols), hi))
            self.series[:, lo:hi] = np.array(values)
        self.n = hi

    def write_result(self, res) -> None:
        """The points of an in-memory result (``Result.save``), block by block."""
        index = np.asarray(res._discrete_index, dtype=np.int64)
        known = len(index) == len(res.t) and bool(res._discrete)
        self.parameters = res.parameters.copy()
        if not known and self.compiled.code.expand is not None:
            # no modes recorded: each block's values as the result computes them
            for lo in range(0, len(res.t), BLOCK):
                hi = min(len(res.t), lo + BLOCK)
                self._write_values(res.t[lo:hi], _columns_of(res, self.cols, lo, hi))
            return
        for lo in range(0, len(res.t), BLOCK):
            hi = min(len(res.t), lo + BLOCK)
            d = None if res._delayed is None else res._delayed[lo:hi]
            self.add(res.t[lo:hi], res._z[lo:hi], index[lo:hi] if known else (),
                     d if d is not None else (), res._discrete)

    def _write_values(self, t, values) -> None:
        lo, hi = self.n, self.n + len(t)
        self.time.resize((hi,))
        self.time[lo:hi] = t
        if self.cols:
            self.series.resize((len(self.cols), hi))
            self.series[:, lo:hi] = np.array(values)
        self.n = hi

    # -- the end ------------------------------------------------------------------------
    def finish(self, *, states, events, state_switches, stats, success, message,
               parameter_names, parameters, units, descriptions) -> None:
        """Write the points still held and what the run said; close the file."""
        try:
            if self._held:
                self._write(self._held)
            fh = self.file
            text = h5py_module().string_dtype()
            fh.create_dataset("parameter_names", dtype=text,
                              data=np.array(parameter_names, dtype=object))
            fh.create_dataset("parameter_values",
                              data=np.asarray(parameters, float)[:len(parameter_names)])
            fh.attrs["states"] = json.dumps(list(states))
            fh.attrs["events"] = json.dumps([e.as_dict() for e in events])
            fh.attrs["state_switches"] = json.dumps([e.as_dict() for e in state_switches])
            fh.attrs["parameter_units"] = json.dumps(
                {n: units.get(n, "") for n in parameter_names})
            fh.attrs["parameter_descriptions"] = json.dumps(
                {n: descriptions.get(n, "") for n in parameter_names})
            fh.attrs["stats"] = json.dumps(stats, default=_jsonable)
            fh.attrs["success"] = bool(success)
            fh.attrs["message"] = str(message)
        finally:
            self.close()

    def close(self) -> None:
        if self.file is not None:
            self.file.close()
            self.file = None


def _columns_of(res, cols, lo, hi) -> list:
    """The outputs ``cols`` of an in-memory result at its points lo:hi, as it reads
    them (a result without recorded modes settles each point's own)."""
    y = expand_points(res.compiled, res.t[lo:hi], res._z[lo:hi], res.parameters, (), (),
                None if res._delayed is None else res._delayed[lo:hi])
    return [y[:, k] for k in cols]


def _jsonable(x):
    if isinstance(x, np.generic):
        return x.item()
    return str(x)


def write(res, path) -> None:
    """``res`` (a Result of a compiled model) as a version-2 file at ``path``."""
    writer = ResultWriter(path, res.compiled, res.names)
    try:
        writer.write_result(res)
        writer.finish(states=res.states, events=res.events,
                      state_switches=res.state_switches, stats=res.stats,
                      success=res.success, message=res.message,
                      parameter_names=res.parameter_names, parameters=res.parameters,
                      units=res.units, descriptions=res.descriptions)
    except BaseException:
        writer.close()
        raise


# -- reading ------------------------------------------------------------------------------
class _Series(Mapping):
    """name -> values, read from the file when first asked for (and kept)."""

    def __init__(self, path, names, row, sign, const, n):
        self.path, self.n = path, n
        self.where = {name: (int(r), float(s), float(c))
                      for name, r, s, c in zip(names, row, sign, const)}
        self.read = {}

    def __getitem__(self, name):
        out = self.read.get(name)
        if out is None:
            r, s, c = self.where[name]
            if r < 0:
                out = np.full(self.n, c)
            else:
                with h5py_module().File(self.path, "r") as fh:
                    out = fh["series"][r, :]
                if s != 1.0:
                    out = s * out
            self.read[name] = out
        return out

    def __iter__(self):
        return iter(self.where)

    def __len__(self):
        return len(self.where)

    def __contains__(self, name):
        return name in self.where


def _strings(ds) -> list:
    return [s.decode() if isinstance(s, bytes) else str(s) for s in ds[()]]


def read(path) -> dict:
    """The parts of a version-2 file, as :meth:`acausal.Result.from_table` takes them
    (events as dicts; ``table`` reads a variable when it is first asked for):
    :func:`acausal.results_io.load_result` makes the result."""
    h5py = h5py_module()
    with h5py.File(path, "r") as fh:
        t = fh["time"][()]
        names = _strings(fh["names"])
        table = _Series(str(path), names, fh["row"][()], fh["sign"][()],
                        fh["constant"][()], len(t))
        units = dict(zip(names, _strings(fh["units"])))
        descriptions = dict(zip(names, _strings(fh["descriptions"])))
        kinds = dict(zip(names, _strings(fh["types"])))
        pnames = _strings(fh["parameter_names"])
        units.update(json.loads(fh.attrs["parameter_units"]))
        descriptions.update(json.loads(fh.attrs["parameter_descriptions"]))
        return dict(
            t=t, table=table, stats=json.loads(fh.attrs["stats"]),
            events=json.loads(fh.attrs["events"]),
            success=bool(fh.attrs["success"]), message=str(fh.attrs["message"]),
            parameters=fh["parameter_values"][()], parameter_names=pnames, units=units,
            descriptions=descriptions, _states=json.loads(fh.attrs["states"]),
            value_types={n: k for n, k in kinds.items() if k != "Real"},
            state_switches=json.loads(fh.attrs["state_switches"]))
