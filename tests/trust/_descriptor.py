"""Linear descriptor systems E x' = A x + b(t) reduced to an ODE by hand-written linear
algebra (numpy/scipy only), the reference for the circuit tests.

E is symmetric positive semi-definite (a nodal capacitance matrix, inductances on the
diagonal).  With E = Q diag(lambda) Q^T, x = Q1 z1 + Q2 z2 (Q1 the eigenvectors of the
non-zero eigenvalues, Q2 a basis of the null space) and M = Q^T A Q,

    lambda_1 z1' = M11 z1 + M12 z2 + Q1^T b,     0 = M21 z1 + M22 z2 + Q2^T b,

so for an index-1 system (M22 regular) z2 = -M22^-1 (M21 z1 + Q2^T b) and

    z1' = Ar z1 + Br b,   Ar = L^-1 (M11 - M12 M22^-1 M21),
                          Br = L^-1 (Q1^T - M12 M22^-1 Q2^T),   L = diag(lambda_1).

E x = Q1 diag(lambda_1) z1 is the stored charge/flux, so a circuit with every capacitor
uncharged and every inductor current zero starts at z1 = 0.  For a constant b the
solution is exact, from the matrix exponential (``constant_response``).

Before the split the system is scaled symmetrically, x = S x_s with S diagonal
(S_ii = E_ii^-1/2 where E_ii > 0, else the inverse square root of the row's largest
|A_ij|), S E S x_s' = S A S x_s + S b: capacitances of 1e-15 next to inductances of 1e-3
then do not look like zero eigenvalues.
"""
import numpy as np
import scipy.linalg as sla

__all__ = ["Descriptor"]


class Descriptor:
    """E x' = A x + b reduced to z1' = Ar z1 + Br b (see the module docstring)."""

    def __init__(self, E, A, rank_tol: float = 1e-9):
        E, A = np.asarray(E, dtype=float), np.asarray(A, dtype=float)
        d, a = np.diag(E), np.max(np.abs(A), axis=1)
        self.S = np.where(d > 0, 1.0 / np.sqrt(np.where(d > 0, d, 1.0)),
                          1.0 / np.sqrt(np.where(a > 0, a, 1.0)))
        E = self.S[:, None] * E * self.S[None, :]
        A = self.S[:, None] * A * self.S[None, :]
        lam, Q = np.linalg.eigh(0.5 * (E + E.T))
        keep = lam > rank_tol * max(lam.max(), 0.0)
        self.Q1, self.Q2 = Q[:, keep], Q[:, ~keep]
        M = Q.T @ A @ Q
        k = int(keep.sum())
        order = np.concatenate([np.flatnonzero(keep), np.flatnonzero(~keep)])
        M = M[np.ix_(order, order)]
        M11, M12, M21, M22 = M[:k, :k], M[:k, k:], M[k:, :k], M[k:, k:]
        self._lu = sla.lu_factor(M22) if M22.size else None
        self._M21 = M21
        inv_lam = 1.0 / lam[keep]
        S21 = self._solve(M21)                               # M22^-1 M21
        S2 = self._solve(self.Q2.T)                          # M22^-1 Q2^T
        self.Ar = inv_lam[:, None] * (M11 - M12 @ S21)
        self.Br = inv_lam[:, None] * (self.Q1.T - M12 @ S2)
        self.n_differential = k

    def _solve(self, rhs):
        if self._lu is None:
            return np.zeros((0,) + np.shape(rhs)[1:])
        return sla.lu_solve(self._lu, rhs)

    def rhs(self, z1, b):
        """z1' for the forcing b."""
        return self.Ar @ z1 + self.Br @ (self.S * b)

    def full(self, z1, b):
        """x from z1 and the forcing b (the algebraic part solved)."""
        x = self.Q1 @ z1
        if self._lu is not None:
            x = x - self.Q2 @ self._solve(self._M21 @ z1 + self.Q2.T @ (self.S * b))
        return self.S * x

    def constant_response(self, b, t, z0=None):
        """x(t_k) for a constant forcing b, exactly; rows = times.

        z1(t) = e^(Ar t) z0 + int_0^t e^(Ar s) ds Br b, both from one matrix exponential
        of [[Ar, Br b], [0, 0]] (no inverse of Ar: a loop of inductors has a conserved
        circulating current, a zero eigenvalue)."""
        k = self.n_differential
        z0 = np.zeros(k) if z0 is None else np.asarray(z0, dtype=float)
        M = np.zeros((k + 1, k + 1))
        M[:k, :k], M[:k, k] = self.Ar, self.Br @ (self.S * b)
        out = []
        for tk in np.atleast_1d(t):
            P = sla.expm(M * tk)
            out.append(self.full(P[:k, :k] @ z0 + P[:k, k], b))
        return np.array(out)
