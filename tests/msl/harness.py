"""The MSL examples against the MSL's own reference results.

Each example of the Modelica Standard Library that acausal reproduces is a runnable model
under ``acausal.library.<domain>.examples.msl``: a class that names the MSL example it
translates (``msl_name``, the MSL v4.0.0 class) and carries its experiment (``stop_time``
= StopTime, ``tolerance`` = Tolerance, from the reference's ``creation.txt``).  The
reference results are those of the Modelica Association's regression tests,
``modelica/MAP-LIB_ReferenceResults`` at tag ``v4.0.0``: of each example, the columns its
``comparisonSignals.txt`` names, vendored by :mod:`acausal.tests.msl.vendor` into
``references/<msl_name>.csv``, downsampled, with every event instant kept (the rows that
repeat a time: the values before and after the event), their source in the header.

The bound (:data:`BOUND`): a Real signal passes when

    max |acausal - reference| <= 1e-3 x (max - min of the reference)

over the reference's time grid, the points within :func:`event_window` of an event (of
the reference's or of acausal's run) excluded: there the value depends on which side of
the event a point falls, not on the accuracy of either run.  A reference that is
constant is judged on the scale of its value (or 1 where it is 0); one whose values all
lie within :data:`ZERO` of 0 is the constant 0, its variation the round-off of the tool
that computed it (a coordinate that stays 0 by symmetry).  A Boolean or
Integer signal (the result's array has a bool or integer dtype) passes when it equals the
reference at every point outside those windows.  acausal's values are its own output at
the reference's times (``t_eval``), not an interpolation between its steps.

Where an example's variable has another name in acausal, the class maps it:
``msl_signals = {"reference name": "acausal name"}`` (the library guide lists the names
that differ).
"""
from __future__ import annotations

import csv
import importlib
import pkgutil
import time as _time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

__all__ = ["BOUND", "REFERENCES", "Reference", "SignalCheck", "Outcome", "load_reference",
           "event_window", "compare", "run_example", "examples", "package_of"]

BOUND = 1e-3
ZERO = 1e-12
REFERENCES = Path(__file__).resolve().parent / "references"


@dataclass
class Reference:
    """One example's reference result: the time grid, the compared columns, the events."""

    name: str
    t: np.ndarray
    columns: dict
    stop_time: float
    tolerance: float
    interval: float
    header: dict = field(default_factory=dict)

    @property
    def events(self) -> np.ndarray:
        """The event instants: the times the grid holds twice."""
        repeated = self.t[1:][np.diff(self.t) == 0.0]
        return np.unique(repeated)


def load_reference(name: str) -> Reference:
    """The vendored reference of the MSL example ``name`` (its full class name)."""
    path = REFERENCES / f"{name}.csv"
    if not path.exists():
        raise FileNotFoundError(f"no vendored reference for {name} ({path}); vendor it "
                                "with tests/msl/vendor.py")
    header, rows = {}, []
    with open(path, newline="") as f:
        lines = [line for line in f]
    body = []
    for line in lines:
        if line.startswith("#"):
            key, _, value = line[1:].strip().partition(":")
            header[key.strip()] = value.strip()
        else:
            body.append(line)
    reader = csv.reader(body)
    names = next(reader)
    rows = np.array([[float(x) for x in row] for row in reader if row])
    columns = {n: rows[:, k] for k, n in enumerate(names) if k > 0}
    return Reference(name=name, t=rows[:, 0], columns=columns,
                     stop_time=float(header["StopTime"]),
                     tolerance=float(header["Tolerance"]),
                     interval=float(header["Interval"]), header=header)


def event_window(ref: Reference) -> float:
    """Half the width of the span around an event where points are not compared: two
    intervals of the reference's original output grid."""
    return 2.0 * ref.interval


@dataclass
class SignalCheck:
    """One compared signal: its worst error, the reference's amplitude, the verdict."""

    name: str
    kind: str                 # "real" or "discrete"
    worst: float              # max |acausal - reference| (real), mismatching points (discrete)
    scale: float              # the reference's amplitude (real), 1 (discrete)
    at: float                 # the time of the worst point
    compared: int             # points compared
    passed: bool

    @property
    def ratio(self) -> float:
        return self.worst / self.scale


@dataclass
class Outcome:
    """One example run and compared: its checks, the run's success and time."""

    name: str
    checks: list
    success: bool
    message: str
    seconds: float

    @property
    def passed(self) -> bool:
        return self.success and bool(self.checks) and all(c.passed for c in self.checks)

    @property
    def worst(self) -> float:
        real = [c.ratio for c in self.checks if c.kind == "real"]
        return max(real) if real else 0.0

    def describe(self) -> str:
        lines = [f"{self.name}: {'passed' if self.passed else 'FAILED'}"
                 + ("" if self.success else f" (run failed: {self.message})")]
        for c in self.checks:
            what = (f"{c.worst:.3g} / {c.scale:.3g} = {c.ratio:.2e}" if c.kind == "real"
                    else f"{int(c.worst)} mismatching instant(s)")
            lines.append(f"  {'ok  ' if c.passed else 'FAIL'} {c.name}: {what} "
                         f"(worst at t = {c.at:.6g}, {c.compared} points)")
        return "\n".join(lines)


def _compared_points(ref: Reference, extra_events) -> np.ndarray:
    """The mask of reference points outside every event's window."""
    events = np.concatenate([ref.events, np.asarray(extra_events, dtype=float)])
    keep = np.ones(len(ref.t), dtype=bool)
    if events.size:
        w = event_window(ref)
        events = np.sort(events)
        k = np.searchsorted(events, ref.t)
        lo = np.abs(ref.t - events[np.clip(k - 1, 0, events.size - 1)])
        hi = np.abs(ref.t - events[np.clip(k, 0, events.size - 1)])
        keep = np.minimum(lo, hi) > w
    return keep


def _scale(values: np.ndarray) -> float:
    if float(np.max(np.abs(values))) <= ZERO:
        return 1.0
    amplitude = float(np.max(values) - np.min(values))
    if amplitude > 0.0:
        return amplitude
    level = float(np.max(np.abs(values)))
    return level if level > 0.0 else 1.0


def compare(times, read, ref: Reference, events=(), signals: dict | None = None) -> list:
    """The checks of every reference column: ``read(name)`` gives acausal's values at
    ``times`` (the reference's distinct times), ``events`` acausal's event instants,
    ``signals`` maps reference names to acausal's where they differ."""
    signals = signals or {}
    keep = _compared_points(ref, events)
    index = np.searchsorted(times, ref.t)       # each reference point's row in ours
    checks = []
    for name, values in ref.columns.items():
        ours = np.asarray(read(signals.get(name, name)))[index]
        discrete = ours.dtype.kind in "biu"
        if discrete:
            wrong = keep & (np.round(values).astype(np.int64) != ours.astype(np.int64))
            n = int(np.count_nonzero(wrong))
            at = float(ref.t[np.argmax(wrong)]) if n else 0.0
            checks.append(SignalCheck(name, "discrete", float(n), 1.0, at,
                                      int(keep.sum()), n == 0))
            continue
        scale = _scale(values)
        err = np.where(keep, np.abs(ours.astype(float) - values), 0.0)
        if not np.all(np.isfinite(err)):
            k = int(np.argmax(~np.isfinite(err)))
            checks.append(SignalCheck(name, "real", np.inf, scale, float(ref.t[k]),
                                      int(keep.sum()), False))
            continue
        k = int(np.argmax(err))
        checks.append(SignalCheck(name, "real", float(err[k]), scale, float(ref.t[k]),
                                  int(keep.sum()), float(err[k]) <= BOUND * scale))
    return checks


def run_example(cls, **simulate_options) -> Outcome:
    """Simulate the example class ``cls`` as its MSL experiment says (``stop_time``,
    ``tolerance``), output at the reference's times, and compare every reference column."""
    import acausal as ac
    ref = load_reference(cls.msl_name)
    times = np.unique(ref.t)
    t0 = _time.perf_counter()
    options = dict(t_end=cls.stop_time, rtol=cls.tolerance, t_eval=times)
    options.update(getattr(cls, "msl_simulate", {}))
    options.update(simulate_options)
    res = ac.simulate(cls(), **options)
    seconds = _time.perf_counter() - t0
    checks = []
    if len(res.t) == len(times):
        checks = compare(res.t, res.__getitem__, ref, np.asarray(res.events, dtype=float),
                         getattr(cls, "msl_signals", None))
    return Outcome(cls.msl_name, checks, bool(res.success), res.message or "", seconds)


def examples() -> dict:
    """Every MSL example in the library: {msl_name: class}, found in the modules of the
    ``examples.msl`` packages of ``acausal.library``'s domains."""
    import acausal.library as lib
    found = {}
    for info in pkgutil.walk_packages(lib.__path__, lib.__name__ + "."):
        if ".examples.msl." not in info.name + ".":
            continue
        module = importlib.import_module(info.name)
        for value in vars(module).values():
            if isinstance(value, type) and "msl_name" in vars(value) \
                    and value.__module__ == module.__name__:
                if value.msl_name in found:
                    raise ValueError(f"two examples claim {value.msl_name}: "
                                     f"{found[value.msl_name].__module__} and {module.__name__}")
                found[value.msl_name] = value
    return dict(sorted(found.items()))


def package_of(msl_name: str) -> str:
    """The MSL package an example belongs to (``Modelica.Mechanics.Rotational``)."""
    return msl_name.split(".Examples.")[0]
