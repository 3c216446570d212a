"""Result: the time series of every variable of a simulation, by dotted name.

A result is read by name (``res["C1.v"]``), exported to the data tools of the Python
ecosystem (:meth:`Result.to_pandas`, :meth:`Result.to_xarray`, :meth:`Result.to_csv`),
to the result file of Dymola and OpenModelica (:meth:`Result.to_mat`), saved and loaded
(:meth:`Result.save`, :func:`acausal.load_result`: :mod:`acausal.results_io`),
and plotted with units (:meth:`Result.plot`).  Its events are :class:`Event` records.
"""
from __future__ import annotations

import csv

import numpy as np

from .result_export import plot_result, save_result, write_mat
from .runtime.outputs import evaluate, expand_points, pointwise
from .words import listed, shortened, suggestion

__all__ = ["Result", "Event"]


class Event(float):
    """One event of a run: a float equal to its time, with what happened then.

    ``kind``: ``"relation"`` (a relation crossed zero: a state event), ``"time"`` (a
    relation of time alone switched where it was predicted), ``"when"`` (a when-clause
    fired, at a crossing or a time event) or ``"state switch"`` (dynamic state selection
    chose other states; these are in ``Result.state_switches``, not ``Result.events``).
    ``relations``: the texts of the relations that crossed, each with the equation and
    component it is in; ``changes``: ``(text, before, after)`` for every relation
    (1.0 true, 0.0 false) or frozen integer value the event changed; ``whens``: the
    when-clauses that fired (text and component); ``reinits``: ``(variable, before,
    after)`` for every state a ``reinit`` restarted.  Being a float keeps code that
    reads event times working: ``np.array(res.events)``, ``res.events[0] - t``.
    """

    def __new__(cls, time, kind, relations=(), changes=(), whens=(), reinits=()):
        ev = super().__new__(cls, time)
        ev.kind = str(kind)
        ev.relations = list(relations)
        ev.changes = [tuple(c) for c in changes]
        ev.whens = list(whens)
        ev.reinits = [tuple(r) for r in reinits]
        return ev

    @property
    def time(self) -> float:
        return float(self)

    @property
    def components(self) -> list:
        """The components whose relations or when-clauses took part (sorted)."""
        found = {_component_of(s) for s in self.relations + self.whens
                 + [c[0] for c in self.changes]}
        return sorted(c for c in found if c)

    def as_dict(self) -> dict:
        return {"time": self.time, "kind": self.kind, "relations": list(self.relations),
                "changes": [list(c) for c in self.changes], "whens": list(self.whens),
                "reinits": [list(r) for r in self.reinits]}

    def __reduce__(self):
        return (Event, (self.time, self.kind, self.relations, self.changes, self.whens,
                        self.reinits))

    def __repr__(self):
        """One line of bounded length: each relation's text shortened, at most a few
        changes (the whole texts are in ``relations`` and ``changes``)."""
        what = [f"{shortened(t, 100)}: {_fmt(a)} -> {_fmt(b)}" for t, a, b in self.changes]
        what += [f"reinit({v}): {_fmt(a)} -> {_fmt(b)}" for v, a, b in self.reinits]
        more = f"; and {len(what) - 4} more" if len(what) > 4 else ""
        return f"Event(t={self.time:.10g}, {self.kind}" + \
            (f"; {'; '.join(what[:4])}{more})" if what else ")")


def _fmt(x) -> str:
    return f"{x:.6g}" if isinstance(x, float) else str(x)


def _component_of(text: str) -> str:
    """The component named at the end of a relation's or when-clause's text ("... [R1
    (Resistor)]"), or "" (the model itself, or no component named)."""
    text = text.rstrip()
    if not (text.endswith("]") and "[" in text):
        return ""
    name = text[text.rindex("[") + 1:-1].split(" (")[0]
    return "" if name == "(model)" else name


def _array_elements(name: str, known):
    """(shape, element names) of the array variable ``name`` or ``der(name)``, or None."""
    # the modelling language (30 ms to import): a result read from a file needs none of it
    from .components.arrays import array_of_name
    if name.startswith("der(") and name.endswith(")"):
        found = array_of_name(name[4:-1], {n[4:-1] for n in known
                                           if n.startswith("der(") and n.endswith(")")})
        return found and (found[0], [f"der({n})" for n in found[1]])
    return array_of_name(name, known)


class Result:
    """What ``acausal.simulate`` returns.

    ``res.t`` (times), ``res["C1.v"]`` (any variable, alias or not, and ``der(x)`` of the
    states; an array variable by element, ``res["q[2]"]``, or whole, ``res["q"]``, of
    shape time x the array's shape), ``res.names``, ``res.units`` / ``res.descriptions`` (by name, "" where none
    was declared), ``res.stats`` (solver statistics), ``res.events`` (:class:`Event`
    records, floats equal to their times), ``res.event_times`` (an array),
    ``res.success`` / ``res.message`` (a failed run keeps what it computed).  A result
    loaded from a file (``ac.load_result``) has ``compiled = None`` and holds every
    variable's values itself.
    """

    def __init__(self, compiled, t, y, stats=None, events=(), success=True, message="",
                 discrete_states=(), discrete_index=(), *, state_switches=(),
                 delay_values=()):
        self.compiled = compiled
        self.t = np.asarray(t, dtype=float)
        self._z = np.asarray(y, dtype=float).reshape(len(self.t), -1)
        self._y = None
        self._table = None                      # name -> column, for a loaded result
        # this run's values: later runs may change p
        self.parameters = compiled.p.copy() if compiled is not None else np.empty(0)
        self.parameter_names = list(compiled.param_names) if compiled is not None else []
        self.stats = stats.as_dict() if hasattr(stats, "as_dict") else dict(stats or {})
        self.events = [e if isinstance(e, Event) else Event(e, "relation") for e in events]
        self.state_switches = list(state_switches)
        self.success = success
        self.message = message
        # the discrete state (relation and floor values) each point was integrated in
        self._discrete = [np.asarray(d, dtype=float) for d in discrete_states]
        self._discrete_index = list(discrete_index)
        # the delayed values at every point (delay(): recorded, the history is gone)
        self._delayed = np.asarray(delay_values, dtype=float) if len(delay_values) else None
        meta = getattr(compiled, "meta", None) or {}
        self.units = dict(meta.get("units", {}))
        self.descriptions = dict(meta.get("descriptions", {}))
        self._cols = {}          # the outputs read so far, by their column of expand
        self._kept = None        # the outputs a run kept (simulate(..., outputs=)), or all
        # "Boolean" or "Integer" by name; every other variable is Real
        self.value_types = dict(meta.get("value_types", {}))

    @classmethod
    def from_table(cls, t, columns: dict, **fields) -> "Result":
        """A result that holds its values (loaded, or gathered from elsewhere)."""
        res = cls(None, t, np.zeros((len(t), 0)), fields.pop("stats", None),
                  fields.pop("events", ()), fields.pop("success", True),
                  fields.pop("message", ""))
        # a dict of arrays, or a mapping that reads each when first asked for (a file)
        res._table = {n: np.asarray(v, dtype=float) for n, v in columns.items()} \
            if isinstance(columns, dict) else columns
        res.value_types = dict(fields.pop("value_types", {}))
        for key, value in fields.items():
            setattr(res, key, value)
        return res

    @property
    def names(self) -> list:
        if self._table is not None:
            return sorted(self._table)
        if self._kept is not None:
            return sorted(self._kept)
        return sorted(self.compiled.outputs)

    def _prefetch(self, names) -> None:
        """Compute the outputs ``names`` (of a result of a compiled model) together:
        the statements they share run once."""
        if self._table is None and self._kept is None:
            outputs = self.compiled.outputs
            self._columns([outputs[n][1] for n in names
                           if n in outputs and outputs[n][0] is not None])

    def _keep(self, names) -> None:
        """Keep only the outputs ``names`` (``simulate(..., outputs=)``), computed now."""
        outputs = self.compiled.outputs
        self._columns([outputs[n][1] for n in names if outputs[n][0] is not None])
        self._kept = set(names)

    @property
    def event_times(self) -> np.ndarray:
        return np.array([float(e) for e in self.events])

    @property
    def states(self) -> list:
        """The states the integrator used (the default of :meth:`plot`)."""
        if self.compiled is None:
            return list(getattr(self, "_states", []))
        return list(self.compiled.states)

    @property
    def parameter_values(self) -> dict:
        """This run's parameter values, by name (with those found by initialization,
        and the parameters bound to them, at the values found)."""
        values = {n: float(v) for n, v in zip(self.parameter_names, self.parameters)}
        meta = getattr(self.compiled, "meta", None) or {}
        for name, f in meta.get("found_followers", ()):
            values[name] = float(f(self.parameters))
        return values

    def __contains__(self, name) -> bool:
        known = self._table if self._table is not None else (
            self._kept if self._kept is not None else self.compiled.outputs)
        return name in known or _signal_name(name, known) is not None

    def __getitem__(self, name: str) -> np.ndarray:
        known = self._table if self._table is not None else (
            self._kept if self._kept is not None else self.compiled.outputs)
        if name not in known and isinstance(name, str):
            array = _array_elements(name, known)
            if array is not None:     # an array variable: time x its shape
                shape, elements = array
                return np.stack([self[n] for n in elements], axis=-1).reshape(
                    (len(self.t),) + shape)
            # a signal port reads by its own name: res["ship.y"] is "ship.y.signal"
            name = _signal_name(name, known) or name
        if self._table is not None:
            if name not in self._table:
                raise KeyError(self._missing(name, self._table))
            return self._typed(name, self._table[name].copy())
        if self._kept is not None and name not in self._kept:
            raise KeyError(self._missing(name, self._kept)
                           + "; the run kept only the outputs asked for (outputs=)")
        try:
            sign, k = self.compiled.outputs[name]
        except KeyError:
            raise KeyError(self._missing(name, self.compiled.outputs)) from None
        if sign is None:
            return self._typed(name, np.full(len(self.t), k(self.parameters)
                                             if callable(k) else k))
        return self._typed(name, sign * self._columns([k])[0])

    def _columns(self, cols) -> list:
        """The outputs ``cols`` (columns of the model's ``expand``) at every point:
        computed for these only, once (:mod:`acausal.runtime.outputs`), and kept."""
        missing = [c for c in dict.fromkeys(cols) if c not in self._cols]
        if missing:
            if self._y is None and not self._vectorized():
                # no modes recorded for the points: each point settles its own, as before
                self._y = expand_points(self.compiled, self.t, self._z, self.parameters,
                                        self._discrete, self._discrete_index,
                                        self._delayed)
            if self._y is not None:
                self._cols.update({c: self._y[:, c] for c in missing})
            else:
                self._cols.update(zip(missing, self._evaluate(missing)))
        return [self._cols[c] for c in cols]

    def _vectorized(self) -> bool:
        c = self.compiled
        if c.code.expand is not None:
            if pointwise(c, len(self.t)):
                return False
        known = len(self._discrete_index) == len(self.t) and bool(self._discrete)
        # the delayed values (and varying inputs') recorded at the points, where needed
        delays_kept = getattr(c, "delays", None) is None or (
            self._delayed is not None and len(self._delayed) == len(self.t))
        return c.code.expand is None or (known and delays_kept) or (
            not len(self.t) and delays_kept)

    def _evaluate(self, cols) -> list:
        """:meth:`_columns` computed (:func:`acausal.runtime.outputs.evaluate`)."""
        return evaluate(self.compiled, cols, self.t, self._z, self.parameters,
                        self._discrete, self._discrete_index, self._delayed)

    def _typed(self, name, values) -> np.ndarray:
        """A Boolean variable's values as a bool array, an Integer's as int64."""
        kind = self.value_types.get(name)
        if kind == "Boolean":
            return np.asarray(values, dtype=float) > 0.5
        if kind == "Integer":
            return np.rint(np.asarray(values, dtype=float)).astype(np.int64)
        return values

    @staticmethod
    def _missing(name, known) -> str:
        hint = suggestion(str(name), _nearby(str(name), known))
        leaf = str(name).split(".")[-1]
        close = [n for n in known if leaf and n.split(".")[-1] == leaf]
        return (f"no variable '{name}' in the result{hint}"
                + (f"; variables named {leaf}: {listed(close)}" if close else ""))

    def at(self, name: str, t: float) -> float:
        """The value of ``name`` at time t (linear interpolation between output points)."""
        return float(np.interp(t, self.t, self[name]))

    def _names(self, names) -> list:
        if names is None:
            return self.names
        if isinstance(names, str):
            return [names]
        return list(names)

    # -- export ------------------------------------------------------------------------
    def to_csv(self, path, names=None) -> None:
        """Columns ``time`` and each variable (default: all, sorted by name)."""
        names = self._names(names)
        self._prefetch(names)
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["time"] + names)
            cols = np.column_stack([self.t] + [self[n] for n in names])
            w.writerows(cols.tolist())

    def _rows(self, unique: bool) -> np.ndarray:
        """Indices of the points to export; ``unique``: at an event time, which appears
        twice (the values just before and just after it), only the point after it."""
        if not unique or len(self.t) < 2:
            return np.arange(len(self.t))
        return np.flatnonzero(np.append(self.t[1:] != self.t[:-1], True))

    def to_pandas(self, names=None, unique: bool = False):
        """A ``pandas.DataFrame``: index ``time``, one column per variable (default: all;
        a Boolean a bool column, an Integer an int64 one); ``df.attrs["units"]``,
        ``df.attrs["descriptions"]`` and ``df.attrs["types"]`` (Real, Boolean, Integer)
        by column name.  An event
        time appears twice (before and after it) unless ``unique=True`` (after only)."""
        try:
            import pandas as pd
        except ImportError as err:
            raise ImportError("Result.to_pandas needs pandas: pip install 'acausal[io]'") \
                from err
        names, rows = self._names(names), self._rows(unique)
        self._prefetch(names)
        df = pd.DataFrame({n: self[n][rows] for n in names},
                          index=pd.Index(self.t[rows], name="time"), columns=names)
        df.attrs["units"] = {n: self.units.get(n, "") for n in names}
        df.attrs["descriptions"] = {n: self.descriptions.get(n, "") for n in names}
        # Booleans and Integers are bool and int64 columns; their Modelica types
        df.attrs["types"] = {n: self.value_types.get(n, "Real") for n in names}
        return df

    def to_xarray(self, names=None, unique: bool = False):
        """An ``xarray.Dataset`` with dimension ``time``, one variable per name (default:
        all) with attributes ``units``, ``description`` and ``type`` (Real, Boolean or
        Integer: bool and int64 data); the run's parameters, success
        and message are dataset attributes.  ``unique=True``: each event time once (the
        point after it), so that ``ds.sel(time=..., method="nearest")`` works."""
        try:
            import xarray as xr
        except ImportError as err:
            raise ImportError("Result.to_xarray needs xarray: pip install 'acausal[io]'") \
                from err
        names, rows = self._names(names), self._rows(unique)
        self._prefetch(names)
        data = {n: ("time", self[n][rows], {"units": self.units.get(n, ""),
                                      "description": self.descriptions.get(n, ""),
                                      "type": self.value_types.get(n, "Real")})
                for n in names}
        attrs = {"success": int(bool(self.success)), "message": str(self.message)}
        attrs.update({f"parameter {k}": v for k, v in self.parameter_values.items()})
        return xr.Dataset(data, coords={"time": ("time", self.t[rows], {"units": "s"})},
                          attrs=attrs)

    def to_mat(self, path, names=None) -> None:
        """The Dymola/OpenModelica result file (MATLAB v4, "binTrans" format 1.1);
        see :mod:`acausal.results_io`."""
        write_mat(self, path, names)

    def save(self, path) -> None:
        """Everything needed to use the result later without the model (HDF5, the ``io``
        extra); read it back with ``acausal.load_result(path)``."""
        save_result(self, path)

    # -- plot ---------------------------------------------------------------------------
    def plot(self, *names, ax=None, path=None, events=True, subplots=False):
        """Plot variables against time (needs matplotlib: the ``plot`` extra).

        Default names: the states.  Variables of one unit share a y-axis labelled with
        the unit; each further unit gets a twin axis on the right (``subplots=True``: one
        subplot per unit instead).  ``events``: mark the events with vertical lines.
        Returns the axes (a list when there is more than one)."""
        return plot_result(self, list(names) or self.states, ax=ax, path=path,
                           events=events, subplots=subplots)

    def __repr__(self):
        status = "ok" if self.success else f"FAILED: {self.message}"
        n_vars = len(self._table) if self._table is not None else (
            len(self._kept) if self._kept is not None else len(self.compiled.outputs))
        span = f"t = {self.t[0]:g} .. {self.t[-1]:g}, " if len(self.t) else ""
        return (f"<Result {len(self.t)} points, {span}{n_vars} variables, "
                f"{len(self.events)} events, {status}>")


def _nearby(name: str, known) -> list:
    """The names worth comparing ``name`` with: those of its component (and its
    parent's) in a large model, else all."""
    if len(known) <= 2000:
        return list(known)
    prefix = name.rsplit(".", 1)[0] + "." if "." in name else ""
    while prefix:
        found = [n for n in known if n.startswith(prefix)]
        if found:
            return found
        prefix = prefix[:-1].rsplit(".", 1)[0] + "." if "." in prefix[:-1] else ""
    return [n for n in known if "." not in n] or list(known)[:2000]


def _signal_name(name, known):
    """``name + ".signal"`` if that is the value of a signal port in ``known``."""
    if isinstance(name, str):
        full = f"{name}.signal"
        if full in known:
            return full
    return None
