"""RealFFT and the MSL's FFT functions (library/blocks/fft.py): the sample-point count
against a brute-force search, the spectrum of sums of sines at known frequency lines
against their closed form (the MSL's scaling |X_k|/(N/2 + 1)), and the block's sampling
against the sampled signal itself."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.blocks.fft import (RealFFT, realFFT, realFFTsamplePoints,
                                        realFFTwriteToFile)


def _smooth_235(n: int) -> bool:
    for p in (2, 3, 5):
        while n % p == 0:
            n //= p
    return n == 1


@pytest.mark.parametrize("f_max, f_res, factor", [(2000, 5, 5), (7, 1, 5), (11, 0.3, 3),
                                                  (1.3, 0.1, 1)])
def test_sample_points_are_the_smallest_even_235_number(f_max, f_res, factor):
    ns = realFFTsamplePoints(f_max, f_res, factor)
    lower = 2 * math.ceil(f_max * factor / f_res)
    brute = next(n for n in range(lower, 10 * lower + 10) if n % 2 == 0 and _smooth_235(n))
    assert ns == brute


def test_sample_points_refuse_bad_arguments():
    with pytest.raises(ac.InvalidValue, match="f_resolution"):
        realFFTsamplePoints(10, 0)
    with pytest.raises(ac.InvalidValue, match="f_max"):
        realFFTsamplePoints(1, 2)


def test_spectrum_of_sines_at_frequency_lines():
    N = 60
    k = np.arange(N)
    u = 1.5 + 2.0 * np.sin(2 * np.pi * 3 * k / N) + 0.5 * np.cos(2 * np.pi * 7 * k / N + 0.4)
    info, amplitudes, phases = realFFT(u, 11)
    scale = (N / 2) / (N / 2 + 1)              # the MSL divides |X_k| by N/2 + 1
    expected = np.zeros(11)
    expected[0], expected[3], expected[7] = 1.5, 2.0 * scale, 0.5 * scale
    assert info == 0
    assert np.max(np.abs(amplitudes - expected)) < 1e-12
    assert phases[3] == pytest.approx(-90.0, abs=1e-9)           # sin = cos(. - 90 deg)
    assert phases[7] == pytest.approx(math.degrees(0.4), abs=1e-9)
    others = [i for i in range(11) if i not in (3, 7)]
    assert np.all(phases[others] == 0.0)            # below 1e-4 of the largest: zero


def test_odd_length_is_info_1_and_table_has_three_rows_per_line(tmp_path):
    info, amplitudes, _ = realFFT(np.ones(7), 3)
    assert info == 1 and np.all(amplitudes == 0)
    table = realFFTwriteToFile(tmp_path / "fft.csv", 10.0, [1.0, 2.0, 3.0], [0.0, 5.0, 6.0])
    assert table.shape == (9, 3)
    assert np.allclose(table[1::3], [[0, 1, 0], [5, 2, 5], [10, 3, 6]])
    assert np.all(table[0::3, 1:] == 0) and np.all(table[2::3, 1:] == 0)
    assert np.allclose(np.loadtxt(tmp_path / "fft.csv", delimiter=",", skiprows=1), table)


class Sampled(ac.Component):
    sine = Sine(amplitude=2.0, f=10.0, offset=1.0)
    realFFT = RealFFT(startTime=0.01, f_max=20.0, f_res=2.0)

    def equations(self):
        return [ac.connect(self.sine.y, self.realFFT.u)]


def test_real_fft_block_samples_its_input():
    model = Sampled()
    assert model.realFFT.ns == 100 and model.realFFT.nf == 11
    T = 1 / (2 * 2.0 * 50)
    res = ac.simulate(model, t_end=0.01 + 99 * T + 1e-3, rtol=1e-8)
    assert int(res["realFFT.iTick"][-1]) == 100
    t_k = 0.01 + T * np.arange(100)
    buf = np.array([res[f"realFFT.buf[{k}]"][-1] for k in range(100)])
    assert np.max(np.abs(buf - (1 + 2 * np.sin(2 * np.pi * 10 * t_k)))) < 1e-9
    info, amplitudes, phases = model.realFFT.spectrum(res)
    assert info == 0
    assert amplitudes[0] == pytest.approx(1.0, abs=1e-9)
    assert amplitudes[5] == pytest.approx(2.0 * 50 / 51, rel=1e-9)     # 10 Hz = line 5
    assert np.max(np.delete(amplitudes, [0, 5])) < 1e-9
    # sin(2 pi 10 (t_k)) with t_0 = 0.01 s: phase 2 pi 0.1 - pi/2
    assert phases[5] == pytest.approx(math.degrees(2 * math.pi * 0.1) - 90.0, abs=1e-6)


def test_real_fft_refuses_a_run_too_short_for_its_buffer():
    model = Sampled()
    res = ac.simulate(model, t_end=0.2)
    with pytest.raises(ac.SimulationError, match="sampling time not sufficient"):
        model.realFFT.spectrum(res)
