"""Runners for ``peers.py``: acausal and the peer solvers on a ``Formulation``.

A runner is built once (its build time is measured) and then run repeatedly; each run
returns an ``Outcome``: accepted steps, right-hand side (residual) evaluations and the
final values under acausal's variable names.  Every peer restarts at the formulation's
time events (M3's voltage step), as one does by hand with a solver that has no events.

* scipy ``solve_ivp(method="BDF")``: finite-difference Jacobian, with the constant
  pattern as ``jac_sparsity`` for the linear models M1 and M4;
* scikit-sundae ``IDA``: residual F = [x' - f; g]; the linear models get their constant
  Jacobian cj I - df/dx on the sparse (SuperLU_MT) solver, the small ones IDA's dense
  difference quotients;
* CasADi ``integrator``: SX expressions, ``cvodes`` for ODE forms and ``idas`` for DAE
  forms, the exact sparse Jacobian by algorithmic differentiation; the states are
  scaled by their nominal values because CasADi takes one scalar abstol.
"""
from __future__ import annotations

import inspect
import time
import warnings
from dataclasses import dataclass
from typing import Callable

import numpy as np
import scipy.sparse as sps
from scipy.integrate import solve_ivp

__all__ = ["Outcome", "Runner", "acausal_runners", "scipy_runner", "ida_runner",
           "casadi_runners", "optional_import"]

MAX_STEPS = 10**7


@dataclass
class Outcome:
    """One run: wall time of the integration, accepted steps, right-hand side or
    residual evaluations, final values by acausal name (and acausal's Result)."""

    seconds: float
    steps: int
    evaluations: int
    values: dict
    result: object = None


@dataclass
class Runner:
    """``run()`` -> Outcome; ``build_s`` the one-off set-up time (None when there is
    none to speak of); ``reason`` set instead of ``run`` when the runner cannot run."""

    label: str
    form: str
    run: Callable | None = None
    build_s: float | None = None
    reason: str = ""
    compiled: object = None


def optional_import(name: str):
    """The module, or the reason it cannot be imported."""
    try:
        return __import__(name, fromlist=["_"]), ""
    except Exception as err:          # noqa: BLE001  (any failure means "not usable")
        return None, f"not installed ({type(err).__name__}: {err})"


def _timed(fn, *args, **kwargs):
    t0 = time.perf_counter()
    out = fn(*args, **kwargs)
    return out, time.perf_counter() - t0


# --- acausal --------------------------------------------------------------------------------

def _backend_keyword(ac) -> str | None:
    """'compile' or 'simulate' if that call takes ``backend=``, else None."""
    for where, fn in (("compile", ac.compile), ("simulate", ac.simulate)):
        if "backend" in inspect.signature(fn).parameters:
            return where
    return None


def acausal_runners(ac, make_model: Callable, t_end: float, rtol: float,
                    names: list, backends=("numpy", "c")) -> list:
    """One runner per backend that compiles and runs (one for the default when neither
    ``ac.compile`` nor ``ac.simulate`` takes ``backend=``)."""
    where = _backend_keyword(ac)
    if where is None:
        return [_acausal_runner(ac, make_model, t_end, rtol, names, None, None)]
    return [_acausal_runner(ac, make_model, t_end, rtol, names, where, b) for b in backends]


def _acausal_runner(ac, make_model, t_end, rtol, names, where, backend) -> Runner:
    label = "acausal" if backend is None else f"acausal [{backend}]"
    # "c-pyloop": the C backend with the BDF steps in the Python loop, not the compiled one
    loop = None
    if backend is not None and backend.endswith("-pyloop"):
        backend, loop = backend[:-len("-pyloop")], "python"
    extra = {} if backend is None else {"backend": backend}
    try:
        compiled, build = _timed(ac.compile, make_model(), **(extra if where == "compile"
                                                               else {}))
    except Exception as err:          # noqa: BLE001  (a backend that is not available)
        return Runner(label, "generated DAE", reason=f"compile failed: {err}")
    sim_extra = dict(extra) if where == "simulate" else {}
    if loop is not None:
        sim_extra["step_loop"] = loop

    def run():
        res, seconds = _timed(ac.simulate, compiled, t_end=t_end, rtol=rtol, **sim_extra)
        if not res.success:
            raise RuntimeError(res.message)
        # the values are read after the clock stopped: Result evaluates them on demand
        return Outcome(seconds, int(res.stats["steps"]),
                       int(res.stats["residual_evaluations"]),
                       {k: float(res[k][-1]) for k in names}, res)

    return Runner(label, "generated DAE", run, build, compiled=compiled)


# --- scipy --------------------------------------------------------------------------------

def scipy_runner(form, rtol: float) -> Runner:
    """solve_ivp BDF on an ODE form; jac_sparsity from the constant Jacobian's pattern."""
    label = "scipy BDF"
    if not form.is_ode:
        return Runner(label, form.label, reason="no DAE solver")
    t0 = time.perf_counter()
    segments = form.segments()
    atol = rtol * form.x_nominal
    sparsity = form.jacobian(segments[0][2]).astype(bool) if form.linear else None
    build = time.perf_counter() - t0

    def run():
        start = time.perf_counter()
        x, steps, nfev = form.x0.astype(float), 0, 0
        for a, b, u in segments:
            sol = solve_ivp(form.rhs(u), (a, b), x, method="BDF", rtol=rtol, atol=atol,
                            jac_sparsity=sparsity)
            if not sol.success:
                raise RuntimeError(sol.message)
            x, steps, nfev = sol.y[:, -1], steps + sol.t.size - 1, nfev + sol.nfev
        return Outcome(time.perf_counter() - start, steps, nfev, form.outputs(x, None))

    how = "FD Jacobian, jac_sparsity" if form.linear else "FD Jacobian (dense)"
    return Runner(label, f"{form.label}; {how}", run, build if form.linear else None)


# --- IDA (scikit-sundae) ------------------------------------------------------------------

def _csc_data(matrix, pattern) -> np.ndarray:
    """The entries of ``matrix`` at the nonzeros of the CSC ``pattern``, in its order."""
    rows = pattern.indices
    cols = np.repeat(np.arange(pattern.shape[1]), np.diff(pattern.indptr))
    return np.asarray(matrix.tocsr()[rows, cols]).ravel()


def ida_runner(sksundae_ida, form, rtol: float) -> Runner:
    """IDA on F(t, y, y') = [x' - f(t, x, z); g(t, x, z)], y = [x, z]."""
    label = "IDA (sksundae)"
    t0 = time.perf_counter()
    nx, nz, ops = form.x0.size, form.z0.size, form.ops
    f, g = form.f, form.g
    segments = form.segments()
    atol = rtol * np.concatenate([form.x_nominal, form.z_nominal])

    def residual_for(u):
        def residual(t, y, yp, r):
            x, z = y[:nx], y[nx:]
            r[:nx] = yp[:nx] - f(t, x, z, u, ops)
            if nz:
                r[nx:] = g(t, x, z, u, ops)
        return residual

    options = dict(rtol=rtol, atol=atol, max_num_steps=MAX_STEPS)
    if nz:
        options["algebraic_idx"] = list(range(nx, nx + nz))
    how = "dense DQ Jacobian"
    if form.linear:
        df = form.jacobian(segments[0][2])
        eye = sps.identity(nx, format="csc")
        pattern = (abs(df) + eye).tocsc()
        pattern.sort_indices()
        minus_df, identity = -_csc_data(df, pattern), _csc_data(eye, pattern)

        def jacobian(t, y, yp, r, cj, jj):
            jj[:] = minus_df + cj * identity

        options.update(linsolver="sparse", sparsity=pattern, jacfn=jacobian)
        how = "constant sparse Jacobian, SuperLU_MT"
    with warnings.catch_warnings():
        # with jacfn given, the sparsity only sets the pattern: IDA says so, it is meant
        warnings.filterwarnings("ignore", "Custom sparse Jacobian", UserWarning)
        solvers = [sksundae_ida.IDA(residual_for(u), **options) for _, _, u in segments]
    build = time.perf_counter() - t0

    def run():
        start = time.perf_counter()
        x, z, steps, nfev = form.x0.astype(float), form.z0.astype(float), 0, 0
        for solver, (a, b, u) in zip(solvers, segments):
            yp0 = np.concatenate([f(a, x, z, u, ops), np.zeros(nz)])
            sol = solver.solve([a, b], np.concatenate([x, z]), yp0)
            if not sol.success:
                raise RuntimeError(sol.message)
            x, z = sol.y[-1, :nx], sol.y[-1, nx:]
            steps, nfev = steps + len(sol.t) - 1, nfev + int(sol.nfev)
        return Outcome(time.perf_counter() - start, steps, nfev, form.outputs(x, z))

    return Runner(label, f"{form.label}; {how}", run, build)


# --- CasADi ---------------------------------------------------------------------------------

class _CasadiOps:
    """The ``ops`` namespace of ``peers_models`` on SX expressions."""

    def __init__(self, ca):
        self.cat = lambda *parts: ca.vertcat(*parts)
        self.where = ca.if_else
        self.sqrt, self.fabs, self.sin, self.cos = ca.sqrt, ca.fabs, ca.sin, ca.cos


def casadi_runners(ca, form, rtol: float) -> list:
    """``cvodes`` on an ODE form, ``idas`` on a DAE form (x' = f, 0 = g)."""
    plugin = "cvodes" if form.is_ode else "idas"
    label = f"CasADi {plugin}"
    t0 = time.perf_counter()
    ops = _CasadiOps(ca)
    nx, nz = form.x0.size, form.z0.size
    xs, zs, u = ca.SX.sym("x", nx), ca.SX.sym("z", nz), ca.SX.sym("u")
    x_nom, z_nom = ca.DM(form.x_nominal), ca.DM(form.z_nominal)
    x, z = xs * x_nom, zs * z_nom
    dae = {"x": xs, "p": u, "ode": form.f(0.0, x, z, u, ops) / x_nom}
    if nz:
        dae.update(z=zs, alg=form.g(0.0, x, z, u, ops) / z_nom)
    options = {"reltol": rtol, "abstol": rtol, "max_num_steps": MAX_STEPS}
    segments = form.segments()
    integrators = [ca.integrator(f"peer{k}", plugin, dae, a, b, options)
                   for k, (a, b, _) in enumerate(segments)]
    build = time.perf_counter() - t0

    def run():
        start = time.perf_counter()
        x_s = form.x0 / form.x_nominal
        z_s = form.z0 / form.z_nominal if nz else None
        steps = nfev = 0
        for integ, (_, _, uv) in zip(integrators, segments):
            args = {"x0": x_s, "p": uv}
            if nz:
                args["z0"] = z_s
            out = integ(**args)
            stats = integ.stats()
            if not stats.get("success", True):
                raise RuntimeError(stats.get("return_status", "failed"))
            x_s = np.array(out["xf"]).ravel()
            if nz:
                z_s = np.array(out["zf"]).ravel()
            steps, nfev = steps + int(stats["nsteps"]), nfev + int(stats["nfevals"])
        return Outcome(time.perf_counter() - start, steps, nfev,
                       form.outputs(x_s * form.x_nominal,
                                    z_s * form.z_nominal if nz else None))

    return [Runner(label, f"{form.label}; SX, AD Jacobian", run, build)]
