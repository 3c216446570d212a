"""Parameter estimation: least-squares fit of named parameters to measured time series.

The prediction-error method of the DAE notes (000, chapter 7): with measured y(t_k) and
the model's prediction y^(t_k | theta),

    V_N(theta) = 1/N sum_k 1/2 |y(t_k) - y^(t_k | theta)|^2          (7.1.6)

is minimized over theta.  Here by ``scipy.optimize.least_squares`` (trust-region
reflective, so bounds hold at every iterate) on the parameters scaled by their start
values and on residuals scaled per output.  The sensitivities dy^/dtheta are central
differences of simulations, or (``sensitivities="forward"``) the forward sensitivity
equations integrated with the model (the notes' (7.1.17)-(7.1.26), see
:mod:`.sensitivity`), one simulation per iteration instead of 2p + 1.
Parameters change in place (``CompiledModel.set_parameters``): nothing is recompiled.

The covariance is the Gauss-Newton one, s^2 (J^T J)^-1 with s^2 = SSR / (N - p)
(Seber & Wild 1989, 2.1), from which the standard errors and the correlation matrix.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..runtime import CompiledModel
from ..solvers.base import SimulationError

__all__ = ["estimate", "Estimate"]


@dataclass
class Estimate:
    """What :func:`estimate` returns.

    ``values``, ``std_errors``: dicts by parameter name; ``correlation``: matrix in the
    order of ``names``; ``rms``: root-mean-square of the unscaled residuals per output;
    ``optimizer``: scipy's OptimizeResult.
    """

    names: list
    values: dict
    std_errors: dict
    correlation: np.ndarray
    covariance: np.ndarray
    rms: dict
    success: bool
    message: str
    n_simulations: int
    optimizer: object = field(repr=False, default=None)

    def __getitem__(self, name):
        return self.values[name]


def estimate(model, data: dict, parameters, *, outputs=None, bounds=None, sigma=None,
             rtol: float = 1e-8, diff_step: float = 1e-4, max_nfev: int = 200,
             sensitivities: str = "fd", progress: bool | None = None,
             executor=None) -> Estimate:
    """Fit parameters of a model to measured time series.

    Parameters
    ----------
    model : Component or CompiledModel
    data : dict
        ``"t"``: the sample times (increasing), and one array per measured variable,
        by its name in the model (``{"t": t, "tank.q": q}``).
    parameters : dict or list
        Parameter names with start values (a list starts from the model's values).
    outputs : list of str, optional
        Which measured variables to fit (default: every key of ``data`` but ``"t"``).
    bounds : dict, optional
        ``{name: (low, high)}``; by default a parameter keeps the sign of its start
        value (``(0, inf)`` for a positive one), which keeps a bad start physical.
    sigma : dict, optional
        Measurement standard deviation per output (weights 1/sigma); by default each
        output is scaled by its largest absolute value.
    rtol : float
        Simulation tolerance; keep it well below the noise.
    diff_step : float
        Relative step of the finite-difference sensitivities.
    sensitivities : {"fd", "forward"}
        Finite differences of simulations, or forward sensitivity equations (a model
        with a static choice of states).
    max_nfev : int
        Limit on optimizer iterations (function evaluations).
    progress : bool or None
        Count the simulations on a tqdm bar (None: only when stderr is a terminal).
    executor : optional
        Where the 2 p simulations of each finite-difference Jacobian run
        (:func:`acausal.sweep`'s executors: ``"processes"``, a concurrent.futures
        Executor, a dask Client); None runs them here, one after the other.

    Returns
    -------
    Estimate

    Notes
    -----
    The standard errors assume independent residuals of equal variance per output after
    weighting; they are meaningful when the model is right and the noise is white.
    """
    from ..simulation import compile as compile_model
    compiled = model if isinstance(model, CompiledModel) else compile_model(model)
    start = _start_values(compiled, parameters)
    names = list(start)
    t = np.asarray(data["t"], dtype=float)
    outs = list(outputs) if outputs is not None else [k for k in data if k not in ("t", "time")]
    y = {k: np.asarray(data[k], dtype=float) for k in outs}
    w = {k: 1.0 / (sigma[k] if sigma else max(np.abs(y[k]).max(), 1e-300)) for k in outs}
    scale = np.array([abs(v) if v != 0 else 1.0 for v in start.values()])
    lo, hi = _bounds(names, start, bounds, scale)
    problem = (_ForwardProblem if sensitivities == "forward" else _Problem)(
        compiled, names, scale, t, y, w, rtol)
    problem.executor = executor
    x0 = np.clip(np.array(list(start.values())) / scale, lo, hi)
    saved = compiled.p.copy()
    from scipy.optimize import least_squares

    from ..sweeps import _RunsBar
    problem.bar = _RunsBar.make(progress, None, desc="simulations")
    try:
        opt = least_squares(problem.residual, x0,
                            jac=lambda x: problem.jacobian(x, diff_step),
                            bounds=(lo, hi), x_scale="jac", max_nfev=max_nfev,
                            xtol=1e-12, ftol=1e-12, gtol=1e-12)
        return _summary(problem, opt, names, scale, outs)
    finally:
        compiled.p[:] = saved
        problem.bar.close()


def _start_values(compiled, parameters) -> dict:
    if isinstance(parameters, dict):
        return {k: float(v) for k, v in parameters.items()}
    out = {}
    for name in parameters:
        if name not in compiled.param_names:
            compiled.set_parameters({name: 0.0})        # raises the explanatory KeyError
        out[name] = float(compiled.p[compiled.param_names.index(name)])
    return out


def _bounds(names, start, bounds, scale):
    lo, hi = [], []
    for name, s in zip(names, scale):
        v = start[name]
        b = (bounds or {}).get(name, (0.0, np.inf) if v > 0 else (-np.inf, 0.0) if v < 0
                               else (-np.inf, np.inf))
        lo.append(b[0] / s)
        hi.append(b[1] / s)
    return np.array(lo), np.array(hi)


class _Problem:
    """Weighted residuals r(x) = w (y^(t | x scale) - y) of every output, stacked."""

    def __init__(self, compiled, names, scale, t, y, w, rtol):
        self.compiled, self.names, self.scale = compiled, names, scale
        self.t, self.y, self.w, self.rtol = t, y, w, rtol
        self.n_sim = 0
        self.size = sum(len(v) for v in y.values())
        self.bar = None             # counts the simulations (estimate's progress=)

    def predict(self, x) -> dict:
        from ..simulation import simulate
        self._count()
        values = dict(zip(self.names, x * self.scale))
        res = simulate(self.compiled, t_end=self.t[-1], t_start=self.t[0], t_eval=self.t,
                       rtol=self.rtol, atol=self.rtol, parameters=values,
                       raise_on_failure=True, progress=False)
        return {k: res[k] for k in self.y}

    def _count(self) -> None:
        self.n_sim += 1
        if self.bar is not None:
            self.bar.update(1)

    def residual(self, x) -> np.ndarray:
        try:
            pred = self.predict(x)
        except (SimulationError, ValueError, ArithmeticError):
            # a parameter set the model cannot run with: a large, finite misfit keeps the
            # trust region shrinking back towards where it could
            return np.full(self.size, 1e3)
        return np.concatenate([self.w[k] * (pred[k] - self.y[k]) for k in self.y])

    executor = None             # where the Jacobian's simulations run (estimate's executor=)

    def jacobian(self, x, rel) -> np.ndarray:
        if self.executor is not None:
            return self._jacobian_on(self.executor, x, rel)
        cols = []
        for j in range(len(x)):
            h = rel * max(abs(x[j]), 1e-3)
            xp, xm = x.copy(), x.copy()
            xp[j] += h
            xm[j] -= h
            cols.append((self.residual(xp) - self.residual(xm)) / (2 * h))
        return np.column_stack(cols)


    def _jacobian_on(self, executor, x, rel) -> np.ndarray:
        """The same central differences, the 2 p simulations spread by the ensemble
        engine (:mod:`acausal.sweeps`); a run that fails gives the same large misfit as
        :meth:`residual`."""
        from ..sweeps import ensemble
        steps, runs = [], []
        for j in range(len(x)):
            h = rel * max(abs(x[j]), 1e-3)
            for sgn in (1.0, -1.0):
                xs = x.copy()
                xs[j] += sgn * h
                runs.append(dict(zip(self.names, xs * self.scale)))
            steps.append(h)
        ds = ensemble(self.compiled, runs, t_end=self.t[-1], t_start=self.t[0],
                      t_eval=self.t, rtol=self.rtol, atol=self.rtol, names=list(self.y),
                      executor=executor, progress=False)
        for _ in runs:
            self._count()

        def misfit(i):
            if not bool(ds["success"][i]):
                return np.full(self.size, 1e3)
            return np.concatenate([self.w[k] * (ds[k].values[i] - self.y[k]) for k in self.y])
        return np.column_stack([(misfit(2 * j) - misfit(2 * j + 1)) / (2 * h)
                                for j, h in enumerate(steps)])


class _ForwardProblem(_Problem):
    """Residuals and their Jacobian from one simulation with forward sensitivities."""

    _last = None

    def _evaluate(self, x):
        if self._last is not None and np.array_equal(self._last[0], x):
            return self._last[1:]
        from .sensitivity import output_sensitivities, simulate_sensitivities
        c = self.compiled
        saved = c.p.copy()
        idx = [c.param_names.index(n) for n in self.names]
        self._count()
        try:
            c.p[idx] = x * self.scale
            t, Z, S = simulate_sensitivities(c, idx, self.t, rtol=self.rtol)
            Y, dY = output_sensitivities(c, t, Z, S, idx, list(self.y))
        except (ValueError, ArithmeticError) as err:     # SimulationError is a ValueError
            raise _Failed from err
        finally:
            c.p[:] = saved
        r = np.concatenate([self.w[k] * (Y[:, o] - self.y[k]) for o, k in enumerate(self.y)])
        # dY is p_j dy/dp_j and p_j = x_j scale_j, so dy/dx_j = dY / x_j
        J = np.column_stack([np.concatenate([self.w[k] * dY[:, b, o] / x[b]
                                             for o, k in enumerate(self.y)])
                             for b in range(len(x))])
        self._last = (x.copy(), r, J)
        return r, J

    def residual(self, x):
        try:
            return self._evaluate(x)[0]
        except _Failed:
            return np.full(self.size, 1e3)

    def jacobian(self, x, rel):
        try:
            return self._evaluate(x)[1]
        except _Failed:
            return super().jacobian(x, rel)


class _Failed(Exception):
    """The model could not be simulated with these parameter values."""


def _summary(problem, opt, names, scale, outs) -> Estimate:
    theta = opt.x * scale
    r = opt.fun
    n, p = len(r), len(theta)
    J = problem.jacobian(opt.x, 1e-4) / scale[None, :]        # d r / d theta
    s2 = float(r @ r) / max(n - p, 1)
    cov = s2 * np.linalg.pinv(J.T @ J)
    se = np.sqrt(np.abs(np.diag(cov)))
    corr = cov / np.outer(se, se) if np.all(se > 0) else np.full_like(cov, np.nan)
    rms, k0 = {}, 0
    for k in outs:
        m = len(problem.y[k])
        rms[k] = float(np.sqrt(np.mean((r[k0:k0 + m] / problem.w[k]) ** 2)))
        k0 += m
    return Estimate(names, dict(zip(names, theta.tolist())), dict(zip(names, se.tolist())),
                    corr, cov, rms, bool(opt.success), str(opt.message), problem.n_sim, opt)
