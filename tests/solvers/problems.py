"""Hand-written DAE problems shared by the solver tests and the benchmark."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from acausal.solvers import DAEProblem, EventAction


class VanDerPol(DAEProblem):
    """y1' = y2, y2' = mu((1 - y1^2) y2 - y1), written as F(t, y, y') = 0."""

    def __init__(self, mu=1000.0):
        super().__init__(2, ["x", "v"])
        self.mu = mu

    def residual(self, t, y, yp):
        return np.array([yp[0] - y[1], yp[1] - self.mu * ((1 - y[0] ** 2) * y[1] - y[0])])

    def jacobian(self, t, y, yp, cj):
        mu = self.mu
        return np.array([[cj, -1.0],
                         [mu * (2 * y[0] * y[1] + 1), cj - mu * (1 - y[0] ** 2)]])

    def ode(self, t, y):
        return [y[1], self.mu * ((1 - y[0] ** 2) * y[1] - y[0])]

    def ode_jac(self, t, y):
        mu = self.mu
        return [[0.0, 1.0], [-mu * (2 * y[0] * y[1] + 1), mu * (1 - y[0] ** 2)]]


class Robertson(DAEProblem):
    """Robertson's kinetics with the conservation law as an algebraic equation."""

    def __init__(self):
        super().__init__(3, ["y1", "y2", "y3"])
        self.algebraic[2] = True

    def residual(self, t, y, yp):
        return np.array([yp[0] + 0.04 * y[0] - 1e4 * y[1] * y[2],
                         yp[1] - 0.04 * y[0] + 1e4 * y[1] * y[2] + 3e7 * y[1] ** 2,
                         y[0] + y[1] + y[2] - 1.0])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj + 0.04, -1e4 * y[2], -1e4 * y[1]],
                         [-0.04, cj + 1e4 * y[2] + 6e7 * y[1], 1e4 * y[1]],
                         [1.0, 1.0, 1.0]])

    @staticmethod
    def ode(t, y):
        return [-0.04 * y[0] + 1e4 * y[1] * y[2],
                0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2,
                3e7 * y[1] ** 2]

    @staticmethod
    def ode_jac(t, y):
        return [[-0.04, 1e4 * y[2], 1e4 * y[1]],
                [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]],
                [0.0, 6e7 * y[1], 0.0]]


class DampedOscillator(DAEProblem):
    """x'' + 2 zeta w x' + w^2 x = 0 as x' = v, v' = -2 zeta w v - w^2 x."""

    def __init__(self, w=2.0, zeta=0.1):
        super().__init__(2, ["x", "v"])
        self.w, self.zeta = w, zeta

    def residual(self, t, y, yp):
        w, z = self.w, self.zeta
        return np.array([yp[0] - y[1], yp[1] + 2 * z * w * y[1] + w * w * y[0]])

    def jacobian(self, t, y, yp, cj):
        w, z = self.w, self.zeta
        return np.array([[cj, -1.0], [w * w, cj + 2 * z * w]])

    def ode(self, t, y):
        w, z = self.w, self.zeta
        return [y[1], -2 * z * w * y[1] - w * w * y[0]]

    def exact(self, t, x0=1.0, v0=0.0):
        """Closed-form (x, v) of the under-damped oscillator."""
        w, z = self.w, self.zeta
        wd = w * np.sqrt(1 - z * z)
        a, b = x0, (v0 + z * w * x0) / wd
        e = np.exp(-z * w * t)
        x = e * (a * np.cos(wd * t) + b * np.sin(wd * t))
        v = -z * w * x + e * (-a * wd * np.sin(wd * t) + b * wd * np.cos(wd * t))
        return x, v


class LinearIndex1(DAEProblem):
    """x' = -x + z, 0 = z - cos(t) - x/2; x = (x0-0.4)e^{-t/2} + 0.4cos t + 0.8 sin t."""

    def __init__(self):
        super().__init__(2, ["x", "z"])
        self.algebraic[1] = True
        self.equation_names = ["der(x) = -x + z", "z = cos(t) + x/2"]

    def residual(self, t, y, yp):
        return np.array([yp[0] + y[0] - y[1], y[1] - np.cos(t) - 0.5 * y[0]])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj + 1.0, -1.0], [-0.5, 1.0]])

    @staticmethod
    def exact(t, x0):
        x = (x0 - 0.4) * np.exp(-t / 2) + 0.4 * np.cos(t) + 0.8 * np.sin(t)
        return x, np.cos(t) + 0.5 * x


class BouncingBall(DAEProblem):
    """h' = v, v' = -g; at h = 0 (falling) v := -e v."""

    n_roots = 1

    def __init__(self, e=0.8, g=9.81):
        super().__init__(2, ["h", "v"])
        self.e, self.g = e, g

    def residual(self, t, y, yp):
        return np.array([yp[0] - y[1], yp[1] + self.g])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj, -1.0], [0.0, cj]])

    def roots(self, t, y, yp):
        return np.array([y[0]])

    def handle_event(self, t, y, yp, crossed):
        if crossed[0] and y[1] < 0:
            return EventAction(y=np.array([y[0], -self.e * y[1]]))
        return EventAction(changed=False)

    def bounce_times(self, h0, k):
        """First k impact times from rest at height h0."""
        t = [np.sqrt(2 * h0 / self.g)]
        v = self.g * t[0]
        for _ in range(k - 1):
            v *= self.e
            t.append(t[-1] + 2 * v / self.g)
        return np.array(t)


class BlowUp(DAEProblem):
    """y' = y^2, y(0) = 1: y = 1/(1 - t) blows up at t = 1."""

    def __init__(self):
        super().__init__(1, ["y"])

    def residual(self, t, y, yp):
        return yp - y * y

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj - 2 * y[0]]])


class Decay(DAEProblem):
    """y' = -y."""

    def __init__(self, n=1):
        super().__init__(n)

    def residual(self, t, y, yp):
        return yp + y

    def jacobian(self, t, y, yp, cj):
        return np.eye(self.n) * (cj + 1.0)


class HeatChain(DAEProblem):
    """Method-of-lines heat equation u_t = u_xx on n nodes, as a DAE.

    Node 0 is algebraic (Dirichlet: u_0 = 1), node n-1 algebraic (Neumann:
    u_{n-1} = u_{n-2}); the interior nodes are differential.
    """

    def __init__(self, n=200, sparse=True):
        super().__init__(n, [f"u[{i}]" for i in range(n)])
        self.algebraic[0] = self.algebraic[-1] = True
        self.c = (n - 1) ** 2 * 1e-2     # diffusivity / dx^2 on [0, 1], kappa = 1e-2
        self.sparse = sparse
        J0 = self._matrix(0.0)
        J1 = self._matrix(1.0)
        self._J0, self._dJ = J0, J1 - J0
        if sparse:
            coo = J1.tocoo()
            self.jac_pattern = (coo.row, coo.col)

    def _matrix(self, cj):
        n, c = self.n, self.c
        main = np.full(n, cj + 2 * c)
        main[0] = main[-1] = 1.0
        lower = np.full(n - 1, -c)
        upper = np.full(n - 1, -c)
        upper[0] = 0.0
        lower[-1] = -1.0
        return sp.diags([lower, main, upper], [-1, 0, 1], format="csc")

    def residual(self, t, y, yp):
        r = np.empty(self.n)
        c = self.c
        r[1:-1] = yp[1:-1] - c * (y[:-2] - 2 * y[1:-1] + y[2:])
        r[0] = y[0] - 1.0
        r[-1] = y[-1] - y[-2]
        return r

    def jacobian(self, t, y, yp, cj):
        J = self._J0 + cj * self._dJ
        return J if self.sparse else J.toarray()

    def reference(self, t, u0):
        """Exact solution of the semi-discrete system (matrix exponential)."""
        from scipy.linalg import expm
        n, c = self.n, self.c
        m = n - 2
        A = np.diag(np.full(m, -2 * c)) + np.diag(np.full(m - 1, c), 1) \
            + np.diag(np.full(m - 1, c), -1)
        A[-1, -1] += c          # u_{n-1} = u_{n-2}
        b = np.zeros(m)
        b[0] = c                # u_0 = 1
        xs = np.linalg.solve(A, -b)
        x = expm(A * t) @ (u0[1:-1] - xs) + xs
        return np.concatenate([[1.0], x, [x[-1]]])


class VanDerPolClassic(VanDerPol):
    """The unscaled form y1' = y2, y2' = mu (1 - y1^2) y2 - y1 (period ~1600 for mu=1000)."""

    def residual(self, t, y, yp):
        return np.array([yp[0] - y[1], yp[1] - self.mu * (1 - y[0] ** 2) * y[1] + y[0]])

    def jacobian(self, t, y, yp, cj):
        mu = self.mu
        return np.array([[cj, -1.0],
                         [2 * mu * y[0] * y[1] + 1, cj - mu * (1 - y[0] ** 2)]])

    def ode(self, t, y):
        return [y[1], self.mu * (1 - y[0] ** 2) * y[1] - y[0]]

    def ode_jac(self, t, y):
        mu = self.mu
        return [[0.0, 1.0], [-2 * mu * y[0] * y[1] - 1, mu * (1 - y[0] ** 2)]]


class OscillatorChain(DAEProblem):
    """N equal masses in a chain of springs (and optional dashpots), fixed at the far
    end, the near end moved by a smooth ramp: a linear DAE with N weakly damped modes.

    y = (x_0, x_1..x_N, v_1..v_N); x_0 is algebraic, ``x_0 = u(t) = (1 - e^{-a t})^2``
    (u(0) = u'(0) = 0); ``x_i' = v_i`` and
    ``v_i' = w^2 (x_{i-1} - 2 x_i + x_{i+1}) + d w^2 (v_{i-1} - 2 v_i + v_{i+1})``
    (x_{N+1} = 0, v_0 = u').  Both ends are displacement-driven, so the modes have the
    frequencies ``w_k = 2 w sin(k pi / (2 (N + 1)))``, k = 1..N, up to ``2 w``; the
    stiffness-proportional damping ``d`` gives them damping ratios ``d w_k / 2``.
    """

    def __init__(self, N=40, w=5e3, d=0.0, a=200.0):
        super().__init__(2 * N + 1, ["x[0]"] + [f"x[{i}]" for i in range(1, N + 1)]
                         + [f"v[{i}]" for i in range(1, N + 1)])
        self.N, self.w2, self.d, self.a = N, w * w, d, a
        self.algebraic[0] = True
        K = self.w2 * (np.diag(np.full(N, -2.0)) + np.diag(np.ones(N - 1), 1)
                       + np.diag(np.ones(N - 1), -1))
        # dy'/dt block of the state (x_1..x_N, v_1..v_N) and the input column (x_0)
        self.A = np.block([[np.zeros((N, N)), np.eye(N)], [K, d * K]])
        self.b = np.zeros(2 * N)
        self.b[N] = self.w2
        self.bd = np.zeros(2 * N)
        self.bd[N] = d * self.w2
        J0 = np.zeros((self.n, self.n))
        J0[0, 0] = 1.0
        J0[1:, 1:] = -self.A
        J0[1:, 0] = -self.b
        E = np.zeros((self.n, self.n))
        E[1:, 1:] = np.eye(2 * N)
        E[1:, 0] = -self.bd       # the dashpot at the driven end sees x_0'
        self._J0, self._E = J0, E

    def u(self, t):
        e = np.exp(-self.a * t)
        return (1.0 - e) ** 2

    def residual(self, t, y, yp):
        r = self._J0 @ y + self._E @ yp
        r[0] -= self.u(t)
        return r

    def jacobian(self, t, y, yp, cj):
        return self._J0 + cj * self._E

    def initial(self):
        return np.zeros(self.n), np.zeros(self.n)

    def ode(self, t, y):
        """The same system as an ODE in y (x_0' = u'(t)), for ODE solvers."""
        e = np.exp(-self.a * t)
        du = 2.0 * self.a * e * (1.0 - e)
        return np.concatenate([[du], self.A @ y[1:] + self.b * y[0] + self.bd * du])

    def ode_jac(self, t, y):
        J = np.zeros((self.n, self.n))
        J[1:, 1:] = self.A
        J[1:, 0] = self.b
        return J

    def exact(self, ts):
        """y at the times ``ts`` (rows): the matrix exponential of the system augmented
        with the input's exponentials, u = 1 - 2 e1 + e2, e1' = -a e1, e2' = -2a e2."""
        from scipy.linalg import expm
        m, a = 2 * self.N, self.a
        M = np.zeros((m + 3, m + 3))
        M[:m, :m] = self.A
        # x_0 = u = c - 2 e1 + e2 with a constant state c = 1; x_0' = 2a e1 - 2a e2
        M[:m, m] = self.b
        M[:m, m + 1] = -2 * self.b + 2 * a * self.bd
        M[:m, m + 2] = self.b - 2 * a * self.bd
        M[m + 1, m + 1], M[m + 2, m + 2] = -a, -2 * a
        z0 = np.zeros(m + 3)
        z0[m:] = 1.0
        zs = np.array([expm(M * t) @ z0 for t in np.atleast_1d(ts)])
        return np.column_stack([self.u(np.atleast_1d(ts)), zs[:, :m]])


class Chamber(DAEProblem):
    """A filling hydraulic chamber, x' = 1, (V(x)/beta) p' = q, V = 1e-4 + 1e-3 x,
    beta = 7e8, q = 1e-4, with the pressure's derivative as an algebraic unknown
    (``dp``, as a model compiler leaves it): the iteration matrix has a pivot ~1e-13.
    p = 7e7 ln(1 + 10 t)."""

    def __init__(self):
        super().__init__(3, ["x", "p", "der(p)"])
        self.algebraic[2] = True

    def residual(self, t, y, yp):
        return np.array([yp[0] - 1.0, yp[1] - y[2],
                         (1e-4 + 1e-3 * y[0]) / 7e8 * y[2] - 1e-4])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj, 0.0, 0.0], [0.0, cj, -1.0],
                         [1e-3 / 7e8 * y[2], 0.0, (1e-4 + 1e-3 * y[0]) / 7e8]])

    @staticmethod
    def exact(t):
        return t, 7e7 * np.log1p(10.0 * t)
