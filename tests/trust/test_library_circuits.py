"""Library networks whose topology, not their elements, sets the index.

* A triangle of three capacitors that touches ground nowhere, fed from a sine source
  through a resistor: the capacitor loop makes C_ab v_ab + ... one state short (2, not
  3).  Reference: the nodal equations Cn U' = -G U + b(t) assembled by hand and reduced
  by linear algebra (``_descriptor``), under solve_ivp (DOP853, rtol 1e-12).
* A sine current source feeding an inductor through two parallel resistors: the
  inductor's current is imposed (an inductor/current-source cutset), so there is no
  state at all.  Closed form: i_L = I(t), v_L = L I'(t), the resistor currents split by
  conductance.
* Two translational dampers in parallel on a massless node, the node pulled by a spring
  on a mass released from a stretched position: (d1 + d2) s_N' = c (x - s_N),
  m x'' = -c (x - s_N).  Closed form: the matrix exponential of that 3-state system.
* A hydraulic ``ModalLine`` (impedance form, Egeland & Gravdahl 4.5.11-4.5.16) between
  two ``Volume``s, fed by a constant flow and drained through a laminar orifice.  Two
  references: the volume balance, which holds exactly along the run,
      (V1 p1' + V2 p2')/beta + (A L/beta) p_mean' = q0 - C_l p2,
  (p_mean the line's mean pressure, whose balance is T p_mean' = 2 Z_0 q_s), and the
  steady state p2 = q0/C_l, p1 - p2 = 8 mu L q0/(pi r0^4) (laminar friction, (4.159)).

Values are ordinary bench values (kOhm, uF, a 1 kg mass on 10 kN/m, a 2 m thin oil line).
"""
import numpy as np
import pytest
import scipy.linalg as sla
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import electrical as el
from acausal.library import hydraulics as hy
from acausal.library import translational as tr

from ._descriptor import Descriptor


# -- a capacitor triangle ---------------------------------------------------------------------
RS, RB, RC = 1e3, 2.2e3, 3.3e3
CAB, CBC, CCA = 1e-6, 2.2e-6, 4.7e-7
V_SRC, F_SRC, T_TRI = 5.0, 100.0, 0.02


class CapacitorTriangle(ac.Component):
    """Source - Rs - node A; C_ab, C_bc, C_ca around A, B, C; Rb, Rc from B, C to ground.
    Two capacitors start uncharged; the third then is too (it closes the loop)."""

    src = el.SineVoltage(V=V_SRC, f=F_SRC)
    Rs = el.Resistor(R=RS)
    Cab = el.Capacitor(C=CAB, v={"start": 0.0, "fixed": True})
    Cbc = el.Capacitor(C=CBC, v={"start": 0.0, "fixed": True})
    Cca = el.Capacitor(C=CCA)
    Rb = el.Resistor(R=RB)
    Rc = el.Resistor(R=RC)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.Rs.p),
                ac.connect(self.Rs.n, self.Cab.p, self.Cca.n),
                ac.connect(self.Cab.n, self.Cbc.p, self.Rb.p),
                ac.connect(self.Cbc.n, self.Cca.p, self.Rc.p),
                ac.connect(self.src.n, self.Rb.n, self.Rc.n, self.gnd.p)]


def _triangle_reference(t):
    """Node potentials (A, B, C) from the hand-assembled nodal equations."""
    def branch(i, j, n=3):
        a = np.zeros(n)
        a[i] = 1.0
        a[j] = -1.0
        return np.outer(a, a)
    Cn = CAB * branch(0, 1) + CBC * branch(1, 2) + CCA * branch(2, 0)
    G = np.diag([1 / RS, 1 / RB, 1 / RC])
    sys = Descriptor(Cn, -G)

    def b(tt):
        return np.array([V_SRC * np.sin(2 * np.pi * F_SRC * tt) / RS, 0.0, 0.0])

    sol = solve_ivp(lambda tt, z: sys.rhs(z, b(tt)), (0.0, T_TRI),
                    np.zeros(sys.n_differential), method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=t)
    return sys, np.array([sys.full(z, b(tt)) for tt, z in zip(t, sol.y.T)])


def test_capacitor_triangle_has_two_states():
    sys, _ = _triangle_reference(np.array([0.0]))
    assert sys.n_differential == 2
    assert len(ac.compile(CapacitorTriangle()).report.states) == 2


def test_capacitor_triangle_matches_nodal_analysis():
    t = np.linspace(0.0, T_TRI, 201)
    res = ac.simulate(CapacitorTriangle(), t_end=T_TRI, rtol=1e-9, t_eval=t)
    assert res.success, res.message
    _, U = _triangle_reference(t)
    scale = np.max(np.abs(U))
    for name, (i, j) in (("Cab.v", (0, 1)), ("Cbc.v", (1, 2)), ("Cca.v", (2, 0))):
        assert np.max(np.abs(res[name] - (U[:, i] - U[:, j]))) < 1e-6 * scale, name
    assert np.max(np.abs(res["Rb.v"] - U[:, 1])) < 1e-6 * scale
    # the loop: the three capacitor voltages sum to zero at every point
    loop = res["Cab.v"] + res["Cbc.v"] + res["Cca.v"]
    assert np.max(np.abs(loop)) < 1e-9 * scale


# -- an imposed inductor current --------------------------------------------------------------
I0, F_I, R1, R2, L1 = 0.5, 50.0, 10.0, 15.0, 0.1


class CurrentThroughParallelResistors(ac.Component):
    """SineCurrent into node A, R1 || R2 from A to B, an inductor from B to ground."""

    src = el.SineCurrent(I=I0, f=F_I)
    R1 = el.Resistor(R=R1)
    R2 = el.Resistor(R=R2)
    L1 = el.Inductor(L=L1)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.n, self.R1.p, self.R2.p),
                ac.connect(self.R1.n, self.R2.n, self.L1.p),
                ac.connect(self.L1.n, self.src.p, self.gnd.p)]


def test_imposed_inductor_current_has_no_state():
    assert len(ac.compile(CurrentThroughParallelResistors()).report.states) == 0


def test_imposed_inductor_current_matches_the_closed_form():
    t = np.linspace(0.0, 0.04, 161)
    res = ac.simulate(CurrentThroughParallelResistors(), t_end=0.04, rtol=1e-9, t_eval=t)
    assert res.success, res.message
    w = 2 * np.pi * F_I
    i = I0 * np.sin(w * t)
    v_L = L1 * I0 * w * np.cos(w * t)
    exact = {"L1.i": i, "L1.v": v_L, "R1.i": i * R2 / (R1 + R2), "R2.i": i * R1 / (R1 + R2),
             "R1.p.v": i * R1 * R2 / (R1 + R2) + v_L}
    for name, x in exact.items():
        assert np.max(np.abs(res[name] - x)) < 1e-7 * np.max(np.abs(x)), name


# -- parallel dampers on a massless node ------------------------------------------------------
D1, D2, C_SPRING, MASS, X0 = 30.0, 70.0, 1e4, 1.0, 0.01


class DampedNode(ac.Component):
    """Two dampers from the housing to a massless node; a spring from the node to a mass."""

    housing = tr.Fixed()
    damper_1 = tr.Damper(d=D1, s_rel={"start": 0.0, "fixed": True})
    damper_2 = tr.Damper(d=D2)
    spring = tr.Spring(c=C_SPRING)
    mass = tr.Mass(m=MASS, s={"start": X0, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.housing.flange, self.damper_1.flange_a, self.damper_2.flange_a),
                ac.connect(self.damper_1.flange_b, self.damper_2.flange_b,
                           self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass.flange_a)]


def test_parallel_dampers_on_a_massless_node_match_the_closed_form():
    t = np.linspace(0.0, 0.1, 101)
    res = ac.simulate(DampedNode(), t_end=0.1, rtol=1e-9, t_eval=t)
    assert res.success, res.message
    k = C_SPRING / (D1 + D2)
    M = np.array([[-k, k, 0.0], [0.0, 0.0, 1.0], [C_SPRING / MASS, -C_SPRING / MASS, 0.0]])
    y = np.array([sla.expm(M * tk) @ [0.0, X0, 0.0] for tk in t])
    assert np.max(np.abs(res["mass.s"] - y[:, 1])) < 1e-6 * X0
    assert np.max(np.abs(res["damper_1.s_rel"] - y[:, 0])) < 1e-6 * X0
    # the dampers share the node's speed, so the force splits as d1 : d2
    f_total = C_SPRING * (y[:, 1] - y[:, 0])
    scale = np.max(np.abs(f_total))
    assert np.max(np.abs(res["damper_1.f"] - D1 / (D1 + D2) * f_total)) < 1e-6 * scale
    assert np.max(np.abs(res["damper_2.f"] - D2 / (D1 + D2) * f_total)) < 1e-6 * scale


# -- a modal line between two volumes ---------------------------------------------------------
Q0, V_VOL, C_L, LINE_L, LINE_A, NU, RHO, BETA = 1e-5, 1e-5, 1e-11, 2.0, 3e-6, 30e-6, 870.0, 1.7052e9
T_LINE = 0.1


class LineBetweenVolumes(ac.Component):
    """Constant flow into volume 1, a 4-mode line to volume 2, a laminar drain to tank;
    everything at rest and at 0 Pa at t = 0."""

    pump = hy.ConstantFlow(q0=Q0)
    volume_1 = hy.Volume(V=V_VOL, beta=BETA, p={"start": 0.0, "fixed": True})
    line = hy.ModalLine(N=4, L=LINE_L, A=LINE_A, nu=NU, rho=RHO, beta=BETA)
    volume_2 = hy.Volume(V=V_VOL, beta=BETA, p={"start": 0.0, "fixed": True})
    drain = hy.LaminarOrifice(C_l=C_L)
    tank = hy.FixedPressure(p=0.0)

    def equations(self):
        return [ac.connect(self.pump.port, self.volume_1.port, self.line.port_a),
                ac.connect(self.line.port_b, self.volume_2.port, self.drain.port_a),
                ac.connect(self.drain.port_b, self.tank.port)]


def _modal_line_reference(t, n_modes=4):
    """p1, p2 and the line's mean pressure, reduced by hand.

    The line (Table 4.1, Riemann window sigma_k = sin(b_k)/b_k, b_k = k pi/(N + 1)
    (4.270), b_N of (4.272)) is x' = F x + G q over x = (p_mean, w_1, w_1', ...), driven
    by q = (q1, q2), with port pressures p = H x.  The volumes, C_v = V/beta,

        C_v p1' = q0 - q1,   C_v p2' = q2 - C_l p2,

    tie p1, p2 to the line's states (index 2): with p' = H x' = H (F x + G q) they give
    q = K^-1 ([q0, 0] - (C_v H F + e_2 C_l H_2) x), K = C_v H G + diag(1, -1), and so a
    linear ODE in x alone with a constant forcing, solved by the matrix exponential.
    """
    c = np.sqrt(BETA / RHO)
    T, Z0, B = LINE_L / c, RHO * c / LINE_A, 8 * NU * np.pi / LINE_A
    k = np.arange(1, n_modes + 1)
    sigma = np.sin(k * np.pi / (n_modes + 1)) / (k * np.pi / (n_modes + 1))
    odd = k % 2 == 1
    b_N = 1.0 / (8 * np.sum(sigma[odd] / (k[odd] * np.pi) ** 2))
    n = 1 + 2 * n_modes
    F, G, H = np.zeros((n, n)), np.zeros((n, 2)), np.zeros((2, n))
    G[0] = [Z0 / T, -Z0 / T]                        # T p_mean' = 2 Z0 q_s
    H[:, 0] = 1.0                                   # p1 = p_s + p_a, p2 = p_s - p_a
    for j, (kk, sg) in enumerate(zip(k, sigma)):
        w, wd = 1 + 2 * j, 2 + 2 * j
        F[w, wd] = 1.0
        F[wd, wd], F[wd, w] = -B, -(kk * np.pi / T) ** 2
        drive = 2 * sg * Z0 / T                     # 4 sigma Z0 T q / T^2, q = q_s or q_a
        if kk % 2 == 0:                             # symmetric: q_s, into p_s
            G[wd] = [drive, -drive]
            H[:, wd] += 1.0
            H[:, w] += B
        else:                                       # antisymmetric: q_a, into p_a
            G[wd] = [drive, drive]
            H[:, wd] += [1.0, -1.0]
            H[:, w] += np.array([1.0, -1.0]) * b_N * B
    C_v = V_VOL / BETA
    K = C_v * H @ G + np.diag([1.0, -1.0])
    Kq = np.linalg.solve(K, C_v * H @ F + np.outer([0.0, 1.0], C_L * H[1]))
    Ar = F - G @ Kq
    br = G @ np.linalg.solve(K, [Q0, 0.0])
    x_ss = -np.linalg.solve(Ar, br)
    x = np.array([x_ss - sla.expm(Ar * tk) @ x_ss for tk in t])   # x(0) = 0: at rest
    p = x @ H.T
    return p[:, 0], p[:, 1], x[:, 0]


@pytest.fixture(scope="module")
def line_run():
    t = np.linspace(0.0, T_LINE, 10001)      # dense: the line rings at up to 8.8e3 rad/s
    return ac.simulate(LineBetweenVolumes(), t_end=T_LINE, rtol=1e-8, t_eval=t)


def test_modal_line_matches_its_hand_written_equations(line_run):
    res = line_run
    assert res.success, res.message
    p1, p2, p_mean = _modal_line_reference(res.t[::20])
    scale = np.max(np.abs(p1))
    assert np.max(np.abs(res["volume_1.p"][::20] - p1)) < 1e-6 * scale
    assert np.max(np.abs(res["volume_2.p"][::20] - p2)) < 1e-6 * scale
    assert np.max(np.abs(res["line.mean.p"][::20] - p_mean)) < 1e-6 * scale


def test_modal_line_volume_balance_holds_along_the_run(line_run):
    res = line_run
    assert res.success, res.message
    t = res.t
    stored = (V_VOL * (res["volume_1.p"] + res["volume_2.p"])
              + LINE_A * LINE_L * res["line.mean.p"]) / BETA
    rate = (stored[2:] - stored[:-2]) / (t[2:] - t[:-2])
    net_inflow = Q0 - C_L * res["volume_2.p"][1:-1]
    assert np.max(np.abs(rate - net_inflow)) < 1e-3 * Q0


def test_modal_line_reaches_the_laminar_steady_state(line_run):
    res = line_run
    assert res.success, res.message
    r0 = np.sqrt(LINE_A / np.pi)
    drop = 8 * RHO * NU * LINE_L * Q0 / (np.pi * r0**4)         # 8 mu L q / (pi r0^4)
    assert res["volume_2.p"][-1] == pytest.approx(Q0 / C_L, rel=1e-6)
    assert res["volume_1.p"][-1] - res["volume_2.p"][-1] == pytest.approx(drop, rel=1e-4)
