"""Controllers with limited output: the MSL's LimPID (Modelica.Blocks.Continuous.LimPID),
built from blocks as the MSL builds it, with the MSL's names for its parts (``PI.I.y`` is
the integrator's output, as in the MSL); and ``LimitedPI``, ``LimitedPID``: the textbook
controllers with output limits and back-calculation anti-windup (Astrom & Murray,
Feedback Systems, ch. 10), which the MSL does not have under those names."""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RealOutput

from .continuous import _D_INIT, _I_INIT, Derivative, Integrator
from .interfaces import SISO
from .math import Add, Add3, Gain
from .nonlinear import Limiter, clip
from .sources import Constant

__all__ = ["LimPID", "LimitedPI", "LimitedPID", "CONTROLLER_TYPES"]

CONTROLLER_TYPES = ("P", "PI", "PD", "PID")


class LimPID(ac.Component):
    """P, PI, PD or PID controller with limited output, anti-windup compensation,
    set-point weighting and optional feed-forward (MSL Blocks.Continuous.LimPID):

        addP = wp u_s - u_m,   addD = wd u_s - u_m,
        addI = u_s - u_m - (limiter.u - y)/(k Ni),   der(I.y) = addI / Ti,
        D = Td s/(1 + Td s/Nd) addD,
        limiter.u = k (addP + D.y + I.y) + kFF u_ff,   y = clip(limiter.u, yMin, yMax)

    ``controllerType`` ("PID" by default, "PI", "PD", "P") and ``withFeedForward`` are
    given when it is made; a part the type leaves out is not there (its Constant zero
    is, as in the MSL).  ``initType`` (default InitialState, the MSL's) initializes the
    integrator and the derivative block as the MSL's table: NoInit, SteadyState and
    InitialState for both (I.y = xi_start, D.x = xd_start), InitialOutput gainPID.y =
    y_start with the integrator free and the derivative in steady state.
    """

    k = ac.Parameter(1.0, min=0, description="gain of the controller")
    Ti = ac.Parameter(0.5, unit="s", min=0, description="time constant of the integrator")
    Td = ac.Parameter(0.1, unit="s", min=0, description="time constant of the derivative")
    yMax = ac.Parameter(1.0, description="upper limit of the output")
    yMin = ac.Parameter(lambda c: -c.yMax, description="lower limit of the output")
    wp = ac.Parameter(1.0, min=0, description="set-point weight of the proportional part")
    wd = ac.Parameter(0.0, min=0, description="set-point weight of the derivative part")
    Ni = ac.Parameter(0.9, min=0, description="Ni Ti is the anti-windup time constant")
    Nd = ac.Parameter(10.0, min=0, description="the higher Nd, the more ideal the derivative")
    kFF = ac.Parameter(1.0, description="gain of the feed-forward input")
    unitTime = ac.Parameter(1.0, unit="s", description="1 s (the MSL's constant unitTime)")
    k_I = ac.Parameter(lambda c: c.unitTime / c.Ti, description="unitTime/Ti")
    k_D = ac.Parameter(lambda c: c.Td / c.unitTime, description="Td/unitTime")
    T_D = ac.Parameter(lambda c: c.Td / c.Nd, unit="s", description="Td/Nd")
    k_track = ac.Parameter(lambda c: 1 / (c.k * c.Ni), description="1/(k Ni)")
    controllerType = ac.Parameter("PID", choices=CONTROLLER_TYPES,
                                  description="type of controller")
    withFeedForward = ac.Parameter(False, structural=True,
                                   description="use the feed-forward input u_ff")
    initType = ac.Init.parameter("InitialState")
    xi_start = ac.Parameter(0.0, description="initial or guess value for integrator output "
                                             "(= integrator state)")
    xd_start = ac.Parameter(0.0, description="initial or guess value for state of "
                                             "derivative block")
    y_start = ac.Parameter(0.0, description="initial value of output (InitialOutput)")
    controlError = ac.Variable(description="control error u_s - u_m")
    u_s = RealInput()
    u_m = RealInput()
    y = RealOutput()
    addP = Add(k1=ac.ref("wp"), k2=-1.0)
    P = Gain(k=1.0)
    gainPID = Gain(k=ac.ref("k"))
    addPID = Add3()
    limiter = Limiter(uMax=ac.ref("yMax"), uMin=ac.ref("yMin"))
    addFF = Add(k1=1.0, k2=ac.ref("kFF"))
    u_ff = ac.Conditional(RealInput(), "withFeedForward")
    FFzero = ac.Conditional(Constant(k=0.0), "withFeedForward", when=False)

    def build(self):
        self.with_I = self.controllerType in ("PI", "PID")
        self.with_D = self.controllerType in ("PD", "PID")
        if self.with_I:
            self.I = Integrator(k=ac.ref("k_I"), y_start=ac.ref("xi_start"),
                                initType=_I_INIT[self.initType])
            self.addI = Add3(k2=-1.0)
            self.addSat = Add(k1=1.0, k2=-1.0)
            self.gainTrack = Gain(k=ac.ref("k_track"))
        else:
            self.Izero = Constant(k=0.0)
        if self.with_D:
            self.addD = Add(k1=ac.ref("wd"), k2=-1.0)
            self.D = Derivative(k=ac.ref("k_D"), T=ac.ref("T_D"), x_start=ac.ref("xd_start"),
                                initType=_D_INIT[self.initType])
        else:
            self.Dzero = Constant(k=0.0)

    def initial_equations(self):
        if self.initType == "InitialOutput":
            return [ac.Eq(self.gainPID.y, self.y_start)]
        return []

    def equations(self):
        eqs = [ac.Eq(self.controlError, self.u_s - self.u_m),
               ac.connect(self.u_s, self.addP.u1), ac.connect(self.u_m, self.addP.u2),
               ac.connect(self.addP.y, self.P.u), ac.connect(self.P.y, self.addPID.u1),
               ac.connect(self.addPID.y, self.gainPID.u),
               ac.connect(self.gainPID.y, self.addFF.u1),
               ac.connect(self.addFF.y, self.limiter.u), ac.connect(self.limiter.y, self.y)]
        if self.with_I:
            eqs += [ac.connect(self.u_s, self.addI.u1), ac.connect(self.u_m, self.addI.u2),
                    ac.connect(self.addI.y, self.I.u), ac.connect(self.I.y, self.addPID.u3),
                    ac.connect(self.limiter.y, self.addSat.u1),
                    ac.connect(self.addFF.y, self.addSat.u2),
                    ac.connect(self.addSat.y, self.gainTrack.u),
                    ac.connect(self.gainTrack.y, self.addI.u3)]
        else:
            eqs.append(ac.connect(self.Izero.y, self.addPID.u3))
        if self.with_D:
            eqs += [ac.connect(self.u_s, self.addD.u1), ac.connect(self.u_m, self.addD.u2),
                    ac.connect(self.addD.y, self.D.u), ac.connect(self.D.y, self.addPID.u2)]
        else:
            eqs.append(ac.connect(self.Dzero.y, self.addPID.u2))
        eqs.append(ac.connect(self.u_ff if self.withFeedForward else self.FFzero.y,
                              self.addFF.u2))
        return eqs


class _LimitedController(SISO):
    """Output limits and back-calculation anti-windup shared by LimitedPI and LimitedPID.

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


class LimitedPI(_LimitedController):
    """PI controller  y = clip(k (1 + 1/(Ti s)) u, yMin, yMax), with back-calculation
    anti-windup (the MSL's unlimited PI is ``PI``):

        v = k u + x_i,   der(x_i) = (k/Ti) u + (y - v)/Tt,   y = clip(v, yMin, yMax)
    """

    def equations(self):
        return [ac.Eq(self.v, self.k * self.u + self.x_i)]


class LimitedPID(_LimitedController):
    """PID controller with a filtered derivative, output limits and back-calculation
    anti-windup (the MSL's unlimited PID is ``PID``, its limited one ``LimPID``):

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
