"""Sampled blocks with a fixed sample period (Modelica.Blocks.Discrete).

Every block samples its input at the ticks of ``ac.sample(startTime, samplePeriod)``,
``t_k = startTime + k samplePeriod`` (k = 0, 1, ...), and holds its output, a discrete
variable, until the next tick.  A tick at the start of the run fires once the initial
values are found (the MSL writes ``when {sampleTrigger, initial()}``).  Blocks of the
same period that feed each other fire at the same instant in data-flow order: a hold
behind a sampler outputs the sample of this tick, not the last one.

The MSL's ZeroOrderHold adds an infinitesimal delay (``y = pre(ySample)``) so that a
direct feedthrough from its output back to its input through continuous blocks is not
an algebraic loop; here the same loop is reported at compile time as a loop of
when-clauses, and the hold is the sampler's equation.  Its output is continuous-time
in the MSL's sense: a signal constant between ticks that any block may read.
"""
import acausal as ac
from acausal.ports import RealInput, RealOutput

from .nonlinear import clip

__all__ = ["DiscreteSISO", "Sampler", "ZeroOrderHold", "UnitDelay", "TransferFunction",
           "PI", "PID"]


class DiscreteSISO(ac.Component):
    """Input u sampled at t_k = startTime + k samplePeriod; discrete output y, held
    between ticks (Modelica.Blocks.Interfaces.DiscreteSISO)."""

    u = RealInput()
    y = RealOutput(signal={"discrete": True, "start": 0.0})
    samplePeriod = ac.Parameter(0.1, unit="s", min=0, description="sample period")
    startTime = ac.Parameter(0.0, unit="s", description="first sample instant")

    def ticks(self):
        """The clock of the block."""
        return ac.sample(self.startTime, self.samplePeriod)


class Sampler(DiscreteSISO):
    """Ideal sampler:  y = u(t_k) on [t_k, t_k+1)   (Modelica.Blocks.Discrete.Sampler)."""

    def equations(self):
        return [ac.when(self.ticks(), ac.assign(self.y, self.u))]


class ZeroOrderHold(DiscreteSISO):
    """Zero-order hold:  y(t) = u(t_k) for t_k <= t < t_k+1
    (Modelica.Blocks.Discrete.ZeroOrderHold; see the module docstring for its delay)."""

    def equations(self):
        return [ac.when(self.ticks(), ac.assign(self.y, self.u))]


class _Cell(ac.Component):
    """One held value of a discrete block's state."""

    x = ac.Variable(discrete=True, start=0.0, description="held state")


class UnitDelay(DiscreteSISO):
    """y = z^-1 u:  y(t_k) = u(t_k-1), and y_start before the second tick
    (Modelica.Blocks.Discrete.UnitDelay).  The block keeps its own sample u_s of the
    input, so the delay holds whatever drives it:

        y := pre(u_s),   u_s := u     at every tick t_k,   u_s = y = y_start before t_0

    ``y_start`` is a start value, a number fixed when the block is created.
    """

    u_s = ac.Variable(discrete=True, start=0.0, description="input sampled at the last tick")

    def __init__(self, y_start=0.0, **mods):
        mods.setdefault("u_s", y_start)
        mods.setdefault("y", {"signal": {"discrete": True, "start": y_start}})
        super().__init__(**mods)

    def equations(self):
        return [ac.when(self.ticks(), ac.assign(self.y, ac.pre(self.u_s)),
                        ac.assign(self.u_s, self.u))]


class TransferFunction(DiscreteSISO):
    """y = b(z^-1)/a(z^-1) u with b = [b0, b1, ...], a = [a0, a1, ...] (coefficients of
    z^0, z^-1, ...; the shorter list padded with zeros), that is

        a0 y_k + a1 y_k-1 + ... = b0 u_k + b1 u_k-1 + ...

    realized in transposed direct form II (Oppenheim & Schafer, Discrete-Time Signal
    Processing, 3rd ed., sec. 6.5), with a0 divided out and states x_1..x_n:

        y := b0 u + pre(x_1),   x_i := b_i u + pre(x_i+1) - a_i y   (x_n+1 = 0)

    at every tick (x_i reads the new y: the clauses run in data-flow order).  ``b`` and
    ``a`` are structural (they set the number of states), plain numbers fixed when the
    block is created, as in the continuous ``TransferFunction``; the states start at 0.

    Examples
    --------
    >>> tf = TransferFunction(b=[0.5, 0.5], a=[1.0, -0.5])   # (0.5 + 0.5 z^-1)/(1 - 0.5 z^-1)
    >>> len(tf.state)
    1
    """

    def __init__(self, b=(1.0,), a=(1.0,), **mods):
        super().__init__(**mods)
        b, a = [float(c) for c in b], [float(c) for c in a]
        if not a or a[0] == 0:
            raise ac.ModelError("discrete TransferFunction: a[0] (the coefficient of z^0 "
                                "in the denominator) must not be 0")
        n = max(len(a), len(b)) - 1
        self.a = [c / a[0] for c in a] + [0.0] * (n + 1 - len(a))
        self.b = [c / a[0] for c in b] + [0.0] * (n + 1 - len(b))
        self.state = [_Cell() for _ in range(n)]

    def equations(self):
        x = [cell.x for cell in self.state] + [0]
        u, y = self.u.signal, self.y.signal
        acts = [ac.assign(self.y, self.b[0] * u + (ac.pre(x[0]) if self.state else 0))]
        for i, cell in enumerate(self.state, start=1):
            nxt = ac.pre(x[i]) if i < len(self.state) else 0
            acts.append(ac.assign(cell.x, self.b[i] * u + nxt - self.a[i] * y))
        return [ac.when(self.ticks(), *acts)]


class PI(DiscreteSISO):
    """Discrete PI controller with output limits and back-calculation anti-windup (the
    integral tracks the limited output with tracking time Tt), the computer
    implementation of Åström & Murray, Feedback Systems (2008), ch. 10 "PID Control"
    (sections on integrator windup and implementation; also Åström & Hägglund, PID
    Controllers, 1995): a forward-difference integral, h = samplePeriod, u the control
    error:

        v := k u + pre(I)                              unlimited output
        y := clip(v, yMin, yMax)
        I := pre(I) + (k h / Ti) u + (h / Tt) (y - v)   integral, in output units

    While the output is limited, I tracks the limit (y - v pulls it back with the
    tracking gain h/Tt, 0 < h/Tt <= 1) instead of winding up.
    """

    k = ac.Parameter(1.0, description="proportional gain")
    Ti = ac.Parameter(1.0, unit="s", min=0, description="integral time")
    Tt = ac.Parameter(lambda c: c.Ti, unit="s", min=0,
                      description="anti-windup tracking time (default Ti)")
    yMax = ac.Parameter(float("inf"), description="upper output limit")
    yMin = ac.Parameter(float("-inf"), description="lower output limit")
    v = ac.Variable(discrete=True, start=0.0, description="unlimited output")
    I = ac.Variable(discrete=True, start=0.0, description="integral part, in output units")

    def _derivative(self):
        return []

    def _unlimited(self):
        return self.k * self.u + ac.pre(self.I)

    def equations(self):
        h = self.samplePeriod
        return [ac.when(self.ticks(), *self._derivative(),
                        ac.assign(self.v, self._unlimited()),
                        ac.assign(self.y, clip(self.v, self.yMax, self.yMin)),
                        ac.assign(self.I, ac.pre(self.I) + self.k * h / self.Ti * self.u
                                  + h / self.Tt * (self.y - self.v)))]


class PID(PI):
    """Discrete PID controller: the PI above plus a derivative part filtered with N,
    by backward differences (the same implementation, Åström & Murray 2008, ch. 10):

        D := Td/(Td + N h) pre(D) + k Td N/(Td + N h) (u - pre(u_s)),   u_s := u
        v := k u + pre(I) + D

    so that, unlimited, it approximates k (1 + 1/(Ti s) + Td s/(1 + Td s/N)).
    """

    Td = ac.Parameter(0.1, unit="s", min=0, description="derivative time")
    Nd = ac.Parameter(10.0, min=0, description="derivative filter: high-frequency gain")
    D = ac.Variable(discrete=True, start=0.0, description="derivative part")
    u_s = ac.Variable(discrete=True, start=0.0, description="input at the last tick")

    def _derivative(self):
        h, Td, N = self.samplePeriod, self.Td, self.Nd
        ad = Td / (Td + N * h)
        return [ac.assign(self.D, ad * ac.pre(self.D)
                          + self.k * N * ad * (self.u - ac.pre(self.u_s))),
                ac.assign(self.u_s, self.u)]

    def _unlimited(self):
        return self.k * self.u + ac.pre(self.I) + self.D
