"""Ideal converters between analog and digital signals (Modelica.Electrical.Analog.Ideal,
MSL v4.0.0: AD_Converter, DA_Converter).  Their digital signals are the 9-valued
``Logic`` codes of :mod:`.digital`; the vectors ``y[N]`` and ``x[N]`` are lists of ports
named from 0 as Python indexes them (``y[0]``, the MSL's ``y[1]``, is the least
significant bit).
"""
import sympy as sp

import acausal as ac
from acausal.ports import NegativePin, PositivePin

from .digital import DigitalInput, DigitalOutput, Logic, is_one

__all__ = ["AD_Converter", "DA_Converter"]

_ZERO, _ONE, _UNKNOWN = int(Logic["0"]), int(Logic["1"]), int(Logic["X"])


class AD_Converter(ac.Component):
    """Simple n-bit analog to digital converter (Modelica.Electrical.Analog.Ideal.
    AD_Converter, MSL v4.0.0): an input resistance Rin between p and n, and at each
    rising of the trigger to '1' or 'H' the input voltage u coded in N bits, mid-tread,
    over the range VRefLow ... VRefHigh (little-endian, y[1] the least significant bit):

        u = p.v - n.v,   p.i Rin = u,   p.i + n.i = 0
        when trig == '1' or trig == 'H':
            z := if u > VRefLow then integer((u - VRefLow)/(VRefHigh - VRefLow) (2^N - 1)
                 + 0.5) else 0
            for i in 1:N:  y[i] := if mod(z, 2) > 0 then '1' else '0';  z := div(z, 2)

    The MSL's algorithm leaves z = div(code, 2^N) after its loop; here bit i of the code
    is written directly, mod(div(code, 2^(i-1)), 2).  The outputs are 'X' until the
    first trigger (the MSL's initial algorithm).
    """

    p = PositivePin()
    n = NegativePin()
    trig = DigitalInput()
    N = ac.Parameter(8, structural=True, min=1,
                     description="resolution in bits - output signal width")
    VRefHigh = ac.Parameter(10.0, unit="V", description="high reference voltage")
    VRefLow = ac.Parameter(0.0, unit="V", description="low reference voltage")
    Rin = ac.Parameter(1e6, unit="Ohm", description="input resistance")
    z = ac.Variable(type=int, start=0, fixed=True)
    u = ac.Variable(unit="V")

    def build(self):
        self.y = [DigitalOutput(signal={"start": _UNKNOWN}) for _ in range(int(self.N))]

    def equations(self):
        levels = 2 ** int(self.N) - 1
        code = ac.if_else(self.u > self.VRefLow,
                          ac.integer((self.u - self.VRefLow) / (self.VRefHigh - self.VRefLow)
                                     * levels + sp.Rational(1, 2)), 0)
        bits = [sp.Mod(sp.floor(code / 2 ** i), 2) for i in range(len(self.y))]
        return [ac.Eq(self.p.v - self.n.v, self.u),
                ac.Eq(self.p.i * self.Rin, self.u),
                ac.Eq(self.p.i + self.n.i, 0),
                ac.when(is_one(self.trig.signal),
                        *(ac.assign(y.signal, ac.if_else(bit > 0, _ONE, _ZERO))
                          for y, bit in zip(self.y, bits)),
                        ac.assign(self.z, sp.floor(code / 2 ** len(self.y))))]


class DA_Converter(ac.Component):
    """Simple digital to analog converter (Modelica.Electrical.Analog.Ideal.DA_Converter,
    MSL v4.0.0): an ideal voltage source whose voltage is set at each rising of the
    trigger to '1' or 'H' from the N bits x (x[1] the least significant, a bit is 1
    when it is '1' or 'H'):

        when trig == '1' or trig == 'H':
            y := sum(if x[i] == '1' or x[i] == 'H' then 2^(i-1) else 0, i = 1..N)
            vout := y Vref/(2^N - 1)
        p.v - n.v = vout,   p.i + n.i = 0
    """

    p = PositivePin()
    n = NegativePin()
    trig = DigitalInput()
    N = ac.Parameter(8, structural=True, min=1,
                     description="resolution - input signal width")
    Vref = ac.Parameter(10.0, unit="V", description="reference voltage")
    vout = ac.Variable(discrete=True, start=0.0, fixed=True, unit="V")
    y = ac.Variable(discrete=True, start=0.0, fixed=True)

    def build(self):
        self.x = [DigitalInput() for _ in range(int(self.N))]

    def equations(self):
        value = sum(ac.if_else(is_one(x.signal), 2 ** i, 0) for i, x in enumerate(self.x))
        return [ac.when(is_one(self.trig.signal),
                        ac.assign(self.y, value),
                        ac.assign(self.vout, value * self.Vref / (2 ** int(self.N) - 1))),
                ac.Eq(self.p.v - self.n.v, self.vout),
                ac.Eq(self.p.i + self.n.i, 0)]
