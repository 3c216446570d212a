"""RT-04: motor and load with an elastic transmission, frequency response (Egeland &
Gravdahl, 001 §3.5.1-3.5.5, Fig. 3.11's numbers K = 0.5, J_m = J_L = 1, D = 0.01).

    theta_m/T_m = 1/(J s^2) (1 + 2 zeta_a s/w_a + (s/w_a)^2) / (1 + 2 zeta_1 s/w_1 + (s/w_1)^2)  (3.85)
    theta_L/T_m = 1/(J s^2) (1 + 2 zeta_1 s/w_1) / (1 + 2 zeta_1 s/w_1 + (s/w_1)^2)               (3.86)
    w_1 = sqrt(K/J_e), zeta_1 = D/(2 sqrt(J_e K)), w_a = sqrt(J_m/J) w_1, zeta_a = sqrt(J_m/J) zeta_1

with J = J_m + J_L, J_e = J_m J_L/J: w_1 = 1 rad/s, zeta_1 = 0.01, w_a = 0.7071 rad/s,
zeta_a = 0.00707.  From the storage function, V' = theta_m' T_m - D theta_e'^2 (3.94), so
the motor-speed response is positive real: Re H_wm(jw) >= 0 (3.95),
|angle H_wm(jw)| <= 90 deg (3.96), and -180 <= angle H_theta_m(jw) <= 0 deg (3.97); the
load angle drops a further 180 deg across the resonance.

Checked on ``library/electromechanical/examples/elastic_transmission.ElasticTransmission``
(Inertia - SpringDamper - Inertia driven by a Torque), linearized from the drive's torque
signal: poles and zeros are the printed w_1, zeta_1, w_a, zeta_a (1e-9), the responses
of motor speed, motor angle and load angle equal (3.85)/(3.86) on 0.01 ... 100 rad/s to
1e-10 relative (measured 3e-14, 3e-14, 2.5e-12), and the phase bounds (3.95)-(3.97) hold
on that grid, through w_a and w_1 where the phase swings by nearly 180 deg (max |angle
H_wm| measured 89.9999989 deg); the load angle drops 176.8 deg between w_1/2 and 2 w_1.
"""
import numpy as np
import pytest

from acausal.analysis import linearize
from acausal.library.electromechanical.examples.elastic_transmission import ElasticTransmission

K, J_M, J_L, D = 0.5, 1.0, 1.0, 0.01
J = J_M + J_L
J_E = J_M * J_L / J
W_1 = np.sqrt(K / J_E)
Z_1 = D / (2 * np.sqrt(J_E * K))
W_A = np.sqrt(J_M / J) * W_1
Z_A = np.sqrt(J_M / J) * Z_1
W = np.unique(np.concatenate([np.logspace(-2, 2, 2001),
                              W_A * (1 + np.linspace(-0.05, 0.05, 201)),
                              W_1 * (1 + np.linspace(-0.05, 0.05, 201))]))
S = 1j * W


def _h_theta_m(s):
    return (1 + 2 * Z_A * s / W_A + (s / W_A) ** 2) / (J * s**2 * (1 + 2 * Z_1 * s / W_1
                                                                    + (s / W_1) ** 2))


def _h_theta_l(s):
    return (1 + 2 * Z_1 * s / W_1) / (J * s**2 * (1 + 2 * Z_1 * s / W_1 + (s / W_1) ** 2))


@pytest.fixture(scope="module")
def systems():
    model = ElasticTransmission()
    return {out: linearize(model, ["drive.tau.signal"], [out])
            for out in ("motor.w", "motor.phi", "load.phi")}


def test_printed_resonance_and_anti_resonance(systems):
    assert (W_1, Z_1, W_A) == pytest.approx((1.0, 0.01, 0.70710678), rel=1e-8)
    sys = systems["motor.w"]
    p = sys.minimal().poles()
    p = p[np.abs(p) > 1e-9]
    assert np.abs(p) == pytest.approx(np.full(2, W_1), rel=1e-9)
    assert -p.real / np.abs(p) == pytest.approx(np.full(2, Z_1), rel=1e-9)
    z = sys.zeros()
    assert np.abs(z) == pytest.approx(np.full(2, W_A), rel=1e-9)
    assert -z.real / np.abs(z) == pytest.approx(np.full(2, Z_A), rel=1e-9)


@pytest.mark.parametrize("output, exact", [("motor.w", lambda s: s * _h_theta_m(s)),
                                           ("motor.phi", _h_theta_m),
                                           ("load.phi", _h_theta_l)])
def test_frequency_response_is_3_85_and_3_86(systems, output, exact):
    H = systems[output].freqresp(W)
    ref = exact(S)
    assert np.max(np.abs(H - ref) / np.abs(ref)) < 1e-10


def test_motor_speed_response_is_positive_real_3_95_3_96(systems):
    H = systems["motor.w"].freqresp(W)
    assert np.all(H.real >= -1e-9 * np.abs(H))                          # (3.95)
    phase = np.degrees(np.angle(H))
    assert np.all(np.abs(phase) <= 90.0 + 1e-7)                         # (3.96)
    # the bound is reached: near -90 deg below w_a, swinging to +90 between w_a and w_1
    assert phase[W < 0.5 * W_A].min() < -89.0
    assert phase[(W > W_A * 1.05) & (W < W_1 * 0.95)].max() > 80.0


def test_motor_angle_phase_3_97_and_load_angle_drop(systems):
    phase_m = np.degrees(np.angle(systems["motor.phi"].freqresp(W)))
    # angle of H_theta_m = angle of H_wm - 90 deg, taken in (-270, 90]
    phase_m = np.where(phase_m > 90.0, phase_m - 360.0, phase_m)
    assert np.all((phase_m >= -180.0 - 1e-7) & (phase_m <= 1e-7))       # (3.97)
    phase_l = np.degrees(np.unwrap(np.angle(systems["load.phi"].freqresp(W))))
    below, above = phase_l[np.searchsorted(W, 0.5 * W_1)], phase_l[np.searchsorted(W, 2 * W_1)]
    # "drops 180 deg": less the lead of the zero at w_1/(2 zeta_1) = 50 rad/s and the
    # skirts of a zeta_1 = 0.01 resonance between w_1/2 and 2 w_1 (3.2 deg together)
    assert 170.0 < below - above < 180.0
