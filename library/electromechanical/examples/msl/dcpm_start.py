"""Modelica.Electrical.Machines.Examples.DCMachines.DCPM_Start (MSL v4.0.0): a permanent
magnet DC machine started with a voltage ramp.

The armature voltage ramps from 0 to 100 V between 0.2 s and 1 s; the machine (the data
of Utilities.ParameterRecords.DcPermanentMagnetData, the machine's defaults: 100 V,
100 A, 1425 rpm, Ra = 0.05 Ohm, La = 1.5 mH, Jr = 0.15 kg.m2) accelerates a load
inertia of 0.15 kg.m2, loaded with the nominal torque 63.66 N.m from 1.5 s.
"""
import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import Ground, SignalVoltage
from acausal.library.electromechanical.machines import DC_PermanentMagnet
from acausal.library.rotational import Inertia, TorqueStep

__all__ = ["DCPM_Start"]

Va = 100.0       # V, actual armature voltage
tStart = 0.2     # s, start of armature voltage ramp
tRamp = 0.8      # s, armature voltage ramp
TLoad = 63.66    # N.m, nominal load torque
tStep = 1.5      # s, time of load torque step
JLoad = 0.15     # kg.m2, load's moment of inertia


class DCPM_Start(ac.Component):
    """Voltage ramp 0 -> 100 V, load step -63.66 N.m at 1.5 s."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCPM_Start"
    stop_time = 2.0
    tolerance = 1e-7

    dcpm = DC_PermanentMagnet(TaOperational=293.15, phiMechanical={"fixed": True},
                              wMechanical={"fixed": True}, ia={"fixed": True})
    ramp = Ramp(duration=tRamp, height=Va, startTime=tStart)
    signalVoltage = SignalVoltage()
    ground = Ground()
    loadInertia = Inertia(J=JLoad)
    loadTorqueStep = TorqueStep(startTime=tStep, stepTorque=-TLoad, offsetTorque=0.0)

    def equations(self):
        return [ac.connect(self.ramp.y, self.signalVoltage.v),
                ac.connect(self.signalVoltage.p, self.dcpm.pin_ap),
                ac.connect(self.signalVoltage.n, self.ground.p),
                ac.connect(self.dcpm.pin_an, self.signalVoltage.n),
                ac.connect(self.loadInertia.flange_b, self.loadTorqueStep.flange),
                ac.connect(self.dcpm.flange, self.loadInertia.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(DCPM_Start(), t_end=DCPM_Start.stop_time, rtol=DCPM_Start.tolerance)
    print(f"loadInertia.w at {res.t[-1]:g} s: {res['loadInertia.w'][-1]:.6g} rad/s")
