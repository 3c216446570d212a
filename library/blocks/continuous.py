"""Linear dynamic blocks and controllers (Modelica.Blocks.Continuous).

Every block with dynamics keeps its state in a variable ``x`` (a list of cells for
``TransferFunction``).  ``initType`` chooses how it starts, as in the MSL
(``ac.Init``): ``"NoInit"`` (the default here: the state's start value, 0 unless given,
``FirstOrder(x=1.0)``, where the model does not fix it otherwise), ``"SteadyState"``
(der(x) = 0), ``"InitialState"`` (x = x_start, or y_start where the state is the
output) or ``"InitialOutput"`` (y = y_start).  The MSL's Integrator defaults to
InitialState with y_start = 0, which NoInit gives wherever nothing else fixes its state.
"""

import acausal as ac

from .interfaces import SISO
from .nonlinear import clip

__all__ = ["Integrator", "Der", "Derivative", "FirstOrder", "SecondOrder", "TransferFunction",
           "PI", "PID"]


class Integrator(SISO):
    """y = x,  der(x) = k u."""

    k = ac.Parameter(1.0, description="integrator gain")
    x = ac.Variable(start=0.0, description="state (the integral)")
    initType = ac.Init.parameter()
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialState, "
                                            "InitialOutput)")

    def initial_equations(self):
        return ac.Init.equations(self.initType, [self.x], [self.y_start], self.y,
                                 self.y_start)

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.k * self.u), ac.Eq(self.y, self.x)]


class Der(SISO):
    """The derivative of the input (MSL Blocks.Continuous.Der):  y = der(u).

    Index reduction differentiates whatever computes u: u must be differentiable (a
    filtered signal, not a step)."""

    def equations(self):
        return [ac.Eq(self.y, ac.der(self.u.signal))]


class Derivative(SISO):
    """Filtered derivative  y = k s / (T s + 1) u:

        T der(x) = u - x,   y = (k / T) (u - x)
    """

    k = ac.Parameter(1.0, description="gain")
    T = ac.Parameter(0.01, unit="s", min=0, description="filter time constant")
    x = ac.Variable(start=0.0, description="filter state")
    initType = ac.Init.parameter()
    x_start = ac.Parameter(0.0, description="initial value of the state (InitialState)")
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialOutput)")

    def initial_equations(self):
        return ac.Init.equations(self.initType, [self.x], [self.x_start], self.y,
                                 self.y_start, free_at_output=[])

    def equations(self):
        return [ac.Eq(self.T * ac.der(self.x), self.u - self.x),
                ac.Eq(self.y, self.k / self.T * (self.u - self.x))]


class FirstOrder(SISO):
    """First-order lag  y = k / (T s + 1) u:   T der(x) = k u - x,  y = x."""

    k = ac.Parameter(1.0, description="gain")
    T = ac.Parameter(1.0, unit="s", description="time constant")
    x = ac.Variable(start=0.0, description="state (the output)")
    initType = ac.Init.parameter()
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialState, "
                                            "InitialOutput)")

    def initial_equations(self):
        return ac.Init.equations(self.initType, [self.x], [self.y_start], self.y,
                                 self.y_start)

    def equations(self):
        return [ac.Eq(self.T * ac.der(self.x), self.k * self.u - self.x), ac.Eq(self.y, self.x)]


class SecondOrder(SISO):
    """Second-order system  y = k w^2 / (s^2 + 2 D w s + w^2) u:

        der(x) = xd,   der(xd) = w^2 (k u - x) - 2 D w xd,   y = x
    """

    k = ac.Parameter(1.0, description="gain")
    w = ac.Parameter(1.0, unit="rad/s", description="natural frequency")
    D = ac.Parameter(1.0, description="damping ratio")
    x = ac.Variable(start=0.0, description="state (the output)")
    xd = ac.Variable(start=0.0, description="state (der of the output)")
    initType = ac.Init.parameter()
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialState, "
                                            "InitialOutput)")
    yd_start = ac.Parameter(0.0, description="initial value of der(y) (InitialState)")

    def initial_equations(self):
        # InitialOutput: y = y_start and der(y) = 0, the MSL's
        return ac.Init.equations(self.initType, [self.x, self.xd],
                                 [self.y_start, self.yd_start], self.y, self.y_start,
                                 free_at_output=[self.x])

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.xd),
                ac.Eq(ac.der(self.xd), self.w**2 * (self.k * self.u - self.x)
                      - 2 * self.D * self.w * self.xd),
                ac.Eq(self.y, self.x)]


class _State(ac.Component):
    """One state of a TransferFunction (a cell of its state vector)."""

    x = ac.Variable(start=0.0, description="state")


class TransferFunction(SISO):
    """y = b(s)/a(s) u, coefficients highest power first (MSL
    Blocks.Continuous.TransferFunction), in controllable canonical form.  With a = a0 s^n
    + ... + an (divided through by a0 to alpha_k = a_k/a0) and b padded to n + 1
    coefficients beta_j (also divided by a0):

        der(x[i]) = x[i+1]  (i < n),   der(x[n]) = u - sum_k alpha_k x[n-k+1],
        y = beta_0 der(x[n]) + sum_{j>=1} beta_j x[n-j+1]

    ``b`` and ``a`` are structural parameters (they set the number of states): plain
    numbers fixed when the block is made; ``build`` creates the states.

    Examples
    --------
    >>> tf = TransferFunction(b=[1.0], a=[0.5, 1.0])   # 1 / (0.5 s + 1)
    >>> len(tf.state)
    1
    """

    b = ac.Parameter((1.0,), structural=True,
                     description="numerator coefficients, highest power of s first")
    a = ac.Parameter((1.0, 1.0), structural=True,
                     description="denominator coefficients, highest power of s first")
    initType = ac.Init.parameter()
    x_start = ac.Parameter((), structural=True,
                           description="initial states x[0] .. x[n-1] (InitialState; "
                                       "default zeros)")
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialOutput)")

    def initial_equations(self):
        """InitialOutput: y = y_start with der(x[1:]) = 0 (the MSL's der(x[1:nx-1]) = 0
        in its reversed order of the states)."""
        x = [cell.x for cell in self.state]
        x_start = [float(v) for v in self.x_start] or [0.0] * len(x)
        if len(x_start) != len(x):
            raise ac.InvalidValue(f"TransferFunction: x_start has {len(x_start)} values for "
                                  f"{len(x)} states")
        return ac.Init.equations(self.initType, x, x_start, self.y, self.y_start)

    def build(self):
        num, den = [float(c) for c in self.b], [float(c) for c in self.a]
        if not den or den[0] == 0:
            raise ac.ModelError("TransferFunction: the leading coefficient of a must not be 0")
        if len(num) > len(den):
            raise ac.ModelError("TransferFunction: b has a higher degree than a (improper)")
        n = len(den) - 1
        self.alpha = [c / den[0] for c in den[1:]]
        self.beta = [0.0] * (n + 1 - len(num)) + [c / den[0] for c in num]
        self.state = [_State() for _ in range(n)]

    def equations(self):
        x = [cell.x for cell in self.state]
        n = len(x)
        if n == 0:
            return [ac.Eq(self.y, self.beta[0] * self.u)]
        top = self.u.signal - sum(a * x[n - k] for k, a in enumerate(self.alpha, start=1))
        eqs = [ac.Eq(ac.der(x[i]), x[i + 1]) for i in range(n - 1)]
        eqs.append(ac.Eq(ac.der(x[-1]), top))
        y = self.beta[0] * top + sum(b * x[n - j] for j, b in enumerate(self.beta[1:], start=1))
        return eqs + [ac.Eq(self.y, y)]


class _LimitedController(SISO):
    """Output limits and back-calculation anti-windup shared by PI and PID.

    v is the unlimited controller output, y = clip(v, yMin, yMax); the integral state
    x_i (in output units) is driven by k/Ti u + (y - v)/Tt, so while the output is
    limited x_i tracks the limit with time constant Tt instead of winding up.
    """

    k = ac.Parameter(1.0, description="proportional gain")
    Ti = ac.Parameter(1.0, unit="s", min=0, description="integral time")
    yMax = ac.Parameter(float("inf"), description="upper output limit")
    yMin = ac.Parameter(float("-inf"), description="lower output limit")
    Tt = ac.Parameter(lambda c: c.Ti, unit="s", min=0,
                      description="anti-windup tracking time constant (default Ti)")
    v = ac.Variable(description="unlimited controller output")
    x_i = ac.Variable(start=0.0, description="integral state, in output units")
    initType = ac.Init.parameter()
    xi_start = ac.Parameter(0.0, description="initial integral state, in output units "
                                             "(InitialState)")
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialOutput)")

    def states(self) -> list:
        return [self.x_i]

    def initial_equations(self):
        starts = [self.xi_start] + [getattr(self, "xd_start", 0)] * (len(self.states()) - 1)
        return ac.Init.equations(self.initType, self.states(), starts, self.y, self.y_start)

    def equations(self):
        return [ac.Eq(self.y, clip(self.v, self.yMax, self.yMin)),
                ac.Eq(ac.der(self.x_i), self.k / self.Ti * self.u + (self.y - self.v) / self.Tt)]


class PI(_LimitedController):
    """PI controller  y = clip(k (1 + 1/(Ti s)) u, yMin, yMax), with anti-windup:

        v = k u + x_i,   der(x_i) = (k/Ti) u + (y - v)/Tt,   y = clip(v, yMin, yMax)
    """

    def equations(self):
        return [ac.Eq(self.v, self.k * self.u + self.x_i)]


class PID(_LimitedController):
    """PID controller with a filtered derivative, output limits and anti-windup:

        v = k u + x_i + k Nd (u - x_d),   (Td/Nd) der(x_d) = u - x_d,
        der(x_i) = (k/Ti) u + (y - v)/Tt,   y = clip(v, yMin, yMax)

    so that, unlimited, y = k (1 + 1/(Ti s) + Td s/(1 + Td s/Nd)) u.  ``Ti = inf``
    gives a PD controller.
    """

    Td = ac.Parameter(0.1, unit="s", min=0, description="derivative time")
    Nd = ac.Parameter(10.0, min=0, description="derivative filter: high-frequency gain")
    x_d = ac.Variable(start=0.0, description="derivative filter state")
    xd_start = ac.Parameter(0.0, description="initial derivative filter state "
                                             "(InitialState)")

    def states(self) -> list:
        return [self.x_i, self.x_d]

    def equations(self):
        d = self.k * self.Nd * (self.u - self.x_d)
        return [ac.Eq(self.v, self.k * self.u + self.x_i + d),
                ac.Eq(self.Td / self.Nd * ac.der(self.x_d), self.u - self.x_d)]
