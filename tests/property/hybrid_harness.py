"""One random hybrid or nonlinear model from end to end: draw it (hybrid_circuits,
hybrid_systems), solve it with the hand-written mode-by-mode reference, run acausal on
it, and say what happened.

Outcomes: ``ok``; ``wrong`` (simulated, but a signal deviates from the reference by more
than TOL of its size at rtol 1e-8 and does not converge to it at rtol 1e-10, or the
energy balance of a passive model misses by more than ENERGY_TOL of its energy scale);
``rejected`` / ``rejected, no culprit`` (an ill-posed model refused with a typed error,
naming a culprit or not); ``false rejection`` (a well-posed model refused, or simulated
without success); ``missed`` (an ill-posed model that ran); ``internal error`` (any
exception that is not a typed acausal error); ``hang`` (over the wall-time cap).  An
ill-posed model whose singularity only a mode reached at run time has (a loop of
voltage sources closed through a diode or switches with Ron = 0) is refused when its
run stops with a message naming the culprit.

A draw whose reference chatters (a sliding mode, or a grazing the reference cannot
follow) is drawn again, and also run in acausal (``run_sliding``): ``refused, named``
(stopped with a typed error or a message naming a relation of the model), ``refused,
not named``, ``ran (not judged)``, ``internal error``.

Tolerance.  acausal runs at rtol 1e-8, atol 1e-12 and is compared at 1001 points.  Its
error per step is controlled at about 1e-8; events are located to about the same
relative precision, and a state's error carries through an event times the jump of
the vector field there, so the global deviation of a model with tens of events stays
near 1e-6 of the signal's size.  TOL = 1e-4 leaves a margin of 100 and is far below
what a wrong mode, event or equation produces (O(1)).  Points within 1e-6 of the time
span of a switching of the reference are not compared (a discontinuous signal there
is the jump itself).  A signal's size is its amplitude in the reference, at least 1e-3
of the largest signal of its kind (the leakage current Goff v of a blocking diode beside
the load current), and at least 100 ATOL / TOL (the speed of a mass stuck throughout is
0 in the reference and round-off in acausal: the integrator controls nothing below its
absolute tolerance).  The energy balance is integrated from the result by the
trapezoidal rule on the integrator's own steps (which follow every transient) and 16016
points between them (64064 where that misses) and either side of every switching of the
reference, and ENERGY_TOL = 1e-3 of the largest of
the energies: the quadrature's own error stays near 1e-4 where an ideal diode's current
comes in pulses.

Each model runs in a worker process started with the spawn method (``HybridPool``):
a model over the cap is killed with its worker and counted a hang; the workers are
joined when the pool closes.
"""
from __future__ import annotations

import math
import multiprocessing as mp
import time
import traceback
import warnings
from typing import Optional

import numpy as np

from .hybrid_circuits import ill_posed_circuit, ill_posed_loop, orifices, rectifier
from .hybrid_reference import Chattering, HybridCase
from .hybrid_systems import friction, ill_posed_inline, inline, loop, rotational_friction
from .harness import _first_line, _names_culprit, _typed_errors, _where
from .netlists import SeededChooser

__all__ = ["HYBRID_CYCLE", "HYBRID_CATEGORIES", "SLIDING_CATEGORIES", "hybrid_case",
           "run_hybrid", "run_sliding", "HybridPool",
           "TOL", "ENERGY_TOL"]

RTOL, ATOL = 1e-8, 1e-12
TIGHT = (1e-10, 1e-13)
TOL, ENERGY_TOL, N_POINTS = 1e-4, 1e-3, 1001
DRAWS = {"rectifier": rectifier, "friction": friction,
         "rotational friction": rotational_friction, "loop": loop, "orifices": orifices,
         "inline": inline, "ill-posed circuit": ill_posed_circuit,
         "ill-posed loop": ill_posed_loop, "ill-posed inline": ill_posed_inline}
HYBRID_CYCLE = (["rectifier"] * 5 + ["friction"] * 2 + ["rotational friction"] * 2
                + ["loop"] * 3 + ["orifices"] * 2 + ["inline"] * 3
                + ["ill-posed circuit", "ill-posed loop", "ill-posed inline"])
HYBRID_CATEGORIES = ("ok", "wrong", "rejected", "rejected, no culprit", "false rejection",
                     "missed", "internal error", "hang", "generator error")
# what acausal does with a draw whose reference chatters (a sliding mode, a grazing):
# refused naming the relation (a typed error, or a run stopped with a message naming
# it), refused without naming it, run to the end (not judged: no reference), or failed
SLIDING_CATEGORIES = ("refused, named", "refused, not named", "ran (not judged)",
                      "internal error")


def hybrid_case(seed: int, n: int, chattered: Optional[list] = None):
    """Case n of the seed: (case, reference solution or None, redraws).  A draw whose
    reference chatters (a sliding mode) is drawn again from the next sub-seed; the
    chattering draws are appended to ``chattered`` (with the reference's message)."""
    strategy = HYBRID_CYCLE[n % len(HYBRID_CYCLE)]
    for attempt in range(20):
        case = DRAWS[strategy](SeededChooser(f"hybrid:{seed}:{n}:{attempt}"))
        if case.expect != "regular":
            return case, None, attempt
        try:
            return case, case.reference(), attempt
        except Chattering as why:
            if chattered is not None:
                chattered.append((case, str(why)))
            continue
    raise RuntimeError(f"20 draws of {strategy} chatter")


def run_sliding(case: HybridCase) -> dict:
    """What acausal does with a draw whose reference chatters: it must stop there with
    a typed error, or a message, naming a relation of the model (a component's path)."""
    import acausal as ac
    typed = _typed_errors()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            compiled = ac.compile(case.build())
        res = _simulate(compiled, case, None, RTOL, ATOL)
    except typed as err:
        message = str(err)
    except Exception as err:                # noqa: BLE001  (classifying is the point)
        return dict(category="internal error", detail=_first_line(err) + _where(err))
    else:
        if res.success:
            return dict(category="ran (not judged)", detail="")
        message = res.message
    model = case.build()                    # its components are the relations' owners
    names = [k for k, v in vars(model).items() if isinstance(v, ac.Component)]
    named = _names_culprit(message, names)
    return dict(category="refused, named" if named else "refused, not named",
                detail=message[:200])


def _sizes(case: HybridCase, want: dict) -> dict:
    peers: dict = {}
    for name, kind in case.signals.items():
        peers[kind] = max(peers.get(kind, 0.0), float(np.max(np.abs(want[name]))))
    return {name: max(float(np.max(np.abs(want[name]))), 1e-3 * peers[kind], 100 * ATOL / TOL)
            for name, kind in case.signals.items()}


def compare(case: HybridCase, ref, res, times) -> tuple:
    """(worst relative deviation, its signal, time, missing names)."""
    want = ref.evaluate(times)
    sizes = _sizes(case, want)
    keep = np.ones(len(times), bool)
    for te in ref.events:
        keep &= np.abs(times - te) > 1e-6 * case.t_end
    worst, where, when, missing = 0.0, "", 0.0, []
    for name in case.signals:
        if name not in res:
            missing.append(name)
            continue
        dev = np.abs(np.asarray(res[name], float) - want[name])[keep] / sizes[name]
        k = int(np.argmax(dev)) if len(dev) else 0
        err = float(dev[k]) if len(dev) and np.all(np.isfinite(dev)) else math.inf
        if err > worst or not where:
            worst, where, when = err, name, float(times[keep][k]) if len(dev) else 0.0
    return worst, where, when, missing


def energy_error(case: HybridCase, res) -> float:
    """|stored(t) - stored(0) + dissipated(t) - supplied(t)| over the largest of them."""
    get = lambda name: np.asarray(res[name], float)  # noqa: E731
    supplied, stored, dissipated = case.energy(get)
    t = np.asarray(res.t, float)

    def cum(pw):
        pw = np.broadcast_to(np.asarray(pw, float), t.shape)
        return np.concatenate([[0.0], np.cumsum(np.diff(t) * (pw[1:] + pw[:-1]) / 2)])
    e_in, e_out = cum(supplied), cum(dissipated)
    miss = stored - stored[0] + e_out - e_in
    scale = max(np.max(np.abs(stored)), np.max(np.abs(e_in)), np.max(np.abs(e_out)), 1e-300)
    return float(np.max(np.abs(miss)) / scale)


def _energy(compiled, case, ref, times) -> float:
    """The energy balance on the integrator's own steps (which resolve every transient)
    and 16 times the output points between them (which resolve the smooth stretches);
    a miss over ENERGY_TOL is measured again on 4 times as many points, and the smaller
    is the answer (the trapezoidal rule's error falls 16-fold, a model's does not)."""
    steps = np.asarray(_simulate(compiled, case, None, RTOL, ATOL).t, float)
    # a power that jumps at a switching is integrated across it on an interval of
    # 2e-8 of the time span
    around = np.concatenate([[te - 1e-8 * case.t_end, te + 1e-8 * case.t_end]
                             for te in ref.events] or [[]])
    around = around[(around > 0) & (around < case.t_end)]
    miss = math.inf
    for mult in (16, 64):
        fine = np.union1d(np.union1d(steps, around),
                          np.linspace(0.0, case.t_end, mult * len(times)))
        miss = min(miss, energy_error(case, _simulate(compiled, case, fine, RTOL, ATOL)))
        if miss <= ENERGY_TOL:
            break
    return miss


def _simulate(compiled, case, times, rtol, atol):
    import acausal as ac
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ac.simulate(compiled, t_end=case.t_end, rtol=rtol, atol=atol, t_eval=times)


def run_hybrid(case: HybridCase, ref) -> dict:
    """The outcome of one case: category, detail, worst deviation and its signal."""
    import acausal as ac
    typed, ill = _typed_errors(), case.expect != "regular"
    times = np.linspace(0.0, case.t_end, N_POINTS)
    t0 = time.perf_counter()
    out = dict(category="ok", detail="", error=math.nan, signal="")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            compiled = ac.compile(case.build())
        res = _simulate(compiled, case, times, RTOL, ATOL)
    except typed as err:
        if not ill:
            out.update(category="false rejection", detail=_first_line(err) + _where(err))
        elif not _names_culprit(str(err), case.culprits):
            out.update(category="rejected, no culprit", detail=_first_line(err))
        else:
            out.update(category="rejected", detail=_first_line(err, 120))
        return out
    except Exception as err:                # noqa: BLE001  (classifying is the point)
        out.update(category="internal error", detail=_first_line(err) + _where(err))
        return out
    if ill:
        # a singularity that only a mode reached at run time has (a loop of sources
        # closed through Ron = 0) stops the run; a message naming the culprit refuses it
        if not res.success and _names_culprit(res.message, case.culprits):
            out.update(category="rejected", detail="stopped: " + res.message[:120])
        else:
            out.update(category="missed", detail=f"success={res.success}: {res.message}"[:300])
        return out
    if not res.success:
        out.update(category="false rejection", detail=f"simulation failed: {res.message}"[:300])
        return out
    try:
        worst, where, when, missing = compare(case, ref, res, times)
        e_err = _energy(compiled, case, ref, times) if case.energy else 0.0
    except Exception as err:                # noqa: BLE001
        out.update(category="internal error",
                   detail="reading the result: " + _first_line(err) + _where(err))
        return out
    out.update(error=worst, signal=where, energy=e_err)
    if missing:
        out.update(category="internal error", detail=f"result lacks {', '.join(missing)}")
    elif worst > TOL:
        detail = f"{where} deviates {worst:.2g} of its size at t = {when:.6g}"
        try:
            tight = compare(case, ref, _simulate(compiled, case, times, *TIGHT), times)[0]
        except Exception:                   # noqa: BLE001  (a diagnostic only)
            tight = math.inf
        if tight <= TOL:
            out.update(detail=f"converges: {worst:.2g} at rtol {RTOL:g}, {tight:.2g} at "
                              f"rtol {TIGHT[0]:g}")
        else:
            out.update(category="wrong", detail=detail + f"; at rtol {TIGHT[0]:g}: {tight:.2g}")
    elif e_err > ENERGY_TOL:
        out.update(category="wrong", detail=f"energy balance misses by {e_err:.2g} of its scale")
    out["seconds"] = time.perf_counter() - t0
    return out


def evaluate(seed: int, n: int) -> dict:
    """Draw case n of the seed and run it (what a worker does)."""
    strategy = HYBRID_CYCLE[n % len(HYBRID_CYCLE)]
    base = dict(n=n, strategy=strategy)
    chattered: list = []
    try:
        case, ref, redraws = hybrid_case(seed, n, chattered)
    except Exception:                       # noqa: BLE001  (a defect of the generator)
        return dict(base, category="generator error", detail=traceback.format_exc(limit=3)[-400:])
    sliding = [dict(run_sliding(c), reference=why[:120], describe=c.describe()[:300])
               for c, why in chattered]
    out = run_hybrid(case, ref)
    return dict(base, describe=case.describe(), redraws=redraws, sliding=sliding, **out)


def _worker(conn):
    try:
        while True:
            job = conn.recv()
            if job is None:
                return
            conn.send(evaluate(*job))
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        return


class HybridPool:
    """Worker processes (spawn) that take one case at a time; a case over ``limit``
    seconds is a hang, its worker killed and replaced.  ``close()`` (or leaving the
    ``with`` block) joins every worker."""

    def __init__(self, jobs: int = 1, limit: float = 60.0):
        self.limit, self.ctx = limit, mp.get_context("spawn")
        self.slots = [self._start() for _ in range(jobs)]

    def _start(self):
        parent, child = self.ctx.Pipe()
        proc = self.ctx.Process(target=_worker, args=(child,), daemon=True)
        proc.start()
        child.close()
        return {"proc": proc, "conn": parent, "job": None, "since": 0.0}

    def run(self, seed: int, numbers, report) -> None:
        todo, busy = list(numbers), 0
        while todo or busy:
            for slot in self.slots:
                if slot["job"] is None and todo:
                    slot["job"], slot["since"] = todo.pop(0), time.monotonic()
                    slot["conn"].send((seed, slot["job"]))
                    busy += 1
            for i, slot in enumerate(self.slots):
                if slot["job"] is None:
                    continue
                if slot["conn"].poll(0.02):
                    try:
                        report(slot["conn"].recv())
                    except EOFError:        # the worker died (a crash of the interpreter)
                        report(dict(n=slot["job"], strategy=HYBRID_CYCLE[slot["job"] % len(HYBRID_CYCLE)],
                                    category="internal error", detail="the worker process died"))
                        self._replace(i)
                    slot["job"] = None
                    busy -= 1
                elif time.monotonic() - slot["since"] > self.limit:
                    n = slot["job"]
                    report(dict(n=n, strategy=HYBRID_CYCLE[n % len(HYBRID_CYCLE)],
                                category="hang", detail=f"over {self.limit:g} s; killed"))
                    self._replace(i)
                    busy -= 1

    def _replace(self, i):
        slot = self.slots[i]
        slot["proc"].kill()
        slot["proc"].join()
        slot["conn"].close()
        self.slots[i] = self._start()

    def close(self) -> None:
        for slot in self.slots:
            try:
                slot["conn"].send(None)
            except (BrokenPipeError, OSError):
                pass
        for slot in self.slots:
            slot["proc"].join(timeout=10)
            if slot["proc"].is_alive():
                slot["proc"].kill()
                slot["proc"].join()
            slot["conn"].close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
