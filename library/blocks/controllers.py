"""The MSL's limited PID controller (Modelica.Blocks.Continuous.LimPID), built from
blocks as the MSL builds it, with the MSL's names for its parts (``PI.I.y`` is the
integrator's output, as in the MSL)."""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RealOutput

from .continuous import Derivative, Integrator
from .math import Add, Add3, Gain
from .nonlinear import Limiter
from .sources import Constant

__all__ = ["LimPID", "CONTROLLER_TYPES"]

CONTROLLER_TYPES = ("P", "PI", "PD", "PID")


class LimPID(ac.Component):
    """P, PI, PD or PID controller with limited output, anti-windup compensation,
    set-point weighting and optional feed-forward (MSL Blocks.Continuous.LimPID):

        addP = wp u_s - u_m,   addD = wd u_s - u_m,
        addI = u_s - u_m - (limiter.u - y)/(k Ni),   der(I.x) = addI / Ti,
        D = Td s/(1 + Td s/Nd) addD,
        limiter.u = k (addP + D.y + I.y) + kFF u_ff,   y = clip(limiter.u, yMin, yMax)

    ``controllerType`` ("PID" by default, "PI", "PD", "P") and ``withFeedForward`` are
    given when it is made; a part the type leaves out is not there (its Constant zero
    is, as in the MSL).  The integrator and the derivative block start from their
    states' start values (the MSL's initType = InitialState, with xi_start and xd_start
    their start values); for the MSL's SteadyState, give the model the initial equation
    der(I.x) = 0 (and der(D.x) = 0).
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

    def __init__(self, *, controllerType: str = "PID", withFeedForward: bool = False,
                 **modifications):
        if controllerType not in CONTROLLER_TYPES:
            raise ac.InvalidValue(f"LimPID: controllerType = {controllerType!r} is not one "
                                  f"of {', '.join(CONTROLLER_TYPES)}")
        self.controllerType = controllerType
        self.with_I = controllerType in ("PI", "PID")
        self.with_D = controllerType in ("PD", "PID")
        self.withFeedForward = bool(withFeedForward)
        super().__init__(**modifications)

    def build(self):
        if self.with_I:
            self.I = Integrator(k=ac.ref("k_I"))
            self.addI = Add3(k2=-1.0)
            self.addSat = Add(k1=1.0, k2=-1.0)
            self.gainTrack = Gain(k=ac.ref("k_track"))
        else:
            self.Izero = Constant(k=0.0)
        if self.with_D:
            self.addD = Add(k1=ac.ref("wd"), k2=-1.0)
            self.D = Derivative(k=ac.ref("k_D"), T=ac.ref("T_D"))
        else:
            self.Dzero = Constant(k=0.0)
        if self.withFeedForward:
            self.u_ff = RealInput()
        else:
            self.FFzero = Constant(k=0.0)

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
