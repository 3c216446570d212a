"""Hydraulic transmission lines (Egeland & Gravdahl 4.5-4.6): a chain of Helmholtz
resonators (``LumpedLine``) and the modal (rational) approximation (``ModalLine``).

Line data: length L, cross-section A, density rho, bulk modulus beta = rho c^2, and
linear (laminar) friction F/rho = B q with B = 8 nu / r0^2, r0 = sqrt(A/pi)  (4.159)-(4.160).
"""
from __future__ import annotations

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import FluidPort

__all__ = ["LumpedLine", "ModalLine"]

# (port_a on a pipe, port_b on a pipe) for each form
_FORMS = {"impedance": (0, 0), "admittance": (1, 1), "hybrid": (1, 0)}


class _Node(ac.Component):
    """The pressure of one volume of the chain."""

    p = ac.Variable(start=0.0, unit="Pa", nominal=1e6, state_select="prefer",
                    description="pressure in the volume")


class _Pipe(ac.Component):
    """The flow through one pipe of the chain."""

    q = ac.Variable(start=0.0, unit="m3/s", nominal=1e-4, state_select="prefer",
                    description="flow in the pipe, towards port_b")


class _LineData(ac.Component):
    port_a = FluidPort()
    port_b = FluidPort()
    L = ac.Parameter(10.0, unit="m", min=0, description="line length")
    A = ac.Parameter(1e-4, unit="m2", min=0, description="cross-section")
    rho = ac.Parameter(870.0, unit="kg/m3", min=0, description="density")
    beta = ac.Parameter(1.7052e9, unit="Pa", min=0, description="bulk modulus rho c^2")
    nu = ac.Parameter(0.0, unit="m2/s", min=0, description="kinematic viscosity (0: lossless)")

    def _B(self):
        return 8 * self.nu * sp.pi / self.A


class LumpedLine(_LineData):
    """Transmission line as a chain of n Helmholtz resonators (Egeland & Gravdahl
    4.6.3-4.6.6).  Volume i (V_h = A h) and pipe i (length h):

        (A h / beta) der(p_i) = q_{i-1} - q_i                               (4.279)
        (h rho / A) der(q_{i-1}) = p_{i-1} - p_i - (h rho / A) B q_{i-1}      (4.280), (4.282)

    ``form`` sets what the ends are:

    * ``"impedance"`` (4.6.5): both ports on volumes (the line is fed flows, e.g. by
      valves); n volumes, n - 1 pipes, L = n h.
    * ``"admittance"`` (4.6.4): both ports on pipes (fed pressures, e.g. by volumes or
      tanks); n volumes, n + 1 pipes, L = (n + 1) h.
    * ``"hybrid"`` (4.6.6): port_a on a pipe, port_b on a volume; n volumes, n pipes,
      L = (n + 1/2) h.

    Closed at both ends the impedance form has the natural frequencies
    w_k = 2 (c/h) sin(k pi / (2 n)), k = 1..n-1: 2 sqrt(2) c/L for n = 2 (4.300),
    3 c/L and 3 sqrt(3) c/L for n = 3 (4.305), tending to k pi c/L (4.301).
    """

    p_start = ac.Parameter(0.0, unit="Pa", description="initial pressure along the line")
    q_start = ac.Parameter(0.0, unit="m3/s", description="initial flow along the line")

    def stored_energy(self):
        """sum (A h / beta) p_i^2 / 2 over the volumes + (h rho / A) q_j^2 / 2 over the
        pipes (compression and kinetic energy, Egeland & Gravdahl (4.66), (4.91))."""
        h = self._h()
        return (sum(self.A * h / self.beta * v.p**2 / 2 for v in self.volumes)
                + sum(h * self.rho / self.A * pipe.q**2 / 2 for pipe in self.pipes))

    def loss_power(self):
        """Laminar friction, sum (h rho / A) B q_j^2 over the pipes."""
        h = self._h()
        return sum(h * self.rho / self.A * self._B() * pipe.q**2 for pipe in self.pipes)

    def __init__(self, n=10, form="impedance", **mods):
        super().__init__(**mods)
        if form not in _FORMS:
            raise ac.ModelError(f"LumpedLine: form must be one of {sorted(_FORMS)}, not {form!r}")
        if n < 1 or (form == "impedance" and n < 2):
            raise ac.ModelError("LumpedLine: needs n >= 1 volumes (n >= 2 in impedance form)")
        self.n, self.form = n, form
        self.volumes = [_Node() for _ in range(n)]
        self.pipes = [_Pipe() for _ in range(n - 1 + sum(_FORMS[form]))]

    def initial_equations(self):
        # a uniform initial state: at rest, or a steady flow of a lossless line
        return [*(ac.Eq(v.p, self.p_start) for v in self.volumes),
                *(ac.Eq(pipe.q, self.q_start) for pipe in self.pipes)]

    def _h(self):
        pipes_over_volumes = {"impedance": 0, "admittance": 1, "hybrid": sp.Rational(1, 2)}
        return self.L / (self.n + pipes_over_volumes[self.form])

    def equations(self):
        h, A, rho = self._h(), self.A, self.rho
        p = [v.p for v in self.volumes]
        q = [pipe.q for pipe in self.pipes]
        head, tail = _FORMS[self.form]
        # a port on a volume feeds it a flow, a port on a pipe gives it a pressure
        q_in = (([self.port_a.q] if head == 0 else []) + q)[: self.n]
        q_out = q[head:] + ([-self.port_b.q] if tail == 0 else [])
        left = ([self.port_a.p] if head == 1 else []) + p
        right = p[1 - head:] + ([self.port_b.p] if tail == 1 else [])
        eqs = [ac.Eq(A * h / self.beta * ac.der(p[i]), q_in[i] - q_out[i])
               for i in range(self.n)]
        eqs += [ac.Eq(h * rho / A * ac.der(q[j]),
                      left[j] - right[j] - h * rho / A * self._B() * q[j])
                for j in range(len(q))]
        if head == 0:
            eqs.append(ac.Eq(self.port_a.p, p[0]))
        else:
            eqs.append(ac.Eq(self.port_a.q, q[0]))
        if tail == 1:
            eqs.append(ac.Eq(self.port_b.q, -q[-1]))
        else:
            eqs.append(ac.Eq(self.port_b.p, p[-1]))
        return eqs


_WINDOWS = {"riemann": lambda b: np.sin(b) / b, "hann": lambda b: (1 - np.cos(b)) / 2,
            "hamming": lambda b: 0.54 + 0.46 * np.cos(b), "none": lambda b: 1.0 + 0 * b}


class _Mode(ac.Component):
    """One second-order section T^2 w'' + B T^2 w' + (k pi)^2 w = 4 sigma_k Z_0 T q."""

    w = ac.Variable(start=0.0, unit="Pa.s", nominal=1e4, description="section state")
    w_dot = ac.Variable(start=0.0, unit="Pa", nominal=1e6, description="der(w)")


class ModalLine(_LineData):
    """Transmission line from the truncated modal (rational) expansion of its impedance,
    with linear friction (Piche & Ellman 1996; Egeland & Gravdahl 4.5.11-4.5.16, Table 4.1,
    second row).  Flows are the inputs (impedance form, ports on valves or flow sources):
    with q_1 = port_a.q into the line and q_2 = -port_b.q out of it,

        q_s = (q_1 - q_2)/2,  p_s = (p_1 + p_2)/2,  q_a = (q_1 + q_2)/2,  p_a = (p_1 - p_2)/2
        Z_s/Z_0 = 2/(Ts) + sum_{k=2,4..N} 4 sigma_k T (s + B) / ((Ts)^2 + B T^2 s + (k pi)^2)
        Z_a/Z_0 = sum_{k=1,3..N-1} 4 sigma_k T (s + b_N B) / ((Ts)^2 + B T^2 s + (k pi)^2)

    T = L/c, Z_0 = rho c / A, B = 8 nu / r_0^2 (4.160), sigma_k a window (4.270) with
    beta_k = k pi/(N + 1), and b_N = (8 sum_{k odd} sigma_k/(k pi)^2)^-1 (4.272) makes the
    steady pressure drop the laminar one, p_1 - p_2 = Z_0 T B q = 8 mu L q/(pi r_0^4).
    Each section is T^2 w'' + B T^2 w' + (k pi)^2 w = 4 sigma_k Z_0 T q_{s,a}, with
    p_k = w' + B w (b_N B for the antisymmetric ones).  The poles are those of the
    distributed line with linear friction, s = -B/2 +- j sqrt((k pi/T)^2 - B^2/4).
    """

    def _section_terms(self):
        """Per section, with c_k = 4 sigma_k Z_0 T, K = (k pi)^2, damping b (B for the
        symmetric sections, b_N B for the antisymmetric ones), the port power
        2 q p_k = (2/c_k) (T^2 w'' + B T^2 w' + K w)(w' + b w) splits into
        d/dt of S_k = (T^2 (w' + b w)^2 + (K + b (B - b) T^2) w^2) / c_k and
        the loss (2/c_k) ((B - b) T^2 w'^2 + b K w^2); the mean pressure stores
        T p_m^2 / (2 Z_0).  With b_N > 1 the antisymmetric sections are not passive
        at high frequency (w'^2 (B - b) < 0), a property of the truncated expansion."""
        c = sp.sqrt(self.beta / self.rho)
        T, Z0, B = self.L / c, self.rho * c / self.A, self._B()
        store, loss = T * self.mean.p**2 / (2 * Z0), 0
        for k, (mode, sigma) in enumerate(zip(self.modes, self.sigma), start=1):
            b = B if k % 2 == 0 else self.b_N * B
            K, ck = (k * sp.pi)**2, 4 * float(sigma) * Z0 * T
            w, wd = mode.w, mode.w_dot
            store += (T**2 * (wd + b * w)**2 + (K + b * (B - b) * T**2) * w**2) / ck
            loss += 2 * ((B - b) * T**2 * wd**2 + b * K * w**2) / ck
        return store, loss

    def stored_energy(self):
        """Mean pressure and modal sections (see ``_section_terms``)."""
        return self._section_terms()[0]

    def loss_power(self):
        """Friction in the modal sections (see ``_section_terms``)."""
        return self._section_terms()[1]

    def __init__(self, N=8, window="riemann", **mods):
        super().__init__(**mods)
        if N < 2 or N % 2:
            raise ac.ModelError(f"ModalLine: N must be even and >= 2, not {N}")
        if window not in _WINDOWS:
            raise ac.ModelError(f"ModalLine: window must be one of {sorted(_WINDOWS)}")
        self.N = N
        k = np.arange(1, N + 1)
        self.sigma = _WINDOWS[window](k * np.pi / (N + 1))
        odd = k % 2 == 1
        self.b_N = 1.0 / (8 * np.sum(self.sigma[odd] / (k[odd] * np.pi)**2))
        self.modes = [_Mode() for _ in range(N)]
        self.mean = _Node()        # the integrator 2 Z_0/(T s) of Z_s: the mean pressure

    def equations(self):
        c = sp.sqrt(self.beta / self.rho)
        T, Z0, B = self.L / c, self.rho * c / self.A, self._B()
        q_1, q_2 = self.port_a.q, -self.port_b.q
        q_s, q_a = (q_1 - q_2) / 2, (q_1 + q_2) / 2
        eqs = [ac.Eq(T * ac.der(self.mean.p), 2 * Z0 * q_s)]
        p_s, p_a = self.mean.p, 0
        for k, (mode, sigma) in enumerate(zip(self.modes, self.sigma), start=1):
            q, damping = (q_s, B) if k % 2 == 0 else (q_a, self.b_N * B)
            eqs += [ac.Eq(ac.der(mode.w), mode.w_dot),
                    ac.Eq(T**2 * ac.der(mode.w_dot) + B * T**2 * mode.w_dot
                          + (k * sp.pi)**2 * mode.w, 4 * float(sigma) * Z0 * T * q)]
            if k % 2 == 0:
                p_s = p_s + mode.w_dot + damping * mode.w
            else:
                p_a = p_a + mode.w_dot + damping * mode.w
        return eqs + [ac.Eq(self.port_a.p, p_s + p_a), ac.Eq(self.port_b.p, p_s - p_a)]
