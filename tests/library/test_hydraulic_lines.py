"""Hydraulic transmission lines (Egeland & Gravdahl 4.5-4.6, 11.2.10): lumped and modal
line frequencies against the exact ones, wave reflection, the Joukowsky pressure rise."""
import numpy as np

import acausal as ac
from acausal.library import hydraulics as hy
from acausal.library.hydraulics.examples import water_hammer as wh
from acausal.library.hydraulics.examples.line_resonance import LineClosedAtOneEnd

from .test_hydraulics import RHO, _eigenvalues


# -- transmission lines (4.6) --------------------------------------------------------------

C_OIL, L_LINE = 1400.0, 20.0


class ClosedLine(ac.Component):
    def __init__(self, n=2, **mods):
        super().__init__(**mods)
        self.line = hy.LumpedLine(n=n, form="impedance", L=L_LINE, rho=870.0,
                                  beta=870.0 * C_OIL**2)


def _frequencies(model):
    compiled = ac.compile(model)
    w = _eigenvalues(compiled, ac.initial_values(compiled))
    assert np.max(np.abs(w.real)) < 1e-9 * np.max(np.abs(w))      # lossless
    return np.sort(w.imag[w.imag > 1e-9 * np.max(np.abs(w))]) * L_LINE / C_OIL


def test_lumped_line_closed_at_both_ends_examples_67_68():
    assert np.allclose(_frequencies(ClosedLine(n=2)), [2 * np.sqrt(2)], rtol=1e-9)   # (4.300)
    assert np.allclose(_frequencies(ClosedLine(n=3)), [3.0, 3 * np.sqrt(3)], rtol=1e-9)


def test_lumped_line_frequencies_approach_the_exact_k_pi_c_over_L():
    """Closed-closed impedance chain: w_k = 2n (c/L) sin(k pi/(2n)) -> k pi c/L (4.301)."""
    errors = []
    for n in (4, 8, 16, 32):
        f = _frequencies(ClosedLine(n=n))
        k = np.arange(1, n)
        assert np.allclose(f, 2 * n * np.sin(k * np.pi / (2 * n)), rtol=1e-8)
        errors.append(np.pi - f[0])
    assert all(e2 < e1 / 3.9 for e1, e2 in zip(errors, errors[1:]))   # O(1/n^2)
    assert errors[-1] < 1.3e-3


def test_lumped_line_closed_at_one_end_example_69():
    """Hybrid form: 1.5 c/L for n = 1 (4.308); (2n + 1) sin(pi/(2 (2n + 1))) c/L
    tending to (pi/2) c/L (4.309)."""
    assert np.allclose(_frequencies(LineClosedAtOneEnd(n=1)), [1.5], rtol=1e-9)
    f = _frequencies(LineClosedAtOneEnd(n=16))
    assert abs(f[0] - 33 * np.sin(np.pi / 66)) < 1e-9 and abs(f[0] - np.pi / 2) < 6e-4


def test_line_closed_at_one_end_reflects_the_wave_4_197():
    """The pressure rise arrives at the closed end after T = L/c and doubles there
    (G_L = 1): 2 p for T < t < 3T, then 0 until 5T (time means over each plateau,
    counted from the middle of the 2 ms ramp)."""
    res = ac.simulate(LineClosedAtOneEnd(), t_end=LineClosedAtOneEnd.stop_time, rtol=1e-5)
    assert res.success
    t, p = res.t - 2e-3, res["line.port_b.p"]
    T = L_LINE / C_OIL
    for start, stop, level in [(0.15, 0.85, 0.0), (1.15, 2.85, 2e6), (3.15, 4.85, 0.0)]:
        sel = (t > start * T) & (t < stop * T)
        mean = np.trapezoid(p[sel], t[sel]) / (t[sel][-1] - t[sel][0])
        assert abs(mean - level) < 0.01 * 2e6


# -- water hammer (11.2.10) ----------------------------------------------------------------

def test_water_hammer_joukowsky_pressure_rise_11_125():
    res = ac.simulate(wh.WaterHammer(), t_end=wh.WaterHammer.stop_time, rtol=1e-5)
    assert res.success
    t, p = res.t, res["line.port_b.p"]
    p_before = wh.P_0 + wh.DP_VALVE
    assert abs(res["line.pipes[0].q"][0] - wh.Q_0) < 1e-12 * wh.Q_0     # steady flow first
    rise = wh.RHO * wh.C * wh.V_0                        # 20 bar for 2 m/s of oil
    plateau = (t > 0.02) & (t < 2 * wh.L / wh.C)          # closed, before the reflection
    mean = np.trapezoid(p[plateau] - p_before, t[plateau]) / (t[plateau][-1] - t[plateau][0])
    assert abs(mean - rise) < 2e-3 * rise
    assert abs(p[plateau].max() - p_before - rise) < 0.06 * rise


class ClosedModalLine(ac.Component):
    line = hy.ModalLine(N=6, L=L_LINE, rho=870.0, beta=870.0 * C_OIL**2,
                        A=np.pi * 6e-3**2, nu=8e-5)


def test_modal_line_has_the_poles_of_the_line_with_linear_friction_4_265():
    """Closed at both ends, every section is a mode of the distributed line:
    T^2 s^2 + B T^2 s + (k pi)^2 = 0, k = 1..N, and the mean pressure is an integrator.
    Data of 4.5.16: L = 20 m, rho = 870, c = 1400 m/s, nu = 8e-5 m2/s, r_0 = 6 mm."""
    compiled = ac.compile(ClosedModalLine())
    w = np.sort_complex(_eigenvalues(compiled, ac.initial_values(compiled)))
    B = 8 * 8e-5 / 6e-3**2
    k = np.arange(1, 7)
    upper = -B / 2 + 1j * np.sqrt((k * np.pi * C_OIL / L_LINE)**2 - B**2 / 4)
    assert abs(L_LINE / C_OIL - 0.014) < 1e-3            # "T = L/c = 14 ms"
    assert np.allclose(np.sort(w[w.imag > 0].imag), upper.imag, rtol=1e-12)
    assert np.allclose(w[w.imag > 0].real, -B / 2, rtol=1e-9)
    assert np.min(np.abs(w)) < 1e-9 * B


class FlowThroughModalLine(ac.Component):
    source = hy.ConstantFlow(q0=1e-4)
    line = hy.ModalLine(N=6, L=L_LINE, rho=870.0, beta=870.0 * C_OIL**2,
                        A=np.pi * 6e-3**2, nu=8e-5)
    tank = hy.FixedPressure(p=1e6)

    def equations(self):
        return [ac.connect(self.source.port, self.line.port_a),
                ac.connect(self.line.port_b, self.tank.port)]


def test_modal_line_steady_pressure_drop_is_hagen_poiseuille_4_271_4_272():
    """The b_N correction gives p_1 - p_2 = Z_0 T B q = 8 mu L q / (pi r_0^4)."""
    res = ac.simulate(FlowThroughModalLine(), t_end=3.0, rtol=1e-8)
    drop = 8 * 870.0 * 8e-5 * L_LINE / (np.pi * 6e-3**4) * 1e-4
    assert abs(res["line.port_a.p"][-1] - 1e6 - drop) < 1e-6 * drop
