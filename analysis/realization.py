"""Numerics behind StateSpace: balancing, minimal realizations, invariant zeros and
transfer-function polynomials that are checked against the state-space model.

Every rank decision here is made on a *balanced* system and relative to that system's
own norm, so that the answer does not depend on the units of the states, inputs and
outputs (a ship's heading in rad next to a rudder rate in rad/s, a pressure in Pa next to
a speed in rad/s):

1. Inputs and outputs are scaled so that every column of B and every row of C has the
   norm of A (a scaling of u and y changes H(s) by constant factors only, which are
   undone at the end).
2. The states are balanced by a diagonal similarity x = S x_b of powers of two (exact
   in floating point) that equalizes the off-diagonal 1-norms of each state's row of
   [A B] and column of [A; C], as LAPACK's xGEBAL does for a matrix (Parlett & Reinsch
   1969) and SLICOT's TB01ID for a system.
3. Controllable and observable subspaces come from the orthogonal staircase form
   (Van Dooren 1981; Varga 2017, ch. 2): at each step the new directions are the
   singular vectors of the coupling block above ``tol`` = rtol ||[A B]||.
4. Invariant zeros are those of the Rosenbrock system pencil, found by the reduction of
   Emami-Naeini & Van Dooren (1982): orthogonal row and column compressions remove the
   infinite zeros until the feedthrough is invertible, and the finite zeros are then
   the eigenvalues of A - B D^-1 C of the reduced system, exactly as many as remain
   states -- no threshold on generalized eigenvalues "near infinity" is needed.
5. A transfer function num/den is accepted only if H(jw) from its polynomials matches
   the state-space H(jw) = C (jwI - A)^-1 B + D at frequencies spread over the scale of
   its poles and zeros, within a bound on the round-off of polynomial evaluation.
   Otherwise the numerator is recomputed by interpolation, den(s) H(s) sampled on a
   circle whose radius is the scale of the poles (a discrete Fourier transform of the
   scaled polynomial), and a :class:`TransferFunctionWarning` says so.
"""
from __future__ import annotations

import warnings

import numpy as np
from ..errors import TransferFunctionWarning

__all__ = ["TransferFunctionWarning", "balance", "scaled", "controllable_basis",
           "minimal_realization", "invariant_zeros", "tf_polynomials", "check_frequencies",
           "frequency_response", "same_response", "RTOL"]

RTOL = 1e-10           # default relative rank tolerance (times the state dimension)
_EPS = np.finfo(float).eps
_CHECK_RTOL = 1e-6     # accepted change of H(jw) when modes are removed, relative
_TF_RTOL = 1e-5        # accepted mismatch of num/den, relative to its evaluation bound


# -- scaling ----------------------------------------------------------------------------------
def scaled(A, B, C, D=None):
    """The system prepared for rank decisions (module docstring, items 1-2).

    Returns (A_b, B_b, C_b, D_b, s, bu, cy) with x = diag(s) x_b, u = bu u_b and
    y_b = cy y: B_b = S^-1 B diag(bu), C_b = diag(cy) C S, D_b = diag(cy) D diag(bu);
    every non-zero column of B_b and row of C_b has about the norm of A_b."""
    A, B, C = np.asarray(A, float), np.asarray(B, float), np.asarray(C, float)
    D = np.zeros((C.shape[0], B.shape[1])) if D is None else np.asarray(D, float)
    # balance with unit-norm inputs and outputs, then give B and C the norm of A_b
    bu, cy = _unit_scales(B, axis=0), _unit_scales(C, axis=1)
    Ab, Bb, Cb, s = balance(A, B * bu, cy[:, None] * C)
    a = np.linalg.norm(Ab, 2) if Ab.size else 0.0
    a = float(_pow2(a)) if a > 0 else 1.0
    fb, fc = _unit_scales(Bb, axis=0) * a, _unit_scales(Cb, axis=1) * a
    bu, cy = bu * fb, cy * fc
    return Ab, Bb * fb, fc[:, None] * Cb, cy[:, None] * D * bu, s, bu, cy


def _unit_scales(M, axis):
    """Powers of two that bring each column (axis 0) or row (axis 1) to norm about 1."""
    nm = np.linalg.norm(M, axis=axis) if M.size else np.zeros(M.shape[1 - axis])
    return _pow2(np.where(nm > 0, 1.0 / np.where(nm > 0, nm, 1.0), 1.0))


def _pow2(x):
    """The power of two nearest each factor: scaling by it is exact."""
    return np.exp2(np.round(np.log2(x)))


def balance(A, B, C, max_sweeps: int = 100):
    """(A_b, B_b, C_b, s) with x = diag(s) x_b: each state's off-diagonal row of [A B]
    and column of [A; C] brought to comparable 1-norms by powers of two.

    As xGEBAL permutes isolated eigenvalues out before scaling, states coupled on one
    side only (nothing drives them, or they drive nothing, within what remains) are set
    aside first: their entries would otherwise dominate the norms of the states they
    touch.  They are scaled last, their one coupling to the typical norm of the rest."""
    A, B, C = np.array(A, float), np.array(B, float), np.array(C, float)
    n = A.shape[0]
    s = np.ones(n)
    core = _coupled_core(A, B, C)
    M = np.abs(A) * np.outer(core, core)
    np.fill_diagonal(M, 0.0)

    def norms(i):
        return M[:, i].sum() + np.abs(C[:, i]).sum(), M[i, :].sum() + np.abs(B[i, :]).sum()

    def scale(i, f):
        A[:, i] *= f
        A[i, :] /= f
        C[:, i] *= f
        B[i, :] /= f
        M[:, i] *= f
        M[i, :] /= f
        s[i] *= f

    for _ in range(max_sweeps):
        changed = False
        for i in np.flatnonzero(core):
            col, row = norms(i)
            f = float(np.exp2(np.round(0.5 * np.log2(row / col))))
            # accept only a clear gain, as xGEBAL does, so the sweeps terminate
            if f != 1.0 and col * f + row / f < 0.95 * (col + row):
                scale(i, f)
                changed = True
        if not changed:
            break
    both = [np.sqrt(np.prod(norms(i))) for i in np.flatnonzero(core)]
    typical = float(np.exp(np.mean(np.log(both)))) if both else 1.0
    for i in np.flatnonzero(~core):
        col = np.abs(A[:, i]).sum() - abs(A[i, i]) + np.abs(C[:, i]).sum()
        row = np.abs(A[i, :]).sum() - abs(A[i, i]) + np.abs(B[i, :]).sum()
        if col > 0.0 and row == 0.0:
            scale(i, float(_pow2(typical / col)))
        elif row > 0.0 and col == 0.0:
            scale(i, float(_pow2(row / typical)))
    return A, B, C, s


def _coupled_core(A, B, C) -> np.ndarray:
    """Mask of the states that, among the others of the mask, are both driven (by a
    state or an input) and drive something (a state or an output), found by peeling."""
    n = A.shape[0]
    core = np.ones(n, dtype=bool)
    off = A != 0.0
    np.fill_diagonal(off, False)
    has_b, has_c = np.any(B != 0.0, axis=1), np.any(C != 0.0, axis=0)
    while True:
        driven = has_b | (off & core[None, :]).any(axis=1)
        drives = has_c | (off & core[:, None]).any(axis=0)
        new = core & driven & drives
        if np.array_equal(new, core):
            return core
        core = new


# -- controllability, observability, minimality -------------------------------------------
def controllable_basis(A, B, tol: float) -> np.ndarray:
    """Orthonormal basis (n x nc) of the controllable subspace, by the staircase form:
    the directions of each new block are those of the coupling U^T A V_k into the
    still uncontrolled complement U whose singular values exceed ``tol``."""
    n = A.shape[0]
    U = np.eye(n)                     # orthonormal basis of what is not yet reached
    blocks, Z = [], B
    while U.shape[1] > 0 and Z.shape[1] > 0:
        P, sv, _ = np.linalg.svd(U.T @ Z, full_matrices=True)
        r = int(np.sum(sv > tol))
        if r == 0:
            break
        new = U @ P[:, :r]
        blocks.append(new)
        U = U @ P[:, r:]
        Z = A @ new
    return np.hstack(blocks) if blocks else np.zeros((n, 0))


def minimal_realization(A, B, C, D=None, rtol: float | None = None):
    """(A_m, B_m, C_m, T, Q) with x = T x_m: the controllable and observable part of
    (A, B, C), computed on the balanced system; ``T = diag(s) Q`` where Q has
    orthonormal columns in the balanced coordinates.

    A mode is removed only if that leaves H(jw) unchanged (to 1e-6 of its size, at
    frequencies over the scale of the poles); otherwise the rank tolerance is lowered
    and the reduction repeated, down to a few hundred ulps of the system's norm."""
    n = A.shape[0]
    rel = rtol if rtol is not None else max(n, 1) * RTOL
    Ab, Bb, Cb, Db, s, bu, cy = scaled(A, B, C, D)
    w = check_frequencies(np.linalg.eigvals(Ab))
    H = frequency_response(Ab, Bb, Cb, Db, w)
    while True:
        V, W = _kalman_bases(Ab, Bb, Cb, rel)
        Q = V @ W
        Am, Bm, Cm = Q.T @ Ab @ Q, Q.T @ Bb, Cb @ Q
        if Q.shape[1] == n or rel <= 1e3 * _EPS or \
                same_response(H, frequency_response(Am, Bm, Cm, Db, w)):
            break
        rel = max(rel * 1e-3, 1e3 * _EPS)
    return Am, Bm / bu, Cm / cy[:, None], s[:, None] * Q, Q


def _kalman_bases(A, B, C, rel):
    """V (controllable subspace of (A, B)) and W (observable part of (V'AV, CV))."""
    tol_c = rel * max(np.linalg.norm(np.hstack([A, B]), 2), np.finfo(float).tiny)
    V = controllable_basis(A, B, tol_c)
    A1, C1 = V.T @ A @ V, C @ V
    tol_o = rel * max(np.linalg.norm(np.vstack([A1, C1]), 2), np.finfo(float).tiny)
    return V, controllable_basis(A1.T, C1.T, tol_o)


def check_frequencies(roots) -> np.ndarray:
    """Frequencies spread (two a decade, at least seven) over the magnitudes of the
    poles and zeros, off round values and away from poles on the imaginary axis."""
    roots = np.asarray(roots, dtype=complex)
    mags = np.abs(roots)
    mags = mags[mags > 1e-12 * max(mags.max(initial=0.0), 1e-300)]
    lo, hi = (mags.min() / 3.0, mags.max() * 3.0) if mags.size else (0.3, 3.0)
    count = int(np.clip(2 * np.log10(hi / lo) + 3, 7, 25))
    w = np.geomspace(lo, hi, count) * 1.0137
    keep = [wk for wk in w if not roots.size or np.min(np.abs(1j * wk - roots)) > 1e-3 * wk]
    return np.array(keep if keep else w * 1.31)


def frequency_response(A, B, C, D, w) -> np.ndarray:
    """H(jw) = C (jwI - A)^-1 B + D, shape (len(w), p, m)."""
    n = A.shape[0]
    H = np.empty((len(w), C.shape[0], B.shape[1]), dtype=complex)
    for k, wk in enumerate(w):
        H[k] = (C @ np.linalg.solve(1j * wk * np.eye(n) - A, B) if n else 0.0) + D
    return H


def same_response(H, G, rtol: float = _CHECK_RTOL) -> bool:
    """Every channel of G within rtol of H at each frequency (judged against the
    channel's own size there, or a millionth of its largest where it is near a zero)."""
    scale = np.max(np.abs(H), axis=0, keepdims=True)
    return bool(np.all(np.abs(G - H) <= rtol * np.maximum(np.abs(H), 1e-6 * scale)))


# -- invariant zeros ---------------------------------------------------------------------------
def invariant_zeros(A, B, C, D, rtol: float | None = None) -> np.ndarray:
    """Finite invariant zeros of a square system (Emami-Naeini & Van Dooren 1982).

    Returns the zeros, or raises ValueError when the system matrix is singular for
    every s (H(s) singular: every s is a zero, the zeros are not defined)."""
    n, m = B.shape
    if C.shape[0] != m:
        raise ValueError("invariant zeros need a square system")
    A, B, C, D, *_ = scaled(A, B, C, D)
    rel = rtol if rtol is not None else max(n + m, 1) * RTOL
    tol = rel * max(np.linalg.norm(np.block([[A, B], [C, D]]), 2), np.finfo(float).tiny)
    singular = ValueError("the system matrix is singular for every s (H(s) is singular): "
                          "its zeros are not defined")
    while True:
        sigma, D, C = _compress_rows(D, C, tol)
        p = C.shape[0]
        if sigma == p:
            break
        if A.shape[0] == 0:
            raise singular
        # the last p - sigma outputs read the state alone: 0 = C2 x pins part of x
        _, sv, Vt = np.linalg.svd(C[sigma:], full_matrices=True)
        rho = int(np.sum(sv > tol))
        if rho < p - sigma:
            raise singular
        V = Vt[::-1].T                  # its last rho columns span the rows of C2
        A, B, C = V.T @ A @ V, V.T @ B, C @ V
        k = A.shape[0] - rho            # x = [x1; x2] with x2 = 0 on the kernel
        # the x2 rows of the state equation become outputs: 0 = A21 x1 + B2 u
        C = np.vstack([A[k:, :k], C[:sigma, :k]])
        D = np.vstack([B[k:], D[:sigma]])
        A, B = A[:k, :k], B[:k]
    if A.shape[0] == 0:
        return np.zeros(0, complex)
    return np.linalg.eigvals(A - B @ np.linalg.solve(D, C))


def _compress_rows(D, C, tol):
    """Rotate the outputs so that D = [D1; 0] with D1 of full row rank sigma."""
    if D.size == 0:
        return 0, D, C
    U, sv, _ = np.linalg.svd(D, full_matrices=True)
    sigma = int(np.sum(sv > tol))
    return sigma, U.T @ D, U.T @ C


# -- transfer functions -----------------------------------------------------------------------
def tf_polynomials(A, B, C, D, rtol: float | None = None, what: str = "H"):
    """(num, den) of a SISO realization (used as it is: minimality is the caller's).

    num = k prod(s - z_i) with the invariant zeros z_i and the first non-zero Markov
    parameter k; den = det(sI - A), monic.  Checked against the state-space H(jw);
    if the check fails the numerator is also computed by interpolation, the better of
    the two kept, and a :class:`TransferFunctionWarning` gives the mismatch."""
    n = A.shape[0]
    if n == 0:
        return np.array([float(D[0, 0])]), np.array([1.0])
    den = np.real(np.poly(A))
    try:
        num = _num_from_zeros(A, B, C, D, rtol)
    except ValueError:                # H = 0: every s is a zero
        num = np.array([0.0])
    defect, mismatch = _defect(num, den, A, B, C, D)
    if defect <= 1.0:
        return num, den
    first = mismatch
    other = _num_by_interpolation(A, B, C, D, den)
    defect_other, mismatch_other = _defect(other, den, A, B, C, D)
    if defect_other < defect:
        num, defect, mismatch = other, defect_other, mismatch_other
    route = "by interpolation of den(s) H(s)" if num is other else "from the zeros"
    verdict = "" if defect <= 1.0 else (
        f"; it still differs by {mismatch:.2g} of |H| (the poles are ill-conditioned in "
        "this realization)")
    warnings.warn(f"transfer function {what}: num/den from the zeros and the Markov "
                  f"parameter differed from the state-space H(jw) by {first:.2g} of |H|; "
                  f"the numerator was computed {route}{verdict}", TransferFunctionWarning,
                  stacklevel=3)
    return num, den


def _num_from_zeros(A, B, C, D, rtol):
    z = invariant_zeros(A, B, C, D, rtol)
    r = A.shape[0] - len(z)           # relative degree
    Ab, Bb, Cb, _, _, bu, cy = scaled(A, B, C)
    if r == 0:
        k = float(D[0, 0])
    else:
        v = Bb[:, 0]
        for _ in range(r - 1):
            v = Ab @ v
        k = float(Cb[0] @ v) / (bu[0] * cy[0])
    return np.real_if_close(k * np.poly(z)).real if len(z) else np.array([k])


def _defect(num, den, A, B, C, D):
    """(max over check frequencies of |num/den - H| / (rtol x its evaluation bound),
    max |num/den - H| / |H|): the first is <= 1 when the polynomials reproduce the
    state-space model."""
    roots = np.concatenate([np.linalg.eigvals(A), np.roots(num) if len(num) > 1 else []])
    w = check_frequencies(roots)
    s = 1j * w
    H = frequency_response(A, B, C, D, w)[:, 0, 0]
    dn, nn = np.polyval(den, s), np.polyval(num, s)
    # round-off of evaluating the polynomials: the sums of the absolute terms
    bound = (np.polyval(np.abs(num), w) + np.abs(H) * np.polyval(np.abs(den), w)) / np.abs(dn)
    scale = np.max(np.abs(H), initial=0.0)
    err = np.abs(nn / dn - H)
    defect = np.max(err / (_TF_RTOL * np.maximum(bound, 1e-14 * scale + 1e-300)))
    return float(defect), float(np.max(err / np.maximum(np.abs(H), 1e-300)))


def _num_by_interpolation(A, B, C, D, den):
    """num(s) = den(s) H(s) from samples on a circle |s| = rho (the pole scale): the
    coefficients of num(rho x) are the DFT of its values at the roots of unity."""
    n = A.shape[0]
    mags = np.abs(np.linalg.eigvals(A))
    mags = mags[mags > 0]
    rho = float(np.exp(np.mean(np.log(mags)))) if mags.size else 1.0
    N = 2 * (n + 1)
    x = np.exp(2j * np.pi * (np.arange(N) + 0.5) / N)    # half-offset: avoid s = rho
    vals = []
    for xk in x:
        sk = rho * xk
        H = (C @ np.linalg.solve(sk * np.eye(n) - A, B) + D)[0, 0]
        vals.append(np.polyval(den, sk) * H)
    vals = np.array(vals)
    # c_j rho^j = (1/N) sum_k vals_k x_k^-j, ascending powers
    j = np.arange(n + 1)
    asc = (np.exp(-2j * np.pi * np.outer(j, np.arange(N) + 0.5) / N) @ vals) / N
    coef = (asc / rho ** j).real
    coef = np.where(np.abs(coef * rho ** j) < 1e-13 * np.abs(coef * rho ** j).max(), 0.0, coef)
    return np.trim_zeros(coef[::-1], "f") if np.any(coef) else np.array([0.0])
