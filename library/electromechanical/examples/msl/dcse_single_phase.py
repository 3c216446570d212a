"""Modelica.Electrical.Machines.Examples.DCMachines.DCSE_SinglePhase (MSL v4.0.0): a
series excited DC machine on alternating voltage (a universal motor).

DCSE_Start fed from a 50 Hz sine of 100 V RMS instead of 100 V DC: the series field and
the armature current change sign together, so the torque keeps its direction.
"""
import math

import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import Ground, SineVoltage, VariableResistor
from acausal.library.electromechanical.machines import DC_SeriesExcited
from acausal.library.rotational import Inertia, QuadraticSpeedDependentTorque

__all__ = ["DCSE_SinglePhase"]

Va = 100.0                          # V, actual armature voltage (RMS)
tStart = 0.1                        # s, start of resistance ramp
tRamp = 0.9                         # s, resistance ramp
TLoad = 63.66                       # N.m, nominal load torque
wLoad = 1410 * 2 * math.pi / 60     # rad/s, nominal load speed
JLoad = 0.15                        # kg.m2, load's moment of inertia


class DCSE_SinglePhase(ac.Component):
    """100 V RMS, 50 Hz, through 1 -> 0 Ohm; quadratic load 63.66 N.m at 1410 rpm.
    The source keeps the MSL's name, constantVoltage."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCSE_SinglePhase"
    stop_time = 2.0
    tolerance = 1e-7

    dcse = DC_SeriesExcited(TaOperational=293.15, phiMechanical={"fixed": True},
                            wMechanical={"fixed": True}, ia={"fixed": True},
                            TeOperational=293.15)
    ramp = Ramp(duration=tRamp, startTime=tStart, height=-1.0, offset=1.0)
    constantVoltage = SineVoltage(V=math.sqrt(2) * Va, f=50.0)
    ground = Ground()
    loadInertia = Inertia(J=JLoad)
    quadraticLoadTorque = QuadraticSpeedDependentTorque(w_nominal=wLoad,
                                                        TorqueDirection=False,
                                                        tau_nominal=-TLoad)
    variableResistor = VariableResistor()

    def equations(self):
        return [ac.connect(self.constantVoltage.n, self.ground.p),
                ac.connect(self.loadInertia.flange_b, self.quadraticLoadTorque.flange),
                ac.connect(self.dcse.pin_an, self.dcse.pin_ep),
                ac.connect(self.dcse.pin_en, self.constantVoltage.n),
                ac.connect(self.dcse.flange, self.loadInertia.flange_a),
                ac.connect(self.constantVoltage.p, self.variableResistor.p),
                ac.connect(self.variableResistor.n, self.dcse.pin_ap),
                ac.connect(self.ramp.y, self.variableResistor.R)]


if __name__ == "__main__":
    res = ac.simulate(DCSE_SinglePhase(), t_end=DCSE_SinglePhase.stop_time, rtol=DCSE_SinglePhase.tolerance)
    print(f"loadInertia.w at {res.t[-1]:g} s: {res['loadInertia.w'][-1]:.6g} rad/s")
