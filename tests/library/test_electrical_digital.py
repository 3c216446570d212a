"""Digital signals and the ideal AD/DA converters (Modelica.Electrical.Digital,
Modelica.Electrical.Analog.Ideal.AD_Converter/DA_Converter, MSL v4.0.0): the IEEE 1164
tables, the Pulse source's timing, and the converters' quantization in closed form."""
import itertools

import numpy as np
import pytest

import acausal as ac
from acausal.library.electrical import Ground, Resistor, SineVoltage
from acausal.library.electrical.converters import AD_Converter, DA_Converter
from acausal.library.electrical.digital import (AndTable, Logic, NotTable, OrTable, Pulse,
                                                ResolutionTable, UX01Table, X01Table,
                                                X01ZTable, XorTable)

L = Logic
ONE, ZERO, X = int(L["1"]), int(L["0"]), int(L["X"])


def _row(text):
    return tuple(L[c] for c in text)


def test_logic_coding_is_the_msl_one():
    assert [int(v) for v in L] == list(range(1, 10))
    assert "".join(v.name for v in L) == "UX01ZWLH-"


def test_tables_rows_of_ieee_1164():
    # rows of STD_ULOGIC's and/or/xor tables and the not/X01/X01Z/UX01 conversions
    # (IEEE 1164; the MSL's Tables list them in this order U X 0 1 Z W L H -)
    assert AndTable[L["1"]][1:] == _row("UX01XX01X")
    assert AndTable[L["U"]][1:] == _row("UU0UUU0UU")
    assert OrTable[L["0"]][1:] == _row("UX01XX01X")
    assert OrTable[L["U"]][1:] == _row("UUU1UUU1U")
    assert XorTable[L["H"]][1:] == _row("UX10XX10X")
    assert NotTable[1:] == _row("UX10XX10X")
    assert X01Table[1:] == _row("XX01XX01X")
    assert X01ZTable[1:] == _row("XX01ZX01Z")
    assert UX01Table[1:] == _row("UX01XX01X")
    assert ResolutionTable[L["0"]][1:] == _row("UX0X0000X")
    assert ResolutionTable[L["Z"]][1:] == _row("UX01ZWLHX")
    assert ResolutionTable[L["L"]][1:] == _row("UX01LWLWX")


def test_tables_commute_and_obey_de_morgan():
    for a, b in itertools.product(L, L):
        for table in (AndTable, OrTable, XorTable, ResolutionTable):
            assert table[a][b] == table[b][a]
        # not(a and b) = not a or not b, on every pair of the 9 values
        assert NotTable[AndTable[a][b]] == OrTable[NotTable[a]][NotTable[b]]
        # the resolution is associative with Z as its neutral element
        assert ResolutionTable[a][L["Z"]] == a or a.name == "-"
        for c in L:
            assert (ResolutionTable[ResolutionTable[a][b]][c]
                    == ResolutionTable[a][ResolutionTable[b][c]])


class _Pulses(ac.Component):
    pulse = Pulse(pulse=ONE, quiet=ZERO, width=30.0, period=1.0, startTime=0.5, nperiod=2)


def test_pulse_timing_and_number_of_periods():
    t = np.arange(60) * 0.1 + 0.05
    res = ac.simulate(_Pulses(), t_end=6.0, rtol=1e-6, t_eval=t)
    phase = np.mod(t - 0.5, 1.0)
    # '1' for 30 % of each of the first two periods from 0.5 s, '0' otherwise
    expected = np.where((t >= 0.5) & (t < 2.5) & (phase < 0.3), ONE, ZERO)
    np.testing.assert_array_equal(res["pulse.y"], expected)
    np.testing.assert_array_equal(res["pulse.T0"], np.clip(np.floor(t - 0.5), 0, 2) + 0.5)
    np.testing.assert_array_equal(res["pulse.np"], np.clip(np.floor(t - 0.5) + 1, 0, 3))


class _Conversion(ac.Component):
    """A 10 Hz sine (0 ... 10 V) converted to N bits at each millisecond and back."""

    N = 5
    aD = AD_Converter(N=N, Rin=2e3, VRefLow=1.0, VRefHigh=9.0)
    dA = DA_Converter(N=N, Vref=8.0)
    trig = Pulse(pulse=ONE, quiet=ZERO, width=10.0, period=1e-3)
    source = SineVoltage(V=5.0, f=10.0, offset=5.0)
    load = Resistor(R=10.0)
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.source.p, self.aD.p), c(self.source.n, self.aD.n),
                c(self.source.n, self.ground.p), c(self.trig.y, self.aD.trig),
                c(self.trig.y, self.dA.trig),
                *(c(y, x) for y, x in zip(self.aD.y, self.dA.x)),
                c(self.dA.p, self.load.p), c(self.dA.n, self.ground.p),
                c(self.load.n, self.ground.p)]


def test_converters_quantize_mid_tread_and_back():
    t = (np.arange(100) + 0.5) * 1e-3
    res = ac.simulate(_Conversion(), t_end=0.1, rtol=1e-6, t_eval=t)
    tk = np.floor(t / 1e-3) * 1e-3                       # the last trigger
    uk = 5.0 + 5.0 * np.sin(2 * np.pi * 10.0 * tk)
    levels = 2 ** 5 - 1
    code = np.clip(np.floor((uk - 1.0) / 8.0 * levels + 0.5), 0, None)
    code[uk <= 1.0] = 0
    after = t > 1e-3                   # no trigger fires at the initialization
    bits = [res[f"aD.y[{i}].signal"] for i in range(5)]
    for i, y in enumerate(bits):
        np.testing.assert_array_equal(y[after], np.where(np.mod(code // 2 ** i, 2) > 0,
                                                         ONE, ZERO)[after])
        np.testing.assert_array_equal(y[~after], X)          # 'X' until the first trigger
    # the MSL's z after its loop: div(code, 2^N), 1 where u is above VRefHigh
    np.testing.assert_array_equal(res["aD.z"][after], (code // 2 ** 5)[after])
    assert np.any(res["aD.z"] == 1)
    v = res["dA.p.v"]
    # the DA converter reads the N bits: the code modulo 2^N
    assert np.max(np.abs(v[after] - (np.mod(code, 2 ** 5) * 8.0 / levels)[after])) <= 1e-12 * 8.0
    assert np.all(v[~after] == 0.0)
    # input resistance: p.i Rin = u
    u = res["aD.u"]
    assert np.max(np.abs(res["aD.p.i"] * 2e3 - u)) <= 1e-9 * np.max(np.abs(u))
