"""Signal sources (Modelica.Blocks.Sources)."""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput, RealOutput

from . import signals
from .interfaces import SO, SignalSource

__all__ = ["Constant", "Step", "Ramp", "Sine", "Cosine", "ExpSine", "Pulse", "Trapezoid",
           "Sinc", "SineVariableFrequencyAndAmplitude", "CosineVariableFrequencyAndAmplitude",
           "KinematicPTP"]


class Constant(SO):
    """Constant output:  y = k."""

    k = ac.Parameter(1.0, description="constant output value")

    def equations(self):
        return [ac.Eq(self.y, self.k)]


class Step(SignalSource):
    """Step:  y = offset + (height if time >= startTime else 0)."""

    height = ac.Parameter(1.0, description="height of the step")

    def equations(self):
        return [ac.Eq(self.y, self.offset + signals.step(self.height, self.startTime))]


class Ramp(SignalSource):
    """Ramp from offset to offset + height between startTime and startTime + duration."""

    height = ac.Parameter(1.0, description="height of the ramp")
    duration = ac.Parameter(1.0, unit="s", min=0, description="duration of the ramp")

    def equations(self):
        r = signals.ramp(self.height, self.duration, self.startTime)
        return [ac.Eq(self.y, self.offset + r)]


class Sine(SignalSource):
    """Sine:  y = offset + amplitude sin(2 pi f (time - startTime) + phase) after startTime."""

    amplitude = ac.Parameter(1.0, description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")

    def equations(self):
        s = signals.sine(self.amplitude, self.f, self.phase, self.startTime)
        return [ac.Eq(self.y, self.offset + s)]


class Cosine(SignalSource):
    """Cosine:  y = offset + amplitude cos(2 pi f (time - startTime) + phase) after
    startTime (the MSL's Cosine: a Sine with a quarter period more phase)."""

    amplitude = ac.Parameter(1.0, description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")

    def equations(self):
        s = signals.sine(self.amplitude, self.f, self.phase + sp.pi / 2, self.startTime)
        return [ac.Eq(self.y, self.offset + s)]


class ExpSine(SignalSource):
    """Exponentially damped sine (MSL ExpSine), after startTime:

        y = offset + amplitude exp(-damping (time - startTime))
                     sin(2 pi f (time - startTime) + phase)
    """

    amplitude = ac.Parameter(1.0, description="amplitude at startTime")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")
    damping = ac.Parameter(1.0, unit="1/s", description="damping coefficient")

    def equations(self):
        tau = ac.time - self.startTime
        wave = (self.amplitude * ac.exp(-self.damping * tau)
                * ac.sin(2 * sp.pi * self.f * tau + self.phase))
        # gated as a whole: exp(-damping tau) before startTime may overflow
        return [ac.Eq(self.y, self.offset + ac.if_else(tau >= 0, wave, 0))]


class Pulse(SignalSource):
    """Rectangular pulse train (Modelica.Blocks.Sources.Pulse, MSL v4.0.0):
    y = offset + amplitude during the first ``width`` percent of each ``period`` after
    startTime, y = offset otherwise.

    The edges are zero crossings; simulate with ``max_step`` below the pulse width, or
    a long step can jump over a whole pulse.
    """

    amplitude = ac.Parameter(1.0, description="pulse height")
    width = ac.Parameter(50.0, min=0, max=100, description="width of the pulse in % of period")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def equations(self):
        p = signals.pulse(self.amplitude, self.width / 100, self.period, self.startTime)
        return [ac.Eq(self.y, self.offset + p)]


class Trapezoid(SignalSource):
    """Periodic trapezoid (MSL Blocks.Sources.Trapezoid, endless):  y = offset +
    amplitude times a rise over ``rising``, ``width`` at the top and a fall over
    ``falling`` in every ``period`` after startTime (see ``signals.trapezoid``)."""

    amplitude = ac.Parameter(1.0, description="height of the trapezoid")
    rising = ac.Parameter(0.1, unit="s", min=0, description="rise time (> 0)")
    width = ac.Parameter(0.5, unit="s", min=0, description="time at the top")
    falling = ac.Parameter(0.1, unit="s", min=0, description="fall time (> 0)")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def equations(self):
        for name in ("rising", "falling", "period"):
            if self.parameter_value(name) == 0:
                # a zero would divide the edge's slope by a structural zero
                raise ac.ModelError(f"{self._describe()}: {name} must be > 0 (a Pulse "
                                    "has vertical edges)")
        y = signals.trapezoid(self.amplitude, self.rising, self.width, self.falling,
                              self.period, self.startTime)
        return [ac.Eq(self.y, self.offset + y)]


class Sinc(SignalSource):
    """Sinc signal (MSL Blocks.Sources.Sinc):

        y = offset + amplitude sin(x)/x after startTime (amplitude at x = 0), offset
        before,   x = 2 pi f (time - startTime)
    """

    amplitude = ac.Parameter(1.0, description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")

    def equations(self):
        tau = ac.time - self.startTime
        x = 2 * sp.pi * self.f * tau
        wave = ac.no_event(ac.if_else(tau < 1e-15, 1, ac.sin(x) / x))
        return [ac.Eq(self.y, self.offset + ac.if_else(tau < 0, 0, self.amplitude * wave))]


class _VariableFrequencyAndAmplitude(SO):
    """A wave whose phase integrates the frequency: der(phi) = 2 pi f; the amplitude and
    the frequency are input signals, or constants when the block is made with
    ``useConstantAmplitude=True`` / ``useConstantFrequency=True`` (then it has no such
    input, and ``constantAmplitude`` / ``constantFrequency`` hold them)."""

    constantAmplitude = ac.Parameter(1.0, description="the amplitude, if constant")
    constantFrequency = ac.Parameter(1.0, unit="Hz", description="the frequency, if constant")
    offset = ac.Parameter(0.0, description="offset of the wave")
    phi = ac.Variable(start=0.0, unit="rad", description="phase of the wave")

    def __init__(self, *, useConstantAmplitude: bool = False,
                 useConstantFrequency: bool = False, **modifications):
        self.useConstantAmplitude = bool(useConstantAmplitude)
        self.useConstantFrequency = bool(useConstantFrequency)
        super().__init__(**modifications)

    def build(self):
        if not self.useConstantAmplitude:
            self.amplitude = RealInput()
        if not self.useConstantFrequency:
            self.f = RealInput()

    def inputs(self):
        """The amplitude and the frequency, as expressions."""
        a = self.constantAmplitude if self.useConstantAmplitude else self.amplitude.signal
        f = self.constantFrequency if self.useConstantFrequency else self.f.signal
        return a, f


class SineVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    """Sine with variable frequency and amplitude (MSL
    Blocks.Sources.SineVariableFrequencyAndAmplitude):

        der(phi) = 2 pi f,   y = offset + amplitude sin(phi)
    """

    def equations(self):
        a, f = self.inputs()
        return [ac.Eq(ac.der(self.phi), 2 * sp.pi * f),
                ac.Eq(self.y, self.offset + a * ac.sin(self.phi))]


class CosineVariableFrequencyAndAmplitude(_VariableFrequencyAndAmplitude):
    """Cosine with variable frequency and amplitude (MSL
    Blocks.Sources.CosineVariableFrequencyAndAmplitude):

        der(phi) = 2 pi f,   y = offset + amplitude cos(phi)
    """

    def equations(self):
        a, f = self.inputs()
        return [ac.Eq(ac.der(self.phi), 2 * sp.pi * f),
                ac.Eq(self.y, self.offset + a * ac.cos(self.phi))]


class KinematicPTP(ac.Component):
    """The fastest move of each axis over deltaq within the speed and acceleration
    limits qd_max and qdd_max, synchronized on a path s from 0 to 1 (MSL
    Blocks.Sources.KinematicPTP; its output is the acceleration):

        sd_max = 1/max|deltaq/qd_max|,   sdd_max = 1/max|deltaq/qdd_max|,
        Ta1 = sqrt(1/sdd_max),   Ta2 = sd_max/sdd_max,   noWphase = Ta2 >= Ta1,
        Tv = Ta1 if noWphase else 1/sd_max,   Te = 2 Ta1 if noWphase else Tv + Ta2,
        sdd = +sdd_max, (0,) -sdd_max over the phases after startTime,   y = deltaq sdd

    ``deltaq``, ``qd_max`` and ``qdd_max`` (lists, one element per axis or one for all)
    are given when it is made; they set the times of the phases, which are time events.
    Outputs y[0 .. nout-1].
    """

    deltaq = ac.Parameter((1.0,), structural=True, description="distance to move")
    qd_max = ac.Parameter((1.0,), structural=True, description="maximum speeds der(q) (> 0)")
    qdd_max = ac.Parameter((1.0,), structural=True,
                           description="maximum accelerations der(qd) (> 0)")
    startTime = ac.Parameter(0.0, unit="s", description="time the movement starts")

    def build(self):
        lists = [list(self.deltaq), list(self.qd_max), list(self.qdd_max)]
        nout = max(len(v) for v in lists)
        for v in lists:
            if len(v) not in (1, nout):
                raise ac.InvalidValue("KinematicPTP: deltaq, qd_max and qdd_max have one "
                                      "element per axis, or one for all")
        if min(min(lists[1]), min(lists[2])) <= 0:
            raise ac.InvalidValue("KinematicPTP: qd_max and qdd_max must be positive")
        dq, qd, qdd = (v * nout if len(v) == 1 else v for v in lists)
        self.p_deltaq = dq
        sd_max = 1 / max(abs(a / b) for a, b in zip(dq, qd))
        sdd_max = 1 / max(abs(a / b) for a, b in zip(dq, qdd))
        Ta1, Ta2 = (1 / sdd_max)**0.5, sd_max / sdd_max
        noWphase = Ta2 >= Ta1
        Tv = Ta1 if noWphase else 1 / sd_max
        Te = Ta1 + Ta1 if noWphase else Tv + Ta2
        # (end of the phase, path acceleration in it)
        self.phases = ([(Ta1, sdd_max), (Te, -sdd_max)] if noWphase
                       else [(Ta2, sdd_max), (Tv, 0.0), (Te, -sdd_max)])
        self.y = [RealOutput() for _ in range(nout)]

    def equations(self):
        t = ac.time - self.startTime
        sdd = 0
        for end, value in reversed(self.phases):
            sdd = ac.if_else(t < end, value, sdd)
        sdd = ac.if_else(t < 0, 0, sdd)
        return [ac.Eq(y.signal, d * sdd) for y, d in zip(self.y, self.p_deltaq)]
