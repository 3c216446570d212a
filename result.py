"""Result: the time series of every variable of a simulation, by dotted name."""
from __future__ import annotations

import csv

import numpy as np

__all__ = ["Result"]


class Result:
    """What ``acausal.simulate`` returns.

    ``res.t`` (times), ``res["C1.v"]`` (any variable, alias or not, and ``der(x)`` of the
    states), ``res.names``, ``res.stats`` (solver statistics), ``res.events`` (event
    times), ``res.success`` / ``res.message`` (a failed run keeps what it computed).
    """

    def __init__(self, compiled, t, y, stats=None, events=(), success=True, message="",
                 discrete_states=(), discrete_index=()):
        self.compiled = compiled
        self.t = np.asarray(t, dtype=float)
        self._z = np.asarray(y, dtype=float).reshape(len(self.t), -1)
        self._y = None
        self.parameters = compiled.p.copy()     # this run's values: later runs may change p
        self.stats = stats.as_dict() if hasattr(stats, "as_dict") else (stats or {})
        self.events = list(events)
        self.success = success
        self.message = message
        # the discrete state (relation and floor values) each point was integrated in
        self._discrete = [np.asarray(d, dtype=float) for d in discrete_states]
        self._discrete_index = list(discrete_index)

    @property
    def names(self) -> list:
        return sorted(self.compiled.outputs)

    def __contains__(self, name) -> bool:
        return name in self.compiled.outputs

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            sign, k = self.compiled.outputs[name]
        except KeyError:
            close = [n for n in self.compiled.outputs if name.split(".")[-1] in n][:8]
            raise KeyError(f"no variable '{name}' in the result"
                           + (f"; similar: {', '.join(close)}" if close else "")) from None
        if sign is None:
            return np.full(len(self.t), k(self.parameters) if callable(k) else k)
        if self._y is None:
            self._y = _expand(self.compiled, self.t, self._z, self.parameters,
                              self._discrete, self._discrete_index)
        return sign * self._y[:, k]

    def at(self, name: str, t: float) -> float:
        """The value of ``name`` at time t (linear interpolation between output points)."""
        return float(np.interp(t, self.t, self[name]))

    def to_csv(self, path, names=None) -> None:
        names = list(names) if names is not None else self.names
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["time"] + names)
            cols = np.column_stack([self.t] + [self[n] for n in names])
            w.writerows(cols.tolist())

    def plot(self, *names, ax=None, path=None):
        """Plot variables against time (needs matplotlib: the ``plot`` extra)."""
        try:
            import matplotlib
            if path is not None:
                matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError as err:
            raise ImportError("Result.plot needs matplotlib: pip install 'acausal[plot]'") from err
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 4))
        for n in names:
            ax.plot(self.t, self[n], label=n)
        ax.set_xlabel("time [s]")
        ax.legend()
        ax.grid(True, alpha=0.3)
        if path is not None:
            ax.figure.savefig(path, dpi=120, bbox_inches="tight")
        return ax

    def __repr__(self):
        status = "ok" if self.success else f"FAILED: {self.message}"
        return (f"<Result {len(self.t)} points, t = {self.t[0]:g} .. {self.t[-1]:g}, "
                f"{len(self.compiled.outputs)} variables, {status}>")


def _expand(compiled, t, z, p, discrete, index) -> np.ndarray:
    """Every variable at every output time, from the solver vector z, each point in the
    discrete state (relation values) it was integrated in: values computed from
    if-expressions are those of the branch the integrator used there, so an output never
    contradicts the trajectory (at an event, the point before it is in the old modes and
    the point after it in the new)."""
    saved, saved_p = compiled.m.copy(), compiled.p.copy()
    compiled.p[:] = p
    known = len(index) == len(t) and discrete
    try:
        rows = []
        for k, (tk, zk) in enumerate(zip(t, z)):
            if known:
                compiled.m[:] = discrete[index[k]]
            else:                      # a result without its modes: take them from the point
                compiled.init_modes(tk, zk)
            rows.append(compiled.expand(tk, zk))
        return np.array(rows).reshape(len(t), -1)
    finally:
        compiled.m[:] = saved
        compiled.p[:] = saved_p
