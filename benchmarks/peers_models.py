"""The physics of M1..M5 written by hand, once, for the peer solvers of ``peers.py``.

Each model is a semi-explicit system

    x' = f(t, x, z, u),   0 = g(t, x, z, u)

(no z for the ODE forms) with a piecewise-constant input u, written from the component
equations of the library (the docstrings below give them).  One function serves numpy
(scipy's BDF, IDA's residual) and CasADi's SX: it receives an ``ops`` namespace with
``cat``, ``where``, ``sqrt``, ``fabs``, ``sin`` and ``cos``, so the peers share one
formulation, and a wrong formulation shows in every peer's deviation from acausal.

Tolerances follow acausal's default: atol_i = rtol * nominal_i, the nominal being the
one the library declares for the variable (1 where it declares none).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import scipy.sparse as sps

__all__ = ["Formulation", "NumpyOps", "ScalarOps", "formulations"]


class NumpyOps:
    """Vectorized numpy (the large linear models M1 and M4)."""

    @staticmethod
    def cat(*parts):
        return np.concatenate([np.atleast_1d(p) for p in parts])

    where, sqrt, fabs, sin, cos = np.where, np.sqrt, np.abs, np.sin, np.cos


class ScalarOps:
    """Python floats and ``math``, as one writes a right-hand side of a few states."""

    @staticmethod
    def cat(*parts):
        return np.array(parts, dtype=float)

    @staticmethod
    def where(cond, a, b):
        return a if cond else b

    sqrt, fabs, sin, cos = math.sqrt, abs, math.sin, math.cos


@dataclass
class Formulation:
    """One hand-written form of a model.

    ``f(t, x, z, u, ops)`` and ``g(t, x, z, u, ops)`` (None for an ODE); ``u(t)`` the
    input, constant between the ``breaks`` (time events inside (0, t_end), where the
    peers restart); ``outputs(x, z)`` the final values under acausal's names;
    ``groups`` the names whose common peak scales a deviation; ``linear``: f is affine
    in x, so its Jacobian is a constant matrix; ``vectorized``: numpy ops (else floats).
    """

    model: str
    label: str
    t_end: float
    x0: np.ndarray
    x_nominal: np.ndarray
    f: Callable
    u: Callable
    outputs: Callable
    groups: dict
    z0: np.ndarray = field(default_factory=lambda: np.zeros(0))
    z_nominal: np.ndarray = field(default_factory=lambda: np.zeros(0))
    g: Callable | None = None
    breaks: tuple = ()
    linear: bool = False
    vectorized: bool = False

    @property
    def is_ode(self) -> bool:
        return self.g is None

    @property
    def ops(self):
        return NumpyOps if self.vectorized else ScalarOps

    def segments(self) -> list:
        """(t0, t1, u) for each interval between the time events."""
        edges = [0.0, *self.breaks, self.t_end]
        return [(a, b, self.u(0.5 * (a + b))) for a, b in zip(edges[:-1], edges[1:])]

    def rhs(self, u) -> Callable:
        """x' = f(t, x, u) as numpy for an ODE form (scipy's signature)."""
        f, ops = self.f, self.ops
        return lambda t, x: f(t, x, None, u, ops)

    def jacobian(self, u) -> sps.csc_matrix:
        """The constant df/dx of a linear ODE form, column by column: f(e_j) - f(0), which
        for an affine f is the j-th column up to rounding."""
        n, fun = self.x0.size, self.rhs(u)
        base = fun(0.0, np.zeros(n))
        cols = []
        for j in range(n):
            e = np.zeros(n)
            e[j] = 1.0
            cols.append(sps.csc_matrix((fun(0.0, e) - base)[:, None]))
        jac = sps.hstack(cols).tocsc()
        jac.eliminate_zeros()
        return jac


# --- M1: RLC ladder -----------------------------------------------------------------------

def _ladder(n: int) -> Formulation:
    """Section k (1..N): R and L in series from node k-1 to node k, C from node k to
    ground; node 0 is the 1 V step (on from t = 0).  Resistor v = R i, inductor
    L di/dt = v, capacitor C dv/dt = i, Kirchhoff's current law at node k:

        L di_k/dt = v_{k-1} - R i_k - v_k     (v_0 = u = 1 V)
        C dv_k/dt = i_k - i_{k+1}             (i_{N+1} = 0)

    x = [i_1..i_N, v_1..v_N], all zero at t = 0 (the library's start values).
    """
    R, L, C = 1.0, 1e-3, 1e-3

    def f(t, x, z, u, ops):
        i, v = x[:n], x[n:]
        di = (ops.cat(u, v[:-1]) - R * i - v) / L
        dv = (i - ops.cat(i[1:], 0.0)) / C
        return ops.cat(di, dv)

    def outputs(x, z):
        return {**{f"L[{k}].i": x[k] for k in range(n)},
                **{f"C[{k}].v": x[n + k] for k in range(n)}}

    return Formulation("M1", "ODE, 2N states", 0.1, np.zeros(2 * n), np.ones(2 * n), f,
                       lambda t: 1.0, outputs,
                       {"inductor currents": [f"L[{k}].i" for k in range(n)],
                        "capacitor voltages": [f"C[{k}].v" for k in range(n)]},
                       linear=True, vectorized=True)


# --- M2: pendulum ---------------------------------------------------------------------------

_L, _M, _G = 1.0, 1.0, 9.81
_X0 = 0.5                     # x and vx = 0 are fixed; y < 0 follows from the constraint


def _pendulum_outputs(x, y, vx, vy):
    return {"x": x, "y": y, "vx": vx, "vy": vy}


_PENDULUM_GROUPS = {"position": ["x", "y"], "velocity": ["vx", "vy"]}


def _pendulum_angle() -> Formulation:
    """The same pendulum in its angle from the downward vertical, x = L sin(theta),
    y = -L cos(theta):  theta'' = -(g/L) sin(theta), theta(0) = asin(x0/L), omega(0) = 0.
    """
    def f(t, x, z, u, ops):
        return ops.cat(x[1], -_G / _L * ops.sin(x[0]))

    def outputs(x, z):
        th, om = x
        return _pendulum_outputs(_L * math.sin(th), -_L * math.cos(th),
                                 _L * om * math.cos(th), _L * om * math.sin(th))

    return Formulation("M2", "ODE in the angle", 10.0, np.array([math.asin(_X0 / _L), 0.0]),
                       np.ones(2), f, lambda t: 0.0, outputs, _PENDULUM_GROUPS)


def _pendulum_index1() -> Formulation:
    """Cartesian pendulum (the DAE notes, sections 3.2-3.6), the constraint
    x^2 + y^2 = L^2 differentiated twice and the accelerations substituted (index 1):

        x' = vx, y' = vy, m vx' = -lam x, m vy' = -lam y - m g
        0 = m (vx^2 + vy^2) - m g y - lam (x^2 + y^2)

    The position and velocity constraints hold only at t = 0 (they drift at the
    integration error); lam is the algebraic unknown.
    """
    def f(t, x, z, u, ops):
        return ops.cat(x[2], x[3], -z[0] * x[0] / _M, -z[0] * x[1] / _M - _G)

    def g(t, x, z, u, ops):
        px, py, vx, vy = x[0], x[1], x[2], x[3]
        return ops.cat(_M * (vx * vx + vy * vy) - _M * _G * py - z[0] * (px * px + py * py))

    y0 = -math.sqrt(_L**2 - _X0**2)
    lam0 = -_M * _G * y0 / _L**2
    return Formulation("M2", "index-1 DAE, Cartesian", 10.0, np.array([_X0, y0, 0.0, 0.0]),
                       np.ones(4), f, lambda t: 0.0,
                       lambda x, z: _pendulum_outputs(*x), _PENDULUM_GROUPS,
                       z0=np.array([lam0]), z_nominal=np.ones(1), g=g)


# --- M3: DC motor, elastic shaft, load ---------------------------------------------------

def _motor_drive() -> Formulation:
    """DC motor (Egeland & Gravdahl (3.29)-(3.31)), shaft spring-damper c, d, load J_L
    with bearing friction b to the housing (3.5); the 24 V step at t = 0.1 s:

        L di/dt = u - R i - k w_m
        J_m dw_m/dt = k i + tau_s,   tau_s = c phi_rel + d (w_L - w_m)
        J_L dw_L/dt = -tau_s - b w_L
        phi_m' = w_m,   phi_rel' = w_L - w_m        (phi_rel = phi_L - phi_m)

    tau_s is the shaft's torque on the motor flange (SpringDamper: flange_b.tau = tau,
    flange_a.tau = -tau, and the connection sums to zero).
    """
    R, L, k, J_m = 1.0, 1e-3, 0.05, 1e-4
    c, d, J_L, b = 100.0, 0.01, 0.01, 1e-2

    def f(t, x, z, u, ops):
        i, w_m, phi_rel, w_L = x[0], x[2], x[3], x[4]  # phi_m = x[1] acts on nothing
        tau_s = c * phi_rel + d * (w_L - w_m)
        return ops.cat((u - R * i - k * w_m) / L, w_m, (k * i + tau_s) / J_m, w_L - w_m,
                       (-tau_s - b * w_L) / J_L)

    names = ["motor.La.i", "motor.rotor.phi", "motor.rotor.w", "shaft.phi_rel", "load.w"]
    return Formulation("M3", "ODE, 5 states", 1.0, np.zeros(5), np.ones(5), f,
                       lambda t: 24.0 if t >= 0.1 else 0.0,
                       lambda x, z: dict(zip(names, x)),
                       {"current": names[:1], "angle": names[1:2], "speed": ["motor.rotor.w",
                        "load.w"], "shaft twist": names[3:4]},
                       breaks=(0.1,))


# --- M4: mass-spring chain ----------------------------------------------------------------

def _chain(n: int) -> Formulation:
    """Masses m on springs c (spring k from mass k-1 to mass k, spring 1 from the wall),
    1 N on the last mass; f_k = c (s_k - s_{k-1}) with s_0 = 0:

        s_k' = v_k,   m v_k' = f_{k+1} - f_k    (f_{N+1} = 1 N, the applied force)

    x = [s_1..s_N, v_1..v_N], at rest at t = 0.
    """
    m, c, force = 1.0, 1e4, 1.0

    def f(t, x, z, u, ops):
        s, v = x[:n], x[n:]
        spring = c * (s - ops.cat(0.0, s[:-1]))
        return ops.cat(v, (ops.cat(spring[1:], force) - spring) / m)

    def outputs(x, z):
        return {**{f"mass[{k}].s": x[k] for k in range(n)},
                **{f"mass[{k}].v": x[n + k] for k in range(n)}}

    return Formulation("M4", "ODE, 2N states", 1.0, np.zeros(2 * n), np.ones(2 * n), f,
                       lambda t: 0.0, outputs,
                       {"positions": [f"mass[{k}].s" for k in range(n)],
                        "velocities": [f"mass[{k}].v" for k in range(n)]},
                       linear=True, vectorized=True)


# --- M5: valve-controlled hydraulic motor -----------------------------------------------

def _orifice(A, dp, ops, C_d=0.6, rho=900.0, nu=30e-6, Re_tr=1000.0):
    """Regularized orifice flow (Egeland & Gravdahl (4.13), F_tr of (4.42)), odd in dp:
    x = A dp / F_tr; laminar (3 nu Re_tr/4)(sqrt(pi)/2) A^(3/2) (dp/F_tr)(3 - |x|) for
    |x| <= 1, else sign(dp) C_d A sqrt(2 |dp|/rho), |dp|^(1/2) as (dp^2 + 1)^(1/4) as in
    the library."""
    F_tr = 9 * Re_tr**2 * rho * nu**2 / (8 * C_d**2) * math.pi / 4
    x = A * dp / F_tr
    laminar = (3 * nu * Re_tr / 4 * math.sqrt(math.pi) / 2 * A * ops.sqrt(A) * dp / F_tr
               * (3 - ops.fabs(x)))
    turbulent = C_d * A * math.sqrt(2 / rho) * ops.sqrt(ops.sqrt(dp * dp + 1.0))
    return ops.where(x > 1, turbulent, ops.where(x < -1, -turbulent, laminar))


def _valve_motor() -> Formulation:
    """Critical-centre valve (Egeland & Gravdahl (4.18)-(4.20)), two line volumes (4.64),
    motor with internal leakage (4.67)-(4.71), load J_t, P control x_v = K_p (1 - phi)
    of a 1 rad step at t = 0 (section 4.4; data of the library example):

        A_a = A_d = b max(x_v, 0),  A_b = A_c = b max(-x_v, 0)
        q_1 = q(A_a, p_s - p_1) - q(A_c, p_1),   q_2 = q(A_d, p_2) - q(A_b, p_s - p_2)
        (V_0/beta) p_1' = q_1 - D_m w - C_im (p_1 - p_2)
        (V_0/beta) p_2' = -q_2 + D_m w + C_im (p_1 - p_2)
        phi' = w,   J_t w' = D_m (p_1 - p_2)

    p_1 = p_2 = p_s/2 and phi = w = 0 at t = 0; the pressures have nominal 1e6 Pa.
    """
    P_S, B, RHO, C_D = 1e7, 1e-3, 900.0, 0.6
    D_M, V_0, BETA, J_T = 1e-5, 1e-4, 7e8, 8.75e-3
    C_IM = 0.1 * D_M / math.sqrt(BETA * J_T / (2 * V_0))
    K_P = 40.0 * D_M / (C_D * B * math.sqrt(P_S / RHO))

    def f(t, x, z, u, ops):
        p1, p2, phi, w = x[0], x[1], x[2], x[3]
        x_v = K_P * (u - phi)
        open_1 = B * ops.where(x_v > 0, x_v, 0.0)
        open_2 = B * ops.where(-x_v > 0, -x_v, 0.0)
        q_1 = _orifice(open_1, P_S - p1, ops) - _orifice(open_2, p1, ops)
        q_2 = _orifice(open_1, p2, ops) - _orifice(open_2, P_S - p2, ops)
        leak = C_IM * (p1 - p2)
        return ops.cat(BETA / V_0 * (q_1 - D_M * w - leak),
                       BETA / V_0 * (-q_2 + D_M * w + leak), w, D_M * (p1 - p2) / J_T)

    names = ["line_1.p", "line_2.p", "load.phi", "load.w"]
    return Formulation("M5", "ODE, 4 states", 0.5, np.array([P_S / 2, P_S / 2, 0.0, 0.0]),
                       np.array([1e6, 1e6, 1.0, 1.0]), f, lambda t: 1.0,
                       lambda x, z: dict(zip(names, x)),
                       {"line 1 pressure": names[:1], "line 2 pressure": names[1:2],
                        "angle": names[2:3], "speed": names[3:4]})


def formulations(name: str, n: int) -> list:
    """The hand-written forms of model ``name`` (M1..M5), the ODE form first."""
    if name == "M1":
        return [_ladder(n)]
    if name == "M2":
        return [_pendulum_angle(), _pendulum_index1()]
    if name == "M3":
        return [_motor_drive()]
    if name == "M4":
        return [_chain(n)]
    if name == "M5":
        return [_valve_motor()]
    raise ValueError(f"unknown model {name!r}")
