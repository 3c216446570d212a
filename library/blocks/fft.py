"""Sampling and the FFT of a signal (Modelica.Blocks.Math.RealFFT and
Modelica.Math.FastFourierTransform, MSL v4.0.0).

``RealFFT`` samples its input ``ns`` times, one sample every ``samplePeriod`` from
``startTime`` (exact time events), into its buffer ``buf``, counting the ticks in the
Integer ``iTick``.  The MSL computes the FFT when the simulation terminates and writes
it to a file; here :meth:`RealFFT.spectrum` computes it from a result, the buffer as
it stands at the end of the run (the MSL's ``realFFT``), and :func:`realFFTwriteToFile`
writes the MSL's table of frequency lines.
"""
from __future__ import annotations

import math

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput

__all__ = ["realFFTsamplePoints", "realFFT", "realFFTwriteToFile", "RealFFT"]


def realFFTsamplePoints(f_max: float, f_resolution: float, f_max_factor: int = 5) -> int:
    """The number of sample points of a real FFT (MSL FastFourierTransform.
    realFFTsamplePoints): the smallest even ns >= 2 ceil(f_max f_max_factor /
    f_resolution) of the form 2^i 3^j 5^k."""
    if not f_resolution > 0:
        raise ac.InvalidValue(f"realFFTsamplePoints: f_resolution = {f_resolution!r} > 0 "
                              "required")
    if not f_max > f_resolution:
        raise ac.InvalidValue(f"realFFTsamplePoints: f_max = {f_max!r} > f_resolution = "
                              f"{f_resolution!r} required")
    ns = 2 * math.ceil(f_max * f_max_factor / f_resolution)
    ns += ns % 2
    while True:
        rest = ns
        for p in (2, 3, 5):
            while rest % p == 0:
                rest //= p
        if rest <= 1:
            return ns
        ns += 2


def realFFT(u, nfi: int) -> tuple:
    """(info, amplitudes, phases) of the real FFT of the samples ``u`` (MSL
    FastFourierTransform.realFFT): the first ``nfi`` frequency points, amplitudes |X_k|/nf
    (nf = len(u)/2 + 1, the MSL's scaling) with the mean value as the first, phases in
    degrees, set to 0 where the amplitude is below 1e-4 of the largest.  info is 1 if
    len(u) is odd, else 0."""
    u = np.asarray(u, dtype=float)
    nu = len(u)
    if nu % 2:
        return 1, np.zeros(nfi), np.zeros(nfi)
    if not 0 < nfi <= nu // 2 + 1:
        raise ac.InvalidValue(f"realFFT: nfi = {nfi} is out of range 1 .. {nu // 2 + 1}")
    u_dc = float(np.mean(u))
    spectrum = np.fft.rfft(u - u_dc)
    amplitudes = np.abs(spectrum[:nfi]) / (nu // 2 + 1)
    phases = np.degrees(np.arctan2(spectrum.imag[:nfi], spectrum.real[:nfi]))
    small = amplitudes < 1e-4 * np.max(amplitudes)
    amplitudes[0], phases[0] = u_dc, 0.0
    phases[1:][small[1:]] = 0.0
    return 0, amplitudes, phases


def realFFTwriteToFile(path, f_max: float, amplitudes, phases) -> np.ndarray:
    """The MSL's table of frequency lines (FastFourierTransform.realFFTwriteToFile),
    three rows per frequency f = f_max (i - 1)/(nA - 1): [f, 0, 0], [f, amplitude,
    phase], [f, 0, 0], written as CSV to ``path`` (the MSL writes a MAT file) and
    returned."""
    n = len(amplitudes)
    rows = []
    for i, (a, p) in enumerate(zip(amplitudes, phases)):
        f = f_max * i / (n - 1) if n > 1 else 0.0
        rows += [[f, 0.0, 0.0], [f, a, p], [f, 0.0, 0.0]]
    table = np.array(rows)
    if path is not None:
        np.savetxt(path, table, delimiter=",", header="f,abs,arg", comments="")
    return table


class RealFFT(ac.Component):
    """Sampling and FFT of input u (MSL Blocks.Math.RealFFT, a DiscreteBlock):

        ns = realFFTsamplePoints(f_max, f_res, 5),   samplePeriod = 1/(2 f_res div(ns, 2)),
        nf = max(1, min(ceil(f_max/f_res) + 1, div(ns, 2))),
        when sample(startTime, samplePeriod):  iTick = pre(iTick) + 1,
                                               buf[iTick] = u  (while iTick <= ns)

    ``f_max`` and ``f_res`` are given where it is made (they set the buffer's size).
    After a run, ``spectrum(res)`` is the MSL's (info, abs, arg) of the buffer and
    ``write(res, path)`` its file (the MSL's ``resultFileName``); a run that ends before
    the buffer is full is refused, as the MSL asserts.
    """

    f_max = ac.Parameter(1.0, structural=True, description="maximum frequency of interest "
                                                           "[Hz]")
    f_res = ac.Parameter(0.1, structural=True, description="frequency resolution [Hz]")
    startTime = ac.Parameter(0.0, unit="s", description="first sample time instant")
    samplePeriod = ac.Parameter(lambda c: c.sample_period, unit="s",
                                description="sample period, 1/(2 f_res div(ns, 2))")
    u = RealInput()
    iTick = ac.Variable(type=int, start=0, description="sample ticks")
    info = ac.Variable(type=int, start=0, description="information flag from FFT "
                                                       "computation")
    buf = ac.Variable(shape="ns", start=0.0, discrete=True, description="input buffer")

    def build(self):
        self.ns = realFFTsamplePoints(float(self.f_max), float(self.f_res), 5)
        self.nf = max(1, min(math.ceil(float(self.f_max) / float(self.f_res)) + 1,
                             self.ns // 2))
        self.sample_period = 1 / (2 * float(self.f_res) * (self.ns // 2))

    def equations(self):
        tick = ac.pre(self.iTick) + 1
        buf = list(self.buf)
        acts = [ac.assign(self.iTick, tick)]
        acts += [ac.assign(b, ac.if_else(sp.Eq(tick, k + 1), self.u.signal, ac.pre(b)))
                 for k, b in enumerate(buf)]
        return [ac.when(ac.sample(self.startTime, self.samplePeriod), *acts),
                ac.Eq(self.info, 0)]

    def spectrum(self, res) -> tuple:
        """(info, abs, arg): the FFT of the buffer at the end of the run ``res``."""
        path = self.path
        ticks = int(res[f"{path}.iTick"][-1])
        if ticks < self.ns:
            raise ac.SimulationError(
                f"'{path}' (RealFFT): sampling time not sufficient: {ticks} of {self.ns} "
                f"samples taken; stopTime >= startTime + {self.ns - 1} samplePeriod "
                "needed")
        samples = [res[f"{path}.buf[{k}]"][-1] for k in range(self.ns)]
        return realFFT(samples, self.nf)

    def write(self, res, path) -> np.ndarray:
        """The MSL's result file of the spectrum (realFFTwriteToFile), as CSV."""
        _, amplitudes, phases = self.spectrum(res)
        return realFFTwriteToFile(path, float(self.f_max), amplitudes, phases)
