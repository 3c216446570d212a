"""DC machines as the MSL builds them (Modelica.Electrical.Machines): the machines'
equations against closed forms, independent solutions and their power balance."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.electromechanical import machines
from acausal.library.electromechanical.machines.thermal import (alpha20Copper, convertAlpha,
                                                                convertResistance)


def _simulate(model, **options):
    """ac.simulate, which must reach t_end (a run that stops early fails the test)."""
    res = ac.simulate(model, **options)
    assert res.success, res.message
    if "t_eval" in options:
        assert len(res.t) == len(options["t_eval"])
    return res

W_NOMINAL = 1425 * 2 * math.pi / 60
K_PHI = (100.0 - 0.05 * 100.0) / W_NOMINAL      # ViNominal / wNominal of the default data


def test_temperature_coefficients_convert_as_the_msl_s_functions():
    """alpha at 75 degC of copper's 20 degC coefficient, and a resistance warmed by it:
    R(T) = R20 (1 + alpha20 (T - 293.15)) whatever the reference temperature."""
    a75 = convertAlpha(alpha20Copper, 348.15)
    assert a75 == pytest.approx(alpha20Copper / (1 + alpha20Copper * 55.0), rel=1e-15)
    R75 = 0.05 * (1 + alpha20Copper * 55.0)
    assert convertResistance(R75, 348.15, alpha20Copper, 293.15) == pytest.approx(0.05,
                                                                                 rel=1e-14)


def _dcpm_start_exact(t):
    """DCPM_Start as the linear DC motor it is without losses: La ia' = v(t) - Ra ia - kPhi
    w, (Jr + JL) w' = kPhi ia + tau_L(t), v the 0 -> 100 V ramp from 0.2 s to 1 s, tau_L =
    -63.66 N.m from 1.5 s (solve_ivp restarted at each kink)."""
    def rhs(s, y, v, tl):
        ia, w, phi = y
        return [(v(s) - 0.05 * ia - K_PHI * w) / 0.0015, (K_PHI * ia + tl) / 0.3, w]

    pieces = [(0.0, 0.2, lambda s: 0.0, 0.0), (0.2, 1.0, lambda s: 125.0 * (s - 0.2), 0.0),
              (1.0, 1.5, lambda s: 100.0, 0.0), (1.5, 2.0, lambda s: 100.0, -63.66)]
    y, out = [0.0, 0.0, 0.0], np.empty((len(t), 3))
    for a, b, v, tl in pieces:
        sol = solve_ivp(rhs, (a, b), y, args=(v, tl), method="Radau", rtol=1e-11,
                        atol=1e-10, dense_output=True)
        inside = (t >= a) & (t <= b)
        out[inside] = sol.sol(t[inside]).T
        y = sol.y[:, -1]
    return out


def test_permanent_magnet_machine_is_the_linear_dc_motor_of_its_data():
    from acausal.library.electromechanical.examples.msl.dcpm_start import DCPM_Start
    t = np.linspace(0, 2, 201)
    compiled = ac.compile(DCPM_Start())
    assert compiled.derived_parameters["dcpm.turnsRatio"] == pytest.approx(K_PHI, rel=1e-14)
    res = _simulate(compiled, t_end=2.0, rtol=1e-9, t_eval=t)
    exact = _dcpm_start_exact(t)
    assert np.max(np.abs(res["dcpm.ia"] - exact[:, 0])) < 1e-6 * 500
    assert np.max(np.abs(res["loadInertia.w"] - exact[:, 1])) < 1e-6 * 160
    assert np.allclose(res["dcpm.tauElectrical"], K_PHI * res["dcpm.ia"], rtol=1e-9,
                       atol=1e-9)


def test_machine_with_losses_balances_its_power():
    """DCPM_withLosses' dcpm2: electrical power in = shaft power + the change of the
    rotor's kinetic and the armature's magnetic energy + the losses, which leave
    through the heat ports into the thermal ambient."""
    from acausal.library.electromechanical.examples.msl.dcpm_with_losses import \
        DCPM_withLosses
    t = np.linspace(0.05, 2, 400)
    res = _simulate(DCPM_withLosses(), t_end=2.0, rtol=1e-10, t_eval=t)
    m = "dcpm2"
    p_in = res[f"{m}.va"] * res[f"{m}.ia"]
    w = res[f"{m}.wMechanical"]
    p_shaft = res[f"{m}.tauShaft"] * w
    # d/dt (Jr w^2/2 + La ia^2/2) = Jr w a + v_La ia
    d_stored = 0.15 * w * res[f"{m}.inertiaRotor.a"] + res[f"{m}.la.v"] * res[f"{m}.la.i"]
    heat = sum(res[f"{m}.thermalAmbient.heatPort{k}.Q_flow"]
               for k in ("Armature", "Core", "StrayLoad", "Friction", "Brush"))
    assert np.all(heat[t > 0.3] > 0)
    balance = p_in - p_shaft - d_stored - heat
    assert np.max(np.abs(balance)) < 1e-7 * np.max(np.abs(p_in))
    # each loss its law: friction 100 W at wNominal, quadratic in speed
    wNom = 148.44025288212
    assert np.allclose(res[f"{m}.friction.lossPower"][t > 0.5],
                       100.0 * (w[t > 0.5] / wNom)**3, rtol=1e-7)
    assert np.allclose(res[f"{m}.brush.v"][np.abs(res[f"{m}.ia"]) > 1.0],
                       0.5 * np.sign(res[f"{m}.ia"][np.abs(res[f"{m}.ia"]) > 1.0]),
                       rtol=1e-12)
    # the armature at 95 degC: Ra of copper given at TaRef = 20 degC
    R = res[f"{m}.ra.R"]
    assert np.allclose(R, 0.03864 * (1 + alpha20Copper * 75.0), rtol=1e-12)


def test_quasi_static_machine_has_no_armature_transient():
    """DCPM_QuasiStatic's dcpm2: Ra(T) ia = va - kPhi w at every instant (no la), while
    the transient dcpm1 lags behind the load steps."""
    from acausal.library.electromechanical.examples.msl.dcpm_quasi_static import \
        DCPM_QuasiStatic
    t = np.linspace(0, 2, 401)
    res = _simulate(DCPM_QuasiStatic(), t_end=2.0, rtol=1e-9, t_eval=t)
    ia, w = res["dcpm2.ia"], res["loadInertia2.w"]
    assert np.allclose(0.05 * ia, 100.0 - K_PHI * w, atol=1e-6)
    assert np.max(np.abs(res["dcpm1.ia"] - ia)) > 10.0


def test_separately_excited_field_builds_up_with_its_time_constant():
    """DCEE_Start: the excitation circuit, 100 V on Re = 100 Ohm and Le = 1 H, is
    ie = 1 A (1 - exp(-t Re/Le)); the induced voltage is turnsRatio Le ie w."""
    from acausal.library.electromechanical.examples.msl.dcee_start import DCEE_Start
    t = np.linspace(0, 0.1, 101)
    res = _simulate(DCEE_Start(), t_end=0.1, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["dcee.ie"] - (1 - np.exp(-100.0 * t)))) < 1e-8
    assert np.allclose(res["dcee.airGapDC.psi_e"], res["dcee.ie"], rtol=1e-12, atol=1e-15)


def test_series_excited_machine_makes_torque_from_the_square_of_its_current():
    """DCSE_Start: psi = Lme ia, so tauElectrical = turnsRatio Lme ia^2, with turnsRatio
    = ViNominal / (wNominal Lme |IaNominal|); on AC (DCSE_SinglePhase) the torque keeps
    its sign while the current alternates."""
    from acausal.library.electromechanical.examples.msl.dcse_single_phase import \
        DCSE_SinglePhase
    from acausal.library.electromechanical.examples.msl.dcse_start import DCSE_Start
    res = _simulate(DCSE_Start(), t_end=2.0, rtol=1e-9, n_points=201)
    wN = 1410 * 2 * math.pi / 60
    k = (100.0 - (0.05 + 0.01) * 100.0) / (wN * 0.0005 * 100.0)
    ia = res["dcse.ia"]
    assert np.allclose(res["dcse.tauElectrical"], k * 0.0005 * ia**2, rtol=1e-9, atol=1e-9)
    ac_res = _simulate(DCSE_SinglePhase(), t_end=0.5, rtol=1e-8, n_points=2001)
    assert ac_res["dcse.ia"].min() < -10 and ac_res["dcse.ia"].max() > 10
    assert ac_res["dcse.tauElectrical"].min() > -1e-6


def test_records_reach_the_loss_components():
    """A machine's loss records are its loss components' (the MSL's final record =
    record): what the example modifies is what the losses use, and the records' derived
    values follow."""
    from acausal.library.electromechanical.examples.msl.dcpm_with_losses import \
        DCPM_withLosses
    compiled = ac.compile(DCPM_withLosses())
    p = dict(zip(compiled.param_names, compiled.p))
    d = compiled.derived_parameters
    assert p["dcpm2.frictionParameters.PRef"] == 100.0
    assert d["dcpm2.friction.frictionParameters.tauRef"] == pytest.approx(100.0 / 148.44025288212)
    assert d["dcpm1.friction.frictionParameters.tauRef"] == 0.0
    assert d["dcpm2.core.coreParameters.GcRef"] == pytest.approx(
        200.0 / d["dcpm2.ViNominal"]**2)
    # Ra (given at TaRef = 20 degC) at TaNominal = 95 degC, and the brushes' 0.5 V
    assert d["dcpm2.ViNominal"] == pytest.approx(
        100.0 - 0.03864 * (1 + alpha20Copper * 75.0) * 100.0 - 0.5, rel=1e-12)


@pytest.mark.parametrize("module, name", [
    ("dcpm_with_losses", "DCPM_withLosses"), ("dcee_start", "DCEE_Start"),
    ("dcse_start", "DCSE_Start"), ("dc_compare_characteristics", "DC_CompareCharacteristics")])
def test_the_energy_audit_of_every_part_of_the_machines_closes(module, name):
    """Every part declares its energy (inductances and the air gap store it, the losses
    leave through their heat ports, the excitation is lossless) and the audit finds the
    balance and each part consistent."""
    import importlib
    cls = getattr(importlib.import_module(
        f"acausal.library.electromechanical.examples.msl.{module}"), name)
    model = cls()
    res = _simulate(model, t_end=min(cls.stop_time, 2.0), rtol=1e-9)
    audit = ac.energy_balance(res, model)
    assert audit.ok, audit.violations[:3]
    assert not audit.unclassified
