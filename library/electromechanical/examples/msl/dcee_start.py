"""Modelica.Electrical.Machines.Examples.DCMachines.DCEE_Start (MSL v4.0.0): an
electrically (separately) excited DC machine started with a voltage ramp.

The excitation is held at 100 V (Re = 100 Ohm, Le = 1 H: 1 A at steady state, reached
with a time constant of 10 ms); the armature voltage ramps from 0 to 100 V between 0.2 s
and 1 s; the machine (the data of Utilities.ParameterRecords.DcElectricalExcitedData,
the machine's defaults) accelerates a load inertia of 0.15 kg.m2, loaded with the
nominal torque 63.66 N.m from 1.5 s.
"""
import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import ConstantVoltage, Ground, SignalVoltage
from acausal.library.electromechanical.machines import DC_ElectricalExcited
from acausal.library.rotational import Inertia, TorqueStep

__all__ = ["DCEE_Start"]

Va = 100.0       # V, actual armature voltage
tStart = 0.2     # s, start of armature voltage ramp
tRamp = 0.8      # s, armature voltage ramp
Ve = 100.0       # V, actual excitation voltage
TLoad = 63.66    # N.m, nominal load torque
tStep = 1.5      # s, time of load torque step
JLoad = 0.15     # kg.m2, load's moment of inertia


class DCEE_Start(ac.Component):
    """Excitation 100 V; voltage ramp 0 -> 100 V; load step -63.66 N.m at 1.5 s."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCEE_Start"
    stop_time = 2.0
    tolerance = 1e-7

    dcee = DC_ElectricalExcited(TaOperational=293.15, phiMechanical={"fixed": True},
                                wMechanical={"fixed": True}, ia={"fixed": True},
                                TeOperational=293.15, ie={"fixed": True})
    ramp = Ramp(duration=tRamp, height=Va, startTime=tStart)
    signalVoltage = SignalVoltage()
    ground = Ground()
    constantVoltage = ConstantVoltage(V=Ve)
    groundExcitation = Ground()
    loadInertia = Inertia(J=JLoad)
    loadTorqueStep = TorqueStep(startTime=tStep, stepTorque=-TLoad, offsetTorque=0.0)

    def equations(self):
        return [ac.connect(self.ramp.y, self.signalVoltage.v),
                ac.connect(self.signalVoltage.p, self.dcee.pin_ap),
                ac.connect(self.signalVoltage.n, self.ground.p),
                ac.connect(self.dcee.pin_an, self.ground.p),
                ac.connect(self.constantVoltage.n, self.groundExcitation.p),
                ac.connect(self.dcee.pin_ep, self.constantVoltage.p),
                ac.connect(self.dcee.pin_en, self.constantVoltage.n),
                ac.connect(self.loadInertia.flange_b, self.loadTorqueStep.flange),
                ac.connect(self.dcee.flange, self.loadInertia.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(DCEE_Start(), t_end=DCEE_Start.stop_time, rtol=DCEE_Start.tolerance)
    print(f"loadInertia.w at {res.t[-1]:g} s: {res['loadInertia.w'][-1]:.6g} rad/s")
