"""Modelica.Electrical.Machines.Examples.DCMachines.DCPM_Temperature (MSL v4.0.0): the
influence of the armature's temperature on a permanent magnet DC motor.

The motor runs at no load at 1500 rpm (100 V) and is loaded with 63.66 N.m at 0.1 s;
from then its armature temperature, given through the machine's thermal port by a
thermal ambient with temperature inputs, rises exponentially from 20 degC towards
80 degC (time constant 0.5 s).  The armature is of copper and its resistance is the
machine's default Ra at 80 degC (TaRef = TaNominal = 80 degC), so the machine starts
cold (a smaller resistance) and ends warm.

The vendored reference is MAP-LIB's result for MSL v3.2.3 (the v4.0.0 result is not in
the copy of MAP-LIB this library is checked against); the example's source is the same in
both versions but for the units' package names.
"""
import math

import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical.machines import DC_PermanentMagnet, ThermalAmbientDCPM
from acausal.library.electromechanical.machines.thermal import alpha20Copper
from acausal.library.rotational import Inertia, TorqueStep

from .utilities import Exponentials

__all__ = ["DCPM_Temperature"]

Va = 100.0                        # V, actual armature voltage
w0 = 1500 * 2 * math.pi / 60      # rad/s, no-load speed
TLoad = 63.66                     # N.m, nominal load torque
JLoad = 0.15                      # kg.m2, load's moment of inertia

# Utilities.ParameterRecords.DcPermanentMagnetData dcpmData: the machine's defaults with
# these modifications
dcpmData = dict(alpha20a=alpha20Copper, TaNominal=353.15, TaRef=353.15)


class DCPM_Temperature(ac.Component):
    """No-load start at w0, load step at 0.1 s, armature 20 -> 80 degC."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCPM_Temperature"
    stop_time = 3.0
    tolerance = 1e-7

    dcpm = DC_PermanentMagnet(**dcpmData, useThermalPort=True, TaOperational=293.15,
                              wMechanical={"start": w0, "fixed": True},
                              phiMechanical={"fixed": True}, ia={"fixed": True})
    armatureVoltage = ConstantVoltage(V=Va)
    groundArmature = Ground()
    loadInertia = Inertia(J=JLoad)
    loadTorque = TorqueStep(stepTorque=-TLoad, offsetTorque=0.0, startTime=0.1)
    thermalAmbientDCPM = ThermalAmbientDCPM(useTemperatureInputs=True, Ta=293.15,
                                            Tpm=293.15)
    exponential = Exponentials(offset=293.15, outMax=60.0, riseTime=3600.0,
                               riseTimeConst=0.5, fallTimeConst=0.5, startTime=0.1)
    const = Constant(k=293.15)

    def equations(self):
        return [ac.connect(self.loadInertia.flange_b, self.loadTorque.flange),
                ac.connect(self.dcpm.flange, self.loadInertia.flange_a),
                ac.connect(self.armatureVoltage.n, self.groundArmature.p),
                ac.connect(self.armatureVoltage.p, self.dcpm.pin_ap),
                ac.connect(self.armatureVoltage.n, self.dcpm.pin_an),
                ac.connect(self.exponential.y, self.thermalAmbientDCPM.TArmature),
                ac.connect(self.const.y, self.thermalAmbientDCPM.TPermanentMagnet),
                ac.connect(self.dcpm.thermalPort, self.thermalAmbientDCPM.thermalPort)]


if __name__ == "__main__":
    res = ac.simulate(DCPM_Temperature(), t_end=DCPM_Temperature.stop_time,
                      rtol=DCPM_Temperature.tolerance)
    print(f"loadInertia.w at {res.t[-1]:g} s: {res['loadInertia.w'][-1]:.6g} rad/s")
