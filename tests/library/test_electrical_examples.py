"""The MSL Analog examples whose MAP-LIB reference result is missing from the archive
here (CompareTransformers, ChuaCircuit), against scipy's solve_ivp at rtol 1e-11 or tighter on the
circuits' hand-written equations (DOP853; neither circuit is stiff)."""
import math

import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.electrical.examples import chua_circuit as chua
from acausal.library.electrical.examples import compare_transformers as ct


def test_compare_transformers_basic_and_ideal_against_solve_ivp():
    """Basic transformer: v1 = L1 i1' + M i2', v2 = M i1' + L2 i2' with v1 = u - R1 i1,
    v2 = -(R2 + RL) i2.  Ideal one (no magnetization): i2 = -n i1, so one state,
    (L1s + n^2 L2s) i1' = u - (R1 + n^2 (R2 + RL)) i1."""
    def u(t):
        return ct.Vdc + ct.Vpeak * math.sin(2 * math.pi * ct.f * t + ct.phi0)

    Ainv = np.linalg.inv(np.array([[ct.L1, ct.M], [ct.M, ct.L2]]))

    def basic(t, y):
        return Ainv @ [u(t) - ct.R1 * y[0], -(ct.R2 + ct.RL) * y[1]]

    def ideal(t, y):
        Ls = ct.L1sigma + ct.n**2 * ct.L2sigma
        return [(u(t) - (ct.R1 + ct.n**2 * (ct.R2 + ct.RL)) * y[0]) / Ls]

    t = np.linspace(0.0, 2.0, 401)
    ref_b = solve_ivp(basic, (0, 2.0), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-14,
                      t_eval=t)
    ref_i = solve_ivp(ideal, (0, 2.0), [0.0], method="DOP853", rtol=1e-11, atol=1e-14,
                      t_eval=t)
    res = ac.simulate(ct.CompareTransformers(), t_end=2.0, rtol=1e-9, t_eval=t)
    for name, ref in (("basicTransformer.i1", ref_b.y[0]), ("basicTransformer.i2", ref_b.y[1]),
                      ("idealTransformer.i1", ref_i.y[0]),
                      ("inductor22.i", ct.n * ref_i.y[0])):
        assert np.max(np.abs(res[name] - ref)) < 1e-6 * np.ptp(ref), name
    # the ideal transformer's voltages keep the turns ratio
    assert np.allclose(res["idealTransformer.v1"], ct.n * res["idealTransformer.v2"], atol=1e-12)


def test_chua_circuit_against_solve_ivp():
    """C1 v1' = G (v2 - v1) - g(v1), C2 v2' = G (v1 - v2) - iL, L iL' = v2 - Ro iL, with
    Chua's piecewise-linear g; compared over 300 time units (the orbit is chaotic, so
    two solvers part exponentially on longer runs)."""
    Ga, Gb, Ve, G = -0.757576, -0.409091, 1.0, 0.565

    def g(v):
        return Gb * (v + Ve) - Ga * Ve if v < -Ve else (Gb * (v - Ve) + Ga * Ve if v > Ve
                                                        else Ga * v)

    def rhs(t, y):
        v1, v2, iL = y
        return [(G * (v2 - v1) - g(v1)) / 10.0, (G * (v1 - v2) - iL) / 100.0,
                (v2 - 12.5e-3 * iL) / 18.0]

    t = np.linspace(0.0, 300.0, 601)
    ref = solve_ivp(rhs, (0, 300.0), [4.0, 0.0, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-12, t_eval=t)
    res = ac.simulate(chua.ChuaCircuit(), t_end=300.0, rtol=1e-10, t_eval=t)
    for name, k in (("C1.v", 0), ("C2.v", 1), ("L.i", 2)):
        assert np.max(np.abs(res[name] - ref.y[k])) < 1e-5 * np.ptp(ref.y[k]), name
