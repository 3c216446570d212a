"""Modelica.Electrical.Machines.Examples.DCMachines.DC_CompareCharacteristics (MSL
v4.0.0): torque-speed characteristics of DC motors.

Three quasi-static machines on 100 V, at their nominal temperatures and starting at
their nominal speeds (permanent magnet; separately excited at 100 V; series excited,
its field in series with the armature) each drive a load inertia of 0.15 kg.m2 against a
load torque ramped from -63.66 N.m (nominal) to 0 between 0.5 s and 5.5 s; the series
machine's load is limited to [-2, -0.1] x 63.66 N.m, so that it does not run away
unloaded.
"""
import acausal as ac
from acausal.library.blocks import Limiter, Ramp
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical.machines import quasi_static
from acausal.library.rotational import Inertia, Torque

__all__ = ["DC_CompareCharacteristics"]

Va = 100.0       # V, actual armature voltage
Ve = 100.0       # V, actual excitation voltage
TLoad = 63.66    # N.m, nominal load torque
tStart = 0.5     # s, start of load torque ramp
tRamp = 5.0      # s, load torque ramp
JLoad = 0.15     # kg.m2, load's moment of inertia

# the nominal speeds of Utilities.ParameterRecords.DcPermanentMagnetData (also of
# DcElectricalExcitedData) and DcSeriesExcitedData, the machines' defaults
wNominal = 1425 * 2 * 3.141592653589793 / 60
wNominalSE = 1410 * 2 * 3.141592653589793 / 60


class DC_CompareCharacteristics(ac.Component):
    """Load ramp -63.66 N.m -> 0 over 5 s from 0.5 s, on three quasi-static machines."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DC_CompareCharacteristics"
    stop_time = 6.0
    tolerance = 1e-6

    armatureVoltage = ConstantVoltage(V=Va)
    groundArmature = Ground()
    excitationVoltage = ConstantVoltage(V=Ve)
    groundExcitation = Ground()
    dcpm = quasi_static.DC_PermanentMagnet(
        TaOperational=293.15, phiMechanical={"fixed": True, "start": 0.0},
        wMechanical={"fixed": True, "start": wNominal},
        ia={"fixed": False, "start": 100.0})
    loadInertia1 = Inertia(J=JLoad)
    loadTorque1 = Torque()
    dcee = quasi_static.DC_ElectricalExcited(
        TaOperational=293.15, phiMechanical={"fixed": True, "start": 0.0},
        wMechanical={"start": wNominal, "fixed": True}, ia={"fixed": False, "start": 100.0},
        TeOperational=293.15, ie={"start": 1.0, "fixed": False})
    loadInertia2 = Inertia(J=JLoad)
    loadTorque2 = Torque()
    dcse = quasi_static.DC_SeriesExcited(
        TaOperational=293.15, phiMechanical={"fixed": True, "start": 0.0},
        wMechanical={"fixed": True, "start": wNominalSE},
        ia={"fixed": False, "start": 100.0}, TeNominal=293.15, TeOperational=293.15)
    loadInertia3 = Inertia(J=JLoad)
    loadTorque3 = Torque()
    ramp = Ramp(startTime=tStart, height=TLoad, duration=tRamp, offset=-TLoad)
    limiter = Limiter(uMax=-0.1 * TLoad, uMin=-2 * TLoad)

    def equations(self):
        return [ac.connect(self.loadInertia1.flange_b, self.loadTorque1.flange),
                ac.connect(self.armatureVoltage.n, self.groundArmature.p),
                ac.connect(self.excitationVoltage.n, self.groundExcitation.p),
                ac.connect(self.loadInertia2.flange_b, self.loadTorque2.flange),
                ac.connect(self.loadInertia3.flange_b, self.loadTorque3.flange),
                ac.connect(self.armatureVoltage.p, self.dcpm.pin_ap),
                ac.connect(self.armatureVoltage.p, self.dcee.pin_ap),
                ac.connect(self.armatureVoltage.p, self.dcse.pin_ap),
                ac.connect(self.armatureVoltage.n, self.dcpm.pin_an),
                ac.connect(self.armatureVoltage.n, self.dcee.pin_an),
                ac.connect(self.armatureVoltage.n, self.dcse.pin_en),
                ac.connect(self.dcse.pin_ep, self.dcse.pin_an),
                ac.connect(self.excitationVoltage.p, self.dcee.pin_ep),
                ac.connect(self.excitationVoltage.n, self.dcee.pin_en),
                ac.connect(self.dcpm.flange, self.loadInertia1.flange_a),
                ac.connect(self.dcee.flange, self.loadInertia2.flange_a),
                ac.connect(self.dcse.flange, self.loadInertia3.flange_a),
                ac.connect(self.ramp.y, self.loadTorque1.tau),
                ac.connect(self.ramp.y, self.loadTorque2.tau),
                ac.connect(self.ramp.y, self.limiter.u),
                ac.connect(self.limiter.y, self.loadTorque3.tau)]


if __name__ == "__main__":
    res = ac.simulate(DC_CompareCharacteristics(), t_end=DC_CompareCharacteristics.stop_time,
                      rtol=DC_CompareCharacteristics.tolerance)
    for k in (1, 2, 3):
        print(f"loadInertia{k}.w at {res.t[-1]:g} s: {res[f'loadInertia{k}.w'][-1]:.6g} rad/s")
