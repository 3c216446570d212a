"""Consistent initial values for index-1 DAEs F(t, y, y') = 0.

Two formulations (see items 9-10 of :mod:`acausal.solvers.base`):

``reinitialize`` -- IDA's ``YA_YDP_INIT`` (Brown, Hindmarsh & Petzold 1998; Hindmarsh
et al. 2005; ``IDACalcIC``).  The differential components of y are trusted; the unknowns
are ``u = (y[algebraic], y'[differential])`` (y' of an algebraic variable appears in
no equation and is set to zero).  For an index-1 DAE the Jacobian of F with respect to
``u``, made of the columns ``dF/dy[:, algebraic]`` and ``dF/dy'[:, differential]``, is
non-singular (Brenan, Campbell & Petzold 1996, ch. 2), so Newton's method applies.
``dF/dy'`` is taken from the iteration matrix, which is linear in ``cj``:
``dF/dy' = J(cj=1) - J(cj=0)``.  Used at the start and after every event.

``initialize_with_equations`` -- when the problem defines ``init_residual`` the free
initial values are fixed by those equations instead: unknowns all of y plus
``y'[differential]``, equations ``F = 0`` and ``G = 0``.

Both use damped Newton and fall back on a Newton homotopy
(:mod:`acausal.solvers.newton`); failure raises :class:`InitializationFailed` naming
the variables and equations that did not converge.
"""
from __future__ import annotations

import numpy as np

from .base import DAEProblem, InitializationFailed, equation_label
from .linalg import SingularMatrixError, issparse
from .newton import damped_newton, homotopy

__all__ = ["consistent_initial", "reinitialize", "initialize_with_equations",
           "solve_with_fallback"]

_NEWTON_TOL = 1e-5   # weighted step, relative to the integration tolerance
_N_NAMED = 3         # how many culprits an error message names


def _columns(J, idx):
    return J.tocsc()[:, idx] if issparse(J) else J[:, idx]


def _hstack(blocks):
    if any(issparse(b) for b in blocks):
        import scipy.sparse as sp
        return sp.hstack(blocks, format="csc")
    return np.hstack(blocks)


def _vstack(blocks):
    if any(issparse(b) for b in blocks):
        import scipy.sparse as sp
        return sp.vstack(blocks, format="csc")
    return np.vstack(blocks)


def _dF(problem, t, y, yp):
    """(dF/dy, dF/dy') from the iteration matrix at cj = 0 and cj = 1."""
    J0 = problem.jacobian(t, y, yp, 0.0)
    J1 = problem.jacobian(t, y, yp, 1.0)
    return J0, J1 - J0


def _weights(x, rtol, atol):
    return 1.0 / (rtol * np.abs(x) + atol)


def _top(values, k=_N_NAMED):
    v = np.nan_to_num(np.abs(np.asarray(values, float)), nan=np.inf)
    if not v.size or v.max() <= 0:
        return []
    order = np.argsort(-v, kind="stable")
    return [int(i) for i in order[:k] if v[i] >= 0.01 * v.max()]


def solve_with_fallback(fun, jac, x0, weights, what, labels, eq_labels, t):
    """Damped Newton, then homotopy; raise InitializationFailed naming the culprits.

    ``labels``: names of the unknowns; ``eq_labels(i)``: the name of residual row i.
    """
    singular = newton = res = None
    try:
        newton = damped_newton(fun, jac, x0, weights=weights, tol=_NEWTON_TOL)
        if newton.converged:
            return newton.x
    except SingularMatrixError as exc:
        singular = exc
    try:
        res = homotopy(fun, jac, x0, weights=weights, tol=_NEWTON_TOL)
        if res.converged:
            return res.x
    except SingularMatrixError as exc:
        singular = exc
    if newton is not None and (res is None or not np.any(res.step)):
        res = newton     # its last Newton step says which unknowns would not settle
    if singular is not None and not singular.cols and not singular.rows:
        singular = None
    if singular is not None:
        variables = [labels[c] for c in singular.cols if c < len(labels)]
        equations = [eq_labels(r) for r in singular.rows]
        raise InitializationFailed(
            f"{what}: the Jacobian is singular in variables {variables} "
            f"(equations {equations}); the DAE may be of higher index, or the "
            f"initial equations are not independent", t, variables, equations)
    variables = [labels[i] for i in _top(res.step)]
    equations = [eq_labels(i) for i in _top(res.residual)]
    raise InitializationFailed(
        f"{what} did not converge ({res.message}); largest corrections in "
        f"{variables}, largest residuals in {equations}", t, variables, equations,
        res.residual)


def reinitialize(problem: DAEProblem, t: float, y, yp=None, *, rtol: float = 1e-6,
                 atol=1e-8):
    """Consistent (y, y') keeping ``y[differential]`` fixed (``YA_YDP_INIT``).

    Parameters
    ----------
    problem : DAEProblem
    t : float
    y, yp : array_like
        Values to start from; ``yp=None`` means zeros.
    rtol, atol : float or array_like
        Scale of the convergence test (atol is multiplied by ``problem.nominal``).

    Returns
    -------
    y, yp : ndarray
        Consistent values.

    Raises
    ------
    InitializationFailed
    """
    n = problem.n
    y = np.array(y, dtype=float)
    yp = np.zeros(n) if yp is None else np.array(yp, dtype=float)
    alg = np.flatnonzero(np.asarray(problem.algebraic, bool))
    dif = np.flatnonzero(~np.asarray(problem.algebraic, bool))
    yp[alg] = 0.0
    na = alg.size
    atol_v = np.broadcast_to(np.asarray(atol, float), (n,)) * problem.nominal

    def unpack(u):
        yy, yyp = y.copy(), yp.copy()
        yy[alg] = u[:na]
        yyp[dif] = u[na:]
        return yy, yyp

    def fun(u):
        return problem.residual(t, *unpack(u))

    def jac(u):
        Jy, Jyp = _dF(problem, t, *unpack(u))
        return _hstack([_columns(Jy, alg), _columns(Jyp, dif)])

    def weights(u):
        return _weights(u, rtol, np.concatenate([atol_v[alg], atol_v[dif]]))

    labels = [problem.names[i] for i in alg] + [f"der({problem.names[i]})" for i in dif]
    u = solve_with_fallback(fun, jac, np.concatenate([y[alg], yp[dif]]), weights,
               "consistent initialization (algebraic variables and derivatives)",
               labels, lambda i: equation_label(problem, i), t)
    return unpack(u)


def initialize_with_equations(problem: DAEProblem, t: float, y, yp=None, *,
                              rtol: float = 1e-6, atol=1e-8):
    """Consistent (y, y') from F = 0 and ``problem.init_residual`` = 0.

    Unknowns are all of y and ``y'[differential]``; ``y0``/``yp0`` are the start
    guesses.  The Jacobian of the initial equations comes from
    ``problem.init_jacobian(t, y, yp) -> (dG/dy, dG/dy')`` when defined, else from
    forward differences.  Parameters, returns and exceptions as :func:`reinitialize`.
    """
    n = problem.n
    y = np.array(y, dtype=float)
    yp = np.zeros(n) if yp is None else np.array(yp, dtype=float)
    dif = np.flatnonzero(~np.asarray(problem.algebraic, bool))
    yp[np.asarray(problem.algebraic, bool)] = 0.0
    atol_v = np.broadcast_to(np.asarray(atol, float), (n,)) * problem.nominal
    G = problem.init_residual

    def unpack(x):
        yyp = yp.copy()
        yyp[dif] = x[n:]
        return x[:n].copy(), yyp

    def fun(x):
        yy, yyp = unpack(x)
        return np.concatenate([problem.residual(t, yy, yyp), np.atleast_1d(G(t, yy, yyp))])

    def jac(x):
        yy, yyp = unpack(x)
        Jy, Jyp = _dF(problem, t, yy, yyp)
        Gy, Gyp = _init_jacobian(problem, t, yy, yyp)
        top = _hstack([Jy, _columns(Jyp, dif)])
        bottom = _hstack([Gy, _columns(Gyp, dif)])
        return _vstack([top, bottom])

    def weights(x):
        return _weights(x, rtol, np.concatenate([atol_v, atol_v[dif]]))

    labels = list(problem.names) + [f"der({problem.names[i]})" for i in dif]
    x = solve_with_fallback(fun, jac, np.concatenate([y, yp[dif]]), weights,
               "initialization with initial equations", labels,
               _init_equation_labeller(problem), t)
    yy, yyp = unpack(x)
    return yy, yyp


def _init_equation_labeller(problem):
    """Labels of [F; G]: residual labels, then ``problem.init_equation_names``."""
    n = problem.n
    init_names = getattr(problem, "init_equation_names", None)

    def label(i):
        if i < n:
            return equation_label(problem, i)
        k = i - n
        return str(init_names[k]) if init_names is not None else f"initial equation {k}"
    return label


def _init_jacobian(problem, t, y, yp):
    """(dG/dy, dG/dy') from ``init_jacobian`` or by forward differences."""
    if callable(getattr(problem, "init_jacobian", None)):
        Gy, Gyp = problem.init_jacobian(t, y, yp)
        return Gy, Gyp
    g0 = np.atleast_1d(problem.init_residual(t, y, yp))
    m, n = g0.size, problem.n
    Gy, Gyp = np.empty((m, n)), np.empty((m, n))
    for j in range(n):
        h = 1e-7 * max(abs(y[j]), problem.nominal[j])
        y1 = y.copy()
        y1[j] += h
        Gy[:, j] = (np.atleast_1d(problem.init_residual(t, y1, yp)) - g0) / h
        h = 1e-7 * max(abs(yp[j]), problem.nominal[j])
        yp1 = yp.copy()
        yp1[j] += h
        Gyp[:, j] = (np.atleast_1d(problem.init_residual(t, y, yp1)) - g0) / h
    return Gy, Gyp


def consistent_initial(problem: DAEProblem, t: float, y, yp=None, *,
                       rtol: float = 1e-6, atol=1e-8):
    """Entry point: :func:`initialize_with_equations` if the problem defines
    ``init_residual``, else :func:`reinitialize`."""
    if callable(getattr(problem, "init_residual", None)):
        return initialize_with_equations(problem, t, y, yp, rtol=rtol, atol=atol)
    return reinitialize(problem, t, y, yp, rtol=rtol, atol=atol)
