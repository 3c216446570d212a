"""Modelica.Electrical.Analog.Examples.OpAmps (MSL v4.0.0): circuits with operational
amplifiers, each against the MSL's reference result.  The inputs are the MSL's: a
trapezoid of frequency f = 10 Hz (rising 0.2/f, width 0.3/f, falling 0.2/f) started
half-way along its top (startTime = -(rising + width/2)), or a sine and a constant."""
import math

import acausal as ac
from acausal.library.electrical import (Capacitor, ConstantVoltage, Ground,
                                        IdealizedOpAmpLimited, Inductor, Potentiometer,
                                        Resistor, SineVoltage, SupplyVoltage,
                                        TrapezoidVoltage, VoltageSensor)

from .op_amp_circuits import (Add, Buffer, Der, Derivative, Feedback, FirstOrder, Gain,
                              Integrator)

__all__ = ["Adder", "Comparator", "Differentiator", "HighPass", "Integrator_",
           "InvertingAmplifier", "InvertingSchmittTrigger", "LCOscillator", "LowPass",
           "Multivibrator", "NonInvertingAmplifier", "SchmittTrigger", "SignalGenerator",
           "Subtracter", "VoltageFollower"]

Vin = 5.0          # amplitude of the input voltage (V)
f = 10.0           # frequency of the input voltage (Hz)
Vps, Vns = 15.0, -15.0


def _trapezoid(V=2 * Vin, offset=-Vin):
    """The MSL's vIn: V over a period 1/f, started half-way along its top."""
    rising, width = 0.2 / f, 0.3 / f
    return TrapezoidVoltage(V=V, rising=rising, width=width, falling=0.2 / f, period=1 / f,
                            nperiod=-1, offset=offset, startTime=-(rising + width / 2))


class _Example(ac.Component):
    stop_time = 1.0
    tolerance = 1e-07


class Adder(_Example):
    """Inverting adder (OpAmps.Adder): vOut = -(vIn1 + vIn2), a 5 V, 10 Hz sine and 5 V."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.Adder"
    ground = Ground()
    vIn1 = SineVoltage(V=Vin, f=f)
    vIn2 = ConstantVoltage(V=Vin)
    vOut = VoltageSensor()
    add = Add(p1_2={"i": {"start": 0.0}})

    def equations(self):
        c = ac.connect
        return [c(self.add.n1, self.ground.p), c(self.vIn1.p, self.add.p1),
                c(self.vIn2.p, self.add.p1_2), c(self.ground.p, self.vIn2.n),
                c(self.ground.p, self.vIn1.n), c(self.add.p2, self.vOut.n),
                c(self.add.n2, self.vOut.p)]


class Subtracter(_Example):
    """Inverting subtracter (OpAmps.Subtracter): vOut = -(vIn2 - vIn1)."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.Subtracter"
    ground = Ground()
    vIn1 = SineVoltage(V=Vin, f=f)
    vIn2 = ConstantVoltage(V=Vin)
    vOut = VoltageSensor()
    feedback = Feedback(p1_2={"i": {"start": 0.0}})

    def equations(self):
        c = ac.connect
        return [c(self.feedback.n1, self.ground.p), c(self.vIn1.p, self.feedback.p1),
                c(self.vIn2.p, self.feedback.p1_2), c(self.ground.p, self.vIn2.n),
                c(self.ground.p, self.vIn1.n), c(self.feedback.p2, self.vOut.n),
                c(self.feedback.n2, self.vOut.p)]


class Comparator(_Example):
    """Comparator (OpAmps.Comparator): the input against Vref = 0 from a potentiometer
    on a +-15 V supply."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.Comparator"
    opAmp = IdealizedOpAmpLimited(Vps=Vps, Vns=Vns)
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    potentiometer = Potentiometer(R=1000.0, rConstant=(0.0 - Vns) / (Vps - Vns))
    supplyVoltage = SupplyVoltage(Vps=Vps, Vns=Vns)

    def equations(self):
        c = ac.connect
        return [c(self.vIn.p, self.opAmp.in_p), c(self.opAmp.out, self.vOut.p),
                c(self.ground.p, self.vOut.n), c(self.ground.p, self.vIn.n),
                c(self.potentiometer.contact, self.opAmp.in_n),
                c(self.potentiometer.pin_p, self.supplyVoltage.pin_p),
                c(self.potentiometer.pin_n, self.supplyVoltage.pin_n),
                c(self.ground.p, self.supplyVoltage.ground)]


class Differentiator(_Example):
    """Differentiating amplifier (OpAmps.Differentiator), k = 2 at f."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.Differentiator"
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    der_ = Der(k=2.0, f=f, v={"fixed": True})

    def equations(self):
        c = ac.connect
        return [c(self.vIn.p, self.der_.p1), c(self.vIn.n, self.der_.n1),
                c(self.der_.n1, self.ground.p), c(self.der_.p2, self.vOut.p),
                c(self.der_.n2, self.vOut.n)]


class HighPass(_Example):
    """High-pass filter (OpAmps.HighPass), limiting frequency fG = f/10."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.HighPass"
    ground = Ground()
    vOut = VoltageSensor()
    derivative = Derivative(T=1 / (2 * math.pi * (f / 10)), v={"fixed": True})
    vIn = _trapezoid(V=Vin, offset=0.0)

    def equations(self):
        c = ac.connect
        return [c(self.derivative.n1, self.ground.p), c(self.derivative.p2, self.vOut.p),
                c(self.derivative.n2, self.vOut.n), c(self.vIn.p, self.derivative.p1),
                c(self.vIn.n, self.derivative.n1)]


class LowPass(_Example):
    """Low-pass filter (OpAmps.LowPass), limiting frequency fG = f/10."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.LowPass"
    ground = Ground()
    vOut = VoltageSensor()
    firstOrder = FirstOrder(T=1 / (2 * math.pi * (f / 10)), v={"fixed": True})
    vIn = _trapezoid(V=Vin, offset=0.0)

    def equations(self):
        c = ac.connect
        return [c(self.firstOrder.n1, self.ground.p), c(self.firstOrder.p2, self.vOut.p),
                c(self.firstOrder.n2, self.vOut.n), c(self.vIn.p, self.firstOrder.p1),
                c(self.vIn.n, self.firstOrder.n1)]


class Integrator_(_Example):
    """Integrating amplifier (OpAmps.Integrator; named Integrator_ here beside the
    circuit Integrator), k = 2 at f."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.Integrator"
    ground = Ground()
    vOut = VoltageSensor()
    integrator = Integrator(k=2.0, f=f, v={"fixed": True})
    vIn = _trapezoid()

    def equations(self):
        c = ac.connect
        return [c(self.integrator.n1, self.ground.p), c(self.integrator.p2, self.vOut.p),
                c(self.integrator.n2, self.vOut.n), c(self.vIn.p, self.integrator.p1),
                c(self.vIn.n, self.integrator.n1)]


class InvertingAmplifier(_Example):
    """Inverting amplifier (OpAmps.InvertingAmplifier), k = 2."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.InvertingAmplifier"
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    gain = Gain(k=2.0)

    def equations(self):
        c = ac.connect
        return [c(self.vIn.p, self.gain.p1), c(self.gain.n1, self.ground.p),
                c(self.gain.n1, self.vIn.n), c(self.gain.p2, self.vOut.n),
                c(self.gain.n2, self.vOut.p)]


class NonInvertingAmplifier(_Example):
    """Non-inverting amplifier (OpAmps.NonInvertingAmplifier), k = 2."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.NonInvertingAmplifier"
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    buffer = Buffer(k=2.0)

    def equations(self):
        c = ac.connect
        return [c(self.vIn.n, self.buffer.n1), c(self.vIn.p, self.buffer.p1),
                c(self.buffer.p2, self.vOut.p), c(self.buffer.n2, self.vOut.n),
                c(self.buffer.n1, self.ground.p)]


class InvertingSchmittTrigger(_Example):
    """Inverting Schmitt trigger (OpAmps.InvertingSchmittTrigger), hysteresis 1 V:
    R2 = (1 - k)/k R1, k = vHys/Vps."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.InvertingSchmittTrigger"
    msl_known_failure = (
        'a limiter in positive feedback without dynamics: the algebraic branch ends in a '
        'fold (no_event) and the corrector cannot jump')
    opAmp = IdealizedOpAmpLimited(Vps=Vps, Vns=Vns, out={"i": {"start": 0.0}})
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    r1 = Resistor(R=1000.0)
    r2 = Resistor(R=(1 - 1 / Vps) / (1 / Vps) * 1000.0)

    def equations(self):
        c = ac.connect
        return [c(self.r2.n, self.r1.p), c(self.ground.p, self.r1.n),
                c(self.opAmp.out, self.r2.p), c(self.r2.n, self.opAmp.in_p),
                c(self.vIn.p, self.opAmp.in_n), c(self.ground.p, self.vIn.n),
                c(self.ground.p, self.vOut.n), c(self.opAmp.out, self.vOut.p)]


class SchmittTrigger(_Example):
    """Schmitt trigger (OpAmps.SchmittTrigger), hysteresis 1 V: R2 = R1/k, k = vHys/Vps."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.SchmittTrigger"
    msl_known_failure = (
        'a limiter in positive feedback without dynamics: the algebraic branch ends in a '
        'fold (no_event) and the corrector cannot jump')
    opAmp = IdealizedOpAmpLimited(Vps=Vps, Vns=Vns, out={"i": {"start": 0.0}})
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    r1 = Resistor(R=1000.0)
    r2 = Resistor(R=1000.0 / (1 / Vps))

    def equations(self):
        c = ac.connect
        return [c(self.ground.p, self.vIn.n), c(self.ground.p, self.vOut.n),
                c(self.opAmp.out, self.vOut.p), c(self.opAmp.in_n, self.ground.p),
                c(self.opAmp.out, self.r2.n), c(self.r2.p, self.opAmp.in_p),
                c(self.r2.p, self.r1.n), c(self.r1.p, self.vIn.p)]


class LCOscillator(ac.Component):
    """LC oscillator (OpAmps.LCOscillator): f = 1 kHz, amplification A = 1.001 (R2 =
    (A - 1) R1), the capacitor at 10 V at the start."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.LCOscillator"
    stop_time = 0.01
    tolerance = 1e-05
    L_ = 0.001
    A = 1.001
    C_ = 1 / ((2 * math.pi * 1000.0)**2 * L_)
    ground = Ground()
    opAmp = IdealizedOpAmpLimited()
    r = Resistor(R=10000.0)
    r2 = Resistor(R=(A - 1) * 10000.0, i={"start": 0.0})
    r1 = Resistor(R=10000.0)
    c = Capacitor(C=C_, v={"start": 10.0, "fixed": True})
    l = Inductor(L=L_, i={"fixed": True, "start": 0.0})
    vOut = VoltageSensor()

    def equations(self):
        c = ac.connect
        return [c(self.opAmp.out, self.r.p), c(self.opAmp.out, self.r2.p),
                c(self.r2.n, self.r1.p), c(self.r2.n, self.opAmp.in_n),
                c(self.r1.n, self.ground.p), c(self.r.n, self.opAmp.in_p),
                c(self.l.n, self.ground.p), c(self.r.n, self.l.p), c(self.c.p, self.l.p),
                c(self.c.n, self.l.n), c(self.ground.p, self.vOut.n), c(self.r.n, self.vOut.p)]


class Multivibrator(_Example):
    """Multivibrator with a Schmitt trigger (OpAmps.Multivibrator): f = 10 Hz, C =
    1/f/(2 R log(1 + 2 R1/R2)); the op-amp's initial guess its lower limit (the MSL's
    homotopyType LowerLimit)."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.Multivibrator"
    msl_known_failure = (
        'a limiter in positive feedback without dynamics: the algebraic branch ends in a '
        'fold (no_event) and the corrector cannot jump')
    opAmp = IdealizedOpAmpLimited(Vps=Vps, Vns=Vns, homotopyType="LowerLimit", strict=True)
    ground = Ground()
    vOut = VoltageSensor()
    r1 = Resistor(R=1000.0, i={"start": 0.0})
    r2 = Resistor(R=1000.0)
    r = Resistor(R=1000.0)
    c = Capacitor(C=1 / f / (2 * 1000.0 * math.log(1 + 2 * 1000.0 / 1000.0)),
                  v={"start": 1.0, "fixed": True})

    def equations(self):
        c = ac.connect
        return [c(self.ground.p, self.r1.n), c(self.ground.p, self.vOut.n),
                c(self.opAmp.out, self.vOut.p), c(self.ground.p, self.c.n),
                c(self.opAmp.out, self.r.p), c(self.r.n, self.opAmp.in_n),
                c(self.opAmp.out, self.r2.p), c(self.r2.n, self.opAmp.in_p),
                c(self.opAmp.in_p, self.r1.p), c(self.r.n, self.c.p)]


class SignalGenerator(_Example):
    """Rectangle-triangle generator (OpAmps.SignalGenerator): a Schmitt trigger and an
    integrator, amplitude 10 V at 10 Hz."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.SignalGenerator"
    msl_known_failure = (
        'three consistent initial states (+-15 V, 0): acausal starts on the unstable 0, '
        'the reference on -15 V')
    VAmp = 10.0
    R2_ = 1000.0 * Vps / VAmp
    opAmp1 = IdealizedOpAmpLimited(Vps=Vps, Vns=-Vps, strict=False,
                                   homotopyType="UpperLimit")
    r2 = Resistor(R=R2_, i={"start": Vps / R2_})
    r1 = Resistor(R=1000.0)
    ground = Ground()
    opAmp2 = IdealizedOpAmpLimited(Vps=Vps, Vns=-Vps, v_in={"start": 0.0}, strict=False)
    c = Capacitor(C=Vps / VAmp / (4 * f * 1000.0), v={"fixed": True, "start": 0.0})
    r = Resistor(R=1000.0)
    vOutRectangle = VoltageSensor()
    vOutTriangle = VoltageSensor()

    def equations(self):
        c = ac.connect
        return [c(self.opAmp1.out, self.r2.n), c(self.opAmp1.in_p, self.r2.p),
                c(self.opAmp1.in_n, self.ground.p), c(self.opAmp1.out, self.r.p),
                c(self.r.n, self.c.n), c(self.c.p, self.opAmp2.out),
                c(self.ground.p, self.opAmp2.in_p), c(self.c.n, self.opAmp2.in_n),
                c(self.r2.p, self.r1.p), c(self.opAmp2.out, self.r1.n),
                c(self.opAmp1.out, self.vOutRectangle.p),
                c(self.ground.p, self.vOutRectangle.n),
                c(self.opAmp2.out, self.vOutTriangle.p), c(self.ground.p, self.vOutTriangle.n)]


class VoltageFollower(_Example):
    """Voltage follower (OpAmps.VoltageFollower): the input through Ri = 1 Ohm, the
    output loaded by Rl = 1 Ohm."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.VoltageFollower"
    opAmp = IdealizedOpAmpLimited(Vps=Vps, Vns=Vns, v_in={"start": 0.0})
    ground = Ground()
    vIn = _trapezoid()
    vOut = VoltageSensor()
    ri = Resistor(R=1.0)
    rl = Resistor(R=1.0)

    def equations(self):
        c = ac.connect
        return [c(self.ground.p, self.vIn.n), c(self.opAmp.out, self.vOut.p),
                c(self.ground.p, self.vOut.n), c(self.opAmp.out, self.opAmp.in_n),
                c(self.vIn.p, self.ri.p), c(self.ri.n, self.opAmp.in_p),
                c(self.opAmp.out, self.rl.p), c(self.ground.p, self.rl.n)]
