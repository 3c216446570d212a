"""Results in files and pictures: units, the Dymola/OpenModelica MAT file, HDF5, plots.

* :func:`declared_attributes`: the unit and description of every variable and parameter,
  as the components declare them (``ac.Variable(unit="V")``), by dotted name; ``der(x)``
  gets x's unit per second.
* :func:`write_mat`: the result file of Dymola and OpenModelica, MATLAB level 4,
  ``Aclass = ["Atrajectory", "1.1", "", "binTrans"]`` (the layout their readers, e.g.
  DyMat, ModelicaRes or OpenModelica's ``readSimulationResult``, expect):

  ================  ===================================================================
  ``name``          char, one column per variable (binTrans: transposed), ``time`` first
  ``description``   char, the same columns: "description [unit]"
  ``dataInfo``      int32, 4 x n_names: (matrix 1 or 2 (0 for time), +-column
                    (1-based; a minus sign: the negated column, an alias ``a = -b``),
                    0 (linear interpolation), -1 (undefined outside the time range)
  ``data_1``        float64, rows: time [t0, t_end], then each parameter and constant
                    variable [value, value]
  ``data_2``        float64, rows: time, then each distinct time series
  ================  ===================================================================

  An alias is no column of its own: its ``dataInfo`` points at the column of the variable
  it is equal to (or minus it).  A Boolean or Integer is a column of 0/1 or whole
  numbers whose description ends with Dymola's ``[:#(type=Boolean)]`` or
  ``[:#(type=Integer)]``.
* :func:`save_result` / :func:`load_result`: HDF5 (h5py, the ``io`` extra): time,
  values (points x names), names, units, descriptions, value types (a Boolean or
  Integer is loaded as a bool or int array), states, parameters, events, stats,
  success and message; a loaded result needs no model.
* :func:`plot_result`: one y-axis per unit, labelled with it, events marked.
* :class:`Keeping`: what a run keeps (``simulate``'s ``outputs=`` and ``store=``) and the
  result it gives.

The writers and the plot (:mod:`acausal.result_export`, what the methods of
:class:`~acausal.Result` call) and the streamed HDF5 file (:mod:`acausal.results_store`)
are modules of their own; this one reads the files back into results.
"""
from __future__ import annotations

import json
import os

import numpy as np

from .errors import InvalidArgument
from .result import Event, Result, _array_elements
from .result_export import FORMAT, plot_result, save_result, write_mat
from .results_store import ResultWriter, h5py_module, read
from .words import suggestion

__all__ = ["declared_attributes", "write_mat", "save_result", "load_result", "plot_result",
           "Keeping"]


# -- units and descriptions -------------------------------------------------------------
def declared_attributes(model) -> tuple[dict, dict]:
    """(units, descriptions) by dotted name, for every parameter and variable of the
    component tree ``model``; a declaration without a unit maps to "".  The dotted names
    are made here from the tree (as the compiler names them), so the tree need not have
    been bound by a compile in this process."""
    # the modelling language (30 ms to import): loading a result file needs none of it
    from .components.arrays import element_index, elements, shape_of
    from .components.declarations import Parameter
    units, descriptions = {}, {}
    stack = [("", model)]
    while stack:
        path, comp = stack.pop()
        stack.extend((f"{path}.{name}" if path else name, child)
                     for name, child in reversed(list(comp.children().items())))
        for name, decl in comp.declarations().items():
            full = f"{path}.{name}" if path else name
            if isinstance(decl, Parameter):
                units[full], descriptions[full] = decl.unit, decl.description
            else:
                attrs = comp.variable_attributes(name)
                units[full], descriptions[full] = attrs.unit, attrs.description
            if decl.shape is not None:      # the elements of an array: q[0], M[1,0] ...
                for idx in elements(shape_of(decl, comp, name)):
                    units[full + element_index(idx)] = units[full]
                    descriptions[full + element_index(idx)] = descriptions[full]
    return units, descriptions


# -- HDF5 ------------------------------------------------------------------------------
def _integer_keys(stats: dict) -> dict:
    """JSON made the integer keys of nested counts (BDF orders) strings: undo that."""
    return {k: ({int(a) if a.lstrip("-").isdigit() else a: b for a, b in v.items()}
                if isinstance(v, dict) else v) for k, v in stats.items()}


def _strings(ds) -> list:
    return [s.decode() if isinstance(s, bytes) else str(s) for s in ds[()]]


def _event(d) -> Event:
    return Event(d["time"], d["kind"], d["relations"], d["changes"], d["whens"],
                 d["reinits"])


def _result(parts: dict) -> Result:
    """The result of a file's parts (:func:`acausal.results_store.read`'s, or version 1's
    read here): its events as :class:`Event` records."""
    parts = dict(parts, stats=_integer_keys(parts["stats"]),
                 events=[_event(d) for d in parts["events"]],
                 state_switches=[_event(d) for d in parts["state_switches"]])
    return Result.from_table(parts.pop("t"), parts.pop("table"), **parts)


def load_result(path) -> Result:
    """A :class:`~acausal.Result` from a file written by ``Result.save``: ``res[name]``,
    ``res.t``, ``to_pandas``, ``plot`` ... work without the model (``res.compiled`` is
    None)."""
    h5py = h5py_module()
    with h5py.File(path, "r") as fh:
        if fh.attrs.get("format") != FORMAT:
            raise ValueError(f"{path}: not a result saved by acausal (Result.save)")
        version = int(fh.attrs.get("version", 1))
    if version >= 2:
        return _result(read(path))
    with h5py.File(path, "r") as fh:
        t = fh["time"][()]
        values = fh["values"][()]
        names = _strings(fh["names"])
        units = dict(zip(names, _strings(fh["units"])))
        types = dict(zip(names, _strings(fh["types"]))) if "types" in fh else {}
        descriptions = dict(zip(names, _strings(fh["descriptions"])))
        pnames = _strings(fh["parameter_names"])
        units.update(json.loads(fh.attrs["parameter_units"]))
        descriptions.update(json.loads(fh.attrs["parameter_descriptions"]))
        return _result(dict(
            t=t, table={n: values[:, k] for k, n in enumerate(names)},
            stats=json.loads(fh.attrs["stats"]), events=json.loads(fh.attrs["events"]),
            success=bool(fh.attrs["success"]), message=str(fh.attrs["message"]),
            parameters=fh["parameter_values"][()], parameter_names=pnames, units=units,
            descriptions=descriptions, _states=json.loads(fh.attrs["states"]),
            value_types={n: k for n, k in types.items() if k != "Real"},
            state_switches=json.loads(fh.attrs["state_switches"])))


# -- what a run keeps ----------------------------------------------------------------------
class _Held:
    """The driver's sink of a run held in memory: its points in blocks of arrays (one
    row of the solver's unknowns a point, no derivatives): some 8 bytes a value, where
    a list of a point's arrays cost 100 bytes more for each, twice."""

    def __init__(self):
        self.t, self.z, self.index, self.values = [], [], [], []

    def add(self, t, z, index, values, snapshots) -> None:
        self.t.append(np.asarray(t, dtype=float))
        self.z.append(np.asarray(z, dtype=float).reshape(len(t), -1))
        self.index += list(index)
        self.values += list(values)

    def points(self, n):
        """(t, z, index, values) of every point, as arrays."""
        if not self.t:
            return np.zeros(0), np.zeros((0, n)), [], []
        t = np.concatenate(self.t)
        self.t = []
        z = np.concatenate(self.z) if len(self.z) > 1 else self.z[0]
        self.z = []
        return t, z, self.index, self.values


class Keeping:
    """What a run keeps (``simulate``'s ``outputs=`` and ``store=``): every output in
    memory (the default), the outputs asked for (``names``; the states' values are
    kept too, from which they are computed), or those in a file written as the run
    goes (``writer``, the driver's sink; the result returned reads the file).  A run
    held in memory keeps its points in blocks as it goes (:class:`_Held`)."""

    def __init__(self, names=None, writer=None):
        self.names, self.writer = names, writer
        self.held = _Held() if writer is None else None

    @classmethod
    def make(cls, compiled, outputs=None, store=None) -> "Keeping":
        names = None
        if outputs is not None:
            if isinstance(outputs, str) or not all(isinstance(n, str) for n in outputs):
                raise InvalidArgument(f"simulate: outputs must be a list of variable "
                                      f"names, got {outputs!r}")
            names = list(dict.fromkeys(x for n in outputs for x in _resolve(compiled, n)))
        writer = None
        if store is not None:
            folder = os.path.dirname(os.path.abspath(os.fspath(store)))
            if not os.path.isdir(folder):
                raise InvalidArgument(f"simulate: store={os.fspath(store)!r}: the "
                                      f"directory {folder} does not exist")
            writer = ResultWriter(store, compiled, names)
        return cls(names, writer)

    @property
    def sink(self):
        return self.writer if self.writer is not None else self.held

    def result(self, compiled, t, z, stats, events, success, message, discrete=(),
               index=(), switches=(), delayed=()):
        """The run's Result: in memory (its outputs restricted to ``names``), or read
        from the file the writer finishes now."""
        if self.writer is None:
            if self.held.t:                # the points the driver handed over as it went
                t, z, index, delayed = self.held.points(compiled.n)
            res = Result(compiled, t, z, stats, events, success, message, discrete, index,
                         state_switches=switches, delay_values=delayed)
            if self.names is not None:
                res._keep(self.names)
            return res
        self.writer.add(t, z, index, delayed, discrete)     # points not streamed yet
        meta = compiled.meta
        self.writer.finish(states=compiled.states, events=events, state_switches=switches,
                           stats=stats.as_dict() if hasattr(stats, "as_dict")
                           else dict(stats or {}), success=success, message=message,
                           parameter_names=compiled.param_names, parameters=compiled.p,
                           units=meta.get("units", {}),
                           descriptions=meta.get("descriptions", {}))
        return _result(read(self.writer.path))

    def abandon(self) -> None:
        if self.writer is not None:
            self.writer.close()


def _resolve(compiled, name) -> list:
    """The output names ``name`` stands for: itself, a signal port's value, or the
    elements of an array; InvalidArgument (with "did you mean") otherwise."""
    outputs = compiled.outputs
    if name in outputs:
        return [name]
    if f"{name}.signal" in outputs:
        return [f"{name}.signal"]
    array = _array_elements(name, outputs)
    if array is not None:
        return list(array[1])
    raise InvalidArgument(f"simulate: outputs: the model has no variable {name!r}"
                          f"{suggestion(name, outputs)}")
