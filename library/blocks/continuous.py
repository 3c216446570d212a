"""Linear dynamic blocks (Modelica.Blocks.Continuous, MSL v4.0.0).

As in the MSL, the state of ``Integrator``, ``FirstOrder``, ``SecondOrder`` (with its
``yd``) and ``SlewRateLimiter`` is the output ``y`` itself; ``Derivative`` and ``PI`` keep
a state ``x``, ``TransferFunction`` the cells ``state[i].x``.  ``initType`` chooses how
a block starts (``ac.Init``): ``"NoInit"`` (the state's start value, where the model does
not fix it otherwise), ``"SteadyState"`` (der(state) = 0), ``"InitialState"`` (state =
its start parameter) or ``"InitialOutput"`` (y = y_start); the defaults are the MSL's
(Integrator and PID: InitialState, the others NoInit).  ``y_start`` given as a number
where the block is made is also the output's start value (the MSL's ``y(start =
y_start)``), the value a NoInit state starts from; ``FirstOrder(y=1.0)`` sets that start
alone.
"""

import acausal as ac
from acausal.ports import BooleanInput, RealInput

from .interfaces import SISO, start_from
from .math import Add3, Gain

__all__ = ["Integrator", "Der", "Derivative", "FirstOrder", "SecondOrder", "TransferFunction",
           "PI", "PID"]


class Integrator(SISO):
    """Output the integral of the input (MSL Blocks.Continuous.Integrator):

        der(y) = k u,   when reset: reinit(y, set)  (use_reset; set = y_start
        without use_set)

    Starts at y = y_start (initType InitialState, the MSL's default; InitialOutput the
    same), in steady state der(y) = 0, or from y's start value (NoInit).
    """

    k = ac.Parameter(1.0, unit="1", description="integrator gain")
    use_reset = ac.Parameter(False, structural=True, description="enable the reset port")
    use_set = ac.Parameter(False, structural=True,
                           description="enable the set port, the value at a reset")
    initType = ac.Init.parameter("InitialState")
    y_start = ac.Parameter(0.0, description="initial or guess value of output (= state)")
    reset = ac.Conditional(BooleanInput(), "use_reset")
    set = ac.Conditional(RealInput(), "use_set")

    def __init__(self, **modifications):
        super().__init__(**start_from(modifications, "y_start"))

    def build(self):
        if self.use_set and not self.use_reset:
            raise ac.InvalidValue("Integrator: use_set = True needs use_reset = True (the "
                                  "set value is taken at a reset)")

    def initial_equations(self):
        init = "InitialState" if self.initType == "InitialOutput" else self.initType
        return ac.Init.equations(init, [self.y.signal], [self.y_start])

    def equations(self):
        eqs = [ac.Eq(ac.der(self.y.signal), self.k * self.u)]
        if self.use_reset:
            value = self.set.signal if self.use_set else self.y_start
            eqs.append(ac.when(self.reset, ac.reinit(self.y.signal, value)))
        return eqs


class Der(SISO):
    """The derivative of the input (MSL Blocks.Continuous.Der):  y = der(u).

    Index reduction differentiates whatever computes u: u must be differentiable (a
    filtered signal, not a step)."""

    def equations(self):
        return [ac.Eq(self.y, ac.der(self.u.signal))]


class Derivative(SISO):
    """Approximated derivative  y = k s / (T s + 1) u (MSL Blocks.Continuous.Derivative):

        der(x) = (u - x)/T,   y = (k/T) (u - x)
    """

    k = ac.Parameter(1.0, unit="1", description="gain")
    T = ac.Parameter(0.01, unit="s", min=0, description="time constant (T > 0 required)")
    x = ac.Variable(start=0.0, description="state of block")
    initType = ac.Init.parameter()
    x_start = ac.Parameter(0.0, description="initial or guess value of state")
    y_start = ac.Parameter(0.0, description="initial value of output (InitialOutput)")

    def initial_equations(self):
        return ac.Init.equations(self.initType, [self.x], [self.x_start], self.y,
                                 self.y_start, free_at_output=[])

    def equations(self):
        return [ac.Eq(ac.der(self.x), (self.u - self.x) / self.T),
                ac.Eq(self.y, self.k / self.T * (self.u - self.x))]


class FirstOrder(SISO):
    """First order transfer function  y = k / (T s + 1) u (MSL
    Blocks.Continuous.FirstOrder):

        der(y) = (k u - y)/T
    """

    k = ac.Parameter(1.0, unit="1", description="gain")
    T = ac.Parameter(1.0, unit="s", description="time constant")
    initType = ac.Init.parameter()
    y_start = ac.Parameter(0.0, description="initial or guess value of output (= state)")

    def __init__(self, **modifications):
        super().__init__(**start_from(modifications, "y_start"))

    def initial_equations(self):
        init = "InitialState" if self.initType == "InitialOutput" else self.initType
        return ac.Init.equations(init, [self.y.signal], [self.y_start])

    def equations(self):
        return [ac.Eq(ac.der(self.y.signal), (self.k * self.u - self.y) / self.T)]


class SecondOrder(SISO):
    """Second order transfer function  y = k w^2 / (s^2 + 2 D w s + w^2) u (MSL
    Blocks.Continuous.SecondOrder):

        der(y) = yd,   der(yd) = w (w (k u - y) - 2 D yd)

    InitialState and InitialOutput both start at y = y_start, yd = yd_start (the
    MSL's).
    """

    k = ac.Parameter(1.0, unit="1", description="gain")
    w = ac.Parameter(1.0, description="angular frequency")
    D = ac.Parameter(1.0, description="damping")
    initType = ac.Init.parameter()
    y_start = ac.Parameter(0.0, description="initial or guess value of output (= state)")
    yd_start = ac.Parameter(0.0, description="initial or guess value of derivative of "
                                             "output (= state)")
    yd = ac.Variable(start=0.0, description="derivative of y")

    def __init__(self, **modifications):
        modifications = start_from(modifications, "y_start")
        value = modifications.get("yd_start")
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            modifications.setdefault("yd", float(value))
        super().__init__(**modifications)

    def initial_equations(self):
        init = "InitialState" if self.initType == "InitialOutput" else self.initType
        return ac.Init.equations(init, [self.y.signal, self.yd],
                                 [self.y_start, self.yd_start])

    def equations(self):
        return [ac.Eq(ac.der(self.y.signal), self.yd),
                ac.Eq(ac.der(self.yd), self.w * (self.w * (self.k * self.u - self.y)
                                                 - 2 * self.D * self.yd))]


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


class PI(SISO):
    """Proportional-integral controller (MSL Blocks.Continuous.PI):

        der(x) = u/T,   y = k (x + u)

    so that y = k (1 + 1/(T s)) u.  Output limits and anti-windup: ``LimitedPI`` or
    the MSL's ``LimPID``.
    """

    k = ac.Parameter(1.0, unit="1", description="gain")
    T = ac.Parameter(1.0, unit="s", min=1e-60, description="time constant (T > 0 required)")
    initType = ac.Init.parameter()
    x_start = ac.Parameter(0.0, description="initial or guess value of state")
    y_start = ac.Parameter(0.0, description="initial value of output (InitialOutput)")
    x = ac.Variable(start=0.0, description="state of block")

    def __init__(self, **modifications):
        value = modifications.get("x_start")
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            modifications.setdefault("x", float(value))
        super().__init__(**modifications)

    def initial_equations(self):
        return ac.Init.equations(self.initType, [self.x], [self.x_start], self.y,
                                 self.y_start, free_at_output=[])

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.u / self.T),
                ac.Eq(self.y, self.k * (self.x + self.u))]


# the initialization of PID's integrator and derivative for the PID's initType (the
# MSL's table): InitialOutput holds y = y_start with the derivative in steady state
_I_INIT = {"NoInit": "NoInit", "SteadyState": "SteadyState", "InitialState": "InitialState",
           "InitialOutput": "NoInit"}
_D_INIT = {"NoInit": "NoInit", "SteadyState": "SteadyState", "InitialState": "InitialState",
           "InitialOutput": "SteadyState"}


class PID(SISO):
    """PID controller in additive description form (MSL Blocks.Continuous.PID), built
    as the MSL builds it, from its parts ``P``, ``I``, ``D``, ``Add`` and ``Gain``:

        y = k (u + I.y + D.y),   der(I.y) = u/Ti,
        D.y = Td s/(1 + (Td/Nd) s) u   (Derivative with k = Td, T = Td/Nd)

    i.e. y = k (1 + 1/(Ti s) + Td s/(1 + Td s/Nd)) u.  ``initType`` (default
    InitialState) sets the parts' initialization as the MSL's table: NoInit, SteadyState
    and InitialState for both, InitialOutput y = y_start with the integrator free and
    the derivative in steady state.  No limits: ``LimPID`` (the MSL's) or
    ``LimitedPID``.
    """

    k = ac.Parameter(1.0, unit="1", description="gain")
    Ti = ac.Parameter(0.5, unit="s", min=1e-60, description="time constant of integrator")
    Td = ac.Parameter(0.1, unit="s", min=0, description="time constant of derivative block")
    Nd = ac.Parameter(10.0, min=1e-60,
                      description="the higher Nd, the more ideal the derivative block")
    initType = ac.Init.parameter("InitialState")
    xi_start = ac.Parameter(0.0, description="initial or guess value for integrator output "
                                             "(= integrator state)")
    xd_start = ac.Parameter(0.0, description="initial or guess value for state of "
                                             "derivative block")
    y_start = ac.Parameter(0.0, description="initial value of output (InitialOutput)")
    unitTime = ac.Parameter(1.0, unit="s", description="1 s (the MSL's constant unitTime)")
    k_I = ac.Parameter(lambda c: c.unitTime / c.Ti, unit="1", description="unitTime/Ti")
    k_D = ac.Parameter(lambda c: c.Td / c.unitTime, unit="1", description="Td/unitTime")
    T_D = ac.Parameter(lambda c: c.Td / c.Nd, unit="s", description="Td/Nd")
    P = Gain(k=1.0)
    Add = Add3()
    Gain = Gain(k=ac.ref("k"))

    def build(self):
        self.I = Integrator(k=ac.ref("k_I"), y_start=ac.ref("xi_start"),
                            initType=_I_INIT[self.initType])
        self.D = Derivative(k=ac.ref("k_D"), T=ac.ref("T_D"), x_start=ac.ref("xd_start"),
                            initType=_D_INIT[self.initType])

    def initial_equations(self):
        return [ac.Eq(self.y, self.y_start)] if self.initType == "InitialOutput" else []

    def equations(self):
        c = ac.connect
        return [c(self.u, self.P.u), c(self.u, self.I.u), c(self.u, self.D.u),
                c(self.P.y, self.Add.u1), c(self.D.y, self.Add.u2), c(self.I.y, self.Add.u3),
                c(self.Add.y, self.Gain.u), c(self.Gain.y, self.y)]
