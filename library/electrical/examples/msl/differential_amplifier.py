"""Modelica.Electrical.Analog.Examples.OpAmps.DifferentialAmplifier (MSL v4.0.0): the
line-to-line voltage of a 400 V, 50 Hz source, floating against the op-amp's ground
through 100 kOhm, measured by a differential amplifier (attenuation 100) on an
idealized op-amp with +-15 V supply pins; the root mean square of its output over each
period.

The MSL's Blocks.Math.Mean and RootMeanSquare are not in acausal.library.blocks; the
two blocks below are their equations, for this example."""
import math

import acausal as ac
from acausal.library.blocks import Gain, Product, Sqrt
from acausal.library.blocks.interfaces import SISO
from acausal.library.electrical import (ConstantVoltage, Ground, IdealizedOpAmpLimited,
                                        Resistor, SineVoltage, VoltageSensor)
from acausal.ports import NegativePin

__all__ = ["Mean", "RootMeanSquare", "DifferentialAmplifier"]


class Mean(SISO):
    """Mean over the period 1/f (Modelica.Blocks.Math.Mean, yGreaterOrEqualZero = true):

        der(x) = u;  at t0 + k/f:  y_last = max(0, f pre(x)),  reinit(x, 0);  y = y_last
    """

    f = ac.Parameter(50.0, unit="Hz", description="base frequency")
    x0 = ac.Parameter(0.0, description="start value of integrator state")
    x = ac.Variable(start=0.0, description="integrator state")
    y_last = ac.Variable(discrete=True, start=0.0, description="last sampled mean value")

    def initial_equations(self):
        return [ac.Eq(self.x, self.x0)]

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.u),
                ac.when(ac.sample(1 / self.f, 1 / self.f),
                        # x before the reinit: the MSL's pre(x)
                        ac.assign(self.y_last, ac.max(0.0, self.f * self.x)),
                        ac.reinit(self.x, 0)),
                ac.Eq(self.y, self.y_last)]


class RootMeanSquare(SISO):
    """Root mean square over the period 1/f (Modelica.Blocks.Math.RootMeanSquare): the
    square of the input, its Mean, the square root."""

    f = ac.Parameter(50.0, unit="Hz", description="base frequency")
    x0 = ac.Parameter(0.0, description="start value of integrator state")
    product = Product()
    mean = Mean(f=ac.ref("f"), x0=ac.ref("x0"))
    sqrt1 = Sqrt()

    def equations(self):
        c = ac.connect
        return [c(self.product.y, self.mean.u), c(self.mean.y, self.sqrt1.u),
                c(self.sqrt1.y, self.y), c(self.u, self.product.u1),
                c(self.u, self.product.u2)]


VSource = 400.0        # source RMS voltage line-to-line (V)
fSource = 50.0         # source frequency (Hz)
RLoad = 10.0           # load resistance of source (Ohm)
RGround = 100e3        # resistance of ground connection (Ohm)
V0 = 10e3              # no-load differential amplification
VSupply = 15.0         # supply voltage (V)
k = 100.0              # attenuation factor
R1 = 100e3             # resistor 1 (Ohm)
R2 = R1
R3 = R1 / k
R4 = R3
RInstrument = 100e3    # input resistance of instrument (Ohm)


class DifferentialAmplifier(ac.Component):
    """The MSL's DifferentialAmplifierData; the MSL's protected pins groundSource and
    groundOpAmp are the two grounds' nodes."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.DifferentialAmplifier"
    stop_time = 0.2
    tolerance = 1e-08

    sourceVoltage1 = SineVoltage(V=math.sqrt(2 / 3) * VSource, phase=1.0471975511966,
                                 f=fSource)
    sourceVoltage2 = SineVoltage(V=math.sqrt(2 / 3) * VSource, phase=-1.0471975511966,
                                 f=fSource)
    resistanceLoad = Resistor(R=RLoad)
    voltageSensorSource = VoltageSensor()
    gain = Gain(k=-1 / k)
    resistorGround = Resistor(R=RGround, i={"start": 0.0, "fixed": False})
    opAmp = IdealizedOpAmpLimited(V0=V0, useSupply=True, Vps=VSupply, Vns=-VSupply)
    resistor1 = Resistor(R=R1, i={"start": 0.0, "fixed": False})
    resistor2 = Resistor(R=R2, i={"start": 0.0, "fixed": False})
    resistor3 = Resistor(R=R3)
    resistor4 = Resistor(R=R4)
    positiveSupply = ConstantVoltage(V=VSupply)
    negativeSupply = ConstantVoltage(V=-VSupply)
    resistanceInstrument = Resistor(R=RInstrument)
    voltageSensor = VoltageSensor()
    rootMeanSquare = RootMeanSquare(f=fSource)
    ground = Ground()
    groundSource = NegativePin()
    groundOpAmp = NegativePin()

    def equations(self):
        c = ac.connect
        return [c(self.voltageSensor.v, self.rootMeanSquare.u),
                c(self.resistor4.n, self.groundOpAmp),
                c(self.groundOpAmp, self.resistorGround.n),
                c(self.groundOpAmp, self.resistanceInstrument.n),
                c(self.groundOpAmp, self.voltageSensor.n),
                c(self.groundOpAmp, self.positiveSupply.n),
                c(self.groundOpAmp, self.negativeSupply.n),
                c(self.negativeSupply.p, self.opAmp.s_n), c(self.opAmp.s_p, self.positiveSupply.p),
                c(self.sourceVoltage1.n, self.groundSource),
                c(self.groundSource, self.sourceVoltage2.n),
                c(self.groundSource, self.resistorGround.p), c(self.groundSource, self.ground.p),
                c(self.sourceVoltage1.p, self.resistor1.p),
                c(self.sourceVoltage2.p, self.resistor2.p),
                c(self.voltageSensorSource.v, self.gain.u),
                c(self.sourceVoltage2.p, self.voltageSensorSource.n),
                c(self.sourceVoltage1.p, self.voltageSensorSource.p),
                c(self.sourceVoltage1.p, self.resistanceLoad.p),
                c(self.sourceVoltage2.p, self.resistanceLoad.n),
                c(self.resistor3.n, self.resistanceInstrument.p),
                c(self.resistor3.n, self.voltageSensor.p), c(self.resistor3.n, self.opAmp.out),
                c(self.resistor1.n, self.resistor3.p), c(self.resistor2.n, self.resistor4.p),
                c(self.resistor2.n, self.opAmp.in_p), c(self.resistor1.n, self.opAmp.in_n)]


if __name__ == "__main__":
    res = ac.simulate(DifferentialAmplifier(), t_end=0.2, rtol=1e-8)
    print(f"rootMeanSquare.y at {res.t[-1]:g} s: {res['rootMeanSquare.y'][-1]:.6g} V")
