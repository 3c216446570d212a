"""Modelica.Electrical.Machines.Examples.DCMachines.DCPM_withLosses (MSL v4.0.0): the
influence of losses on a permanent magnet DC motor.

Two machines on one voltage ramp (0 -> 100 V between 0.2 s and 1 s) each drive a load
inertia of 0.15 kg.m2 and a load torque quadratic in speed.  dcpm1 has the lossless data
of Utilities.ParameterRecords.DcPermanentMagnetData (its load 63.66 N.m at 1425 rpm);
dcpm2 the data dcpmData2 with losses -- Ra = 0.03864 Ohm of copper at 95 degC, friction
100 W, core 200 W, stray load 50 W, brushes 0.5 V -- and the same nominal point
(61.30 N.m at 1417.5 rpm).

The vendored reference is MAP-LIB's result for MSL v3.2.3, whose example has the same
parameters and connections: the v4.0.0 result is not in the copy of MAP-LIB this library
is checked against.
"""
import math

import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import Ground, SignalVoltage
from acausal.library.electromechanical.machines import DC_PermanentMagnet
from acausal.library.electromechanical.machines.thermal import alpha20Copper
from acausal.library.rotational import Inertia, QuadraticSpeedDependentTorque

__all__ = ["DCPM_withLosses"]

Va = 100.0                        # V, actual armature voltage
tStart = 0.2                      # s, start of armature voltage ramp
tRamp = 0.8                       # s, armature voltage ramp
TLoad1 = 63.66                    # N.m, nominal load torque
wLoad1 = 1425 * 2 * math.pi / 60  # rad/s, nominal load speed
TLoad2 = 61.30                    # N.m, nominal load torque
wLoad2 = 1417.5 * 2 * math.pi / 60
JLoad = 0.15                      # kg.m2, load's moment of inertia

# Utilities.ParameterRecords.DcPermanentMagnetData dcpmData2: the machine's defaults
# with these modifications
dcpmData2 = dict(Ra=0.03864, alpha20a=alpha20Copper, wNominal=148.44025288212,
                 TaNominal=368.15, frictionParameters={"PRef": 100.0},
                 coreParameters={"PRef": 200.0}, strayLoadParameters={"PRef": 50.0},
                 brushParameters={"V": 0.5})


class DCPM_withLosses(ac.Component):
    """dcpm1 without losses, dcpm2 with friction, core, stray load and brush losses."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCPM_withLosses"
    stop_time = 2.0
    tolerance = 1e-7

    dcpm1 = DC_PermanentMagnet(TaOperational=293.15, phiMechanical={"fixed": True},
                               wMechanical={"fixed": True}, ia={"fixed": True})
    ramp = Ramp(duration=tRamp, height=Va, startTime=tStart)
    signalVoltage = SignalVoltage()
    ground = Ground()
    loadInertia1 = Inertia(J=JLoad)
    loadTorque1 = QuadraticSpeedDependentTorque(tau_nominal=-TLoad1, TorqueDirection=False,
                                                w_nominal=wLoad1)
    dcpm2 = DC_PermanentMagnet(**dcpmData2, phiMechanical={"fixed": True},
                               wMechanical={"fixed": True}, ia={"fixed": True},
                               TaOperational=368.15, core={"v": {"start": 0.0}})
    loadInertia2 = Inertia(J=JLoad)
    loadTorque2 = QuadraticSpeedDependentTorque(tau_nominal=-TLoad2, TorqueDirection=False,
                                                w_nominal=wLoad2)

    def equations(self):
        return [ac.connect(self.ramp.y, self.signalVoltage.v),
                ac.connect(self.signalVoltage.n, self.ground.p),
                ac.connect(self.loadInertia1.flange_b, self.loadTorque1.flange),
                ac.connect(self.dcpm1.flange, self.loadInertia1.flange_a),
                ac.connect(self.loadInertia2.flange_b, self.loadTorque2.flange),
                ac.connect(self.dcpm2.flange, self.loadInertia2.flange_a),
                ac.connect(self.signalVoltage.p, self.dcpm1.pin_ap),
                ac.connect(self.signalVoltage.p, self.dcpm2.pin_ap),
                ac.connect(self.signalVoltage.n, self.dcpm1.pin_an),
                ac.connect(self.signalVoltage.n, self.dcpm2.pin_an)]


if __name__ == "__main__":
    res = ac.simulate(DCPM_withLosses(), t_end=DCPM_withLosses.stop_time,
                      rtol=DCPM_withLosses.tolerance)
    print(f"loadInertia1.w, loadInertia2.w at {res.t[-1]:g} s: "
          f"{res['loadInertia1.w'][-1]:.6g}, {res['loadInertia2.w'][-1]:.6g} rad/s")
