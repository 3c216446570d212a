"""Modelica.Electrical.Machines.Examples.DCMachines.DCPM_QuasiStatic (MSL v4.0.0): a
transient and a quasi-static permanent magnet DC machine side by side.

Both machines (the data of Utilities.ParameterRecords.DcPermanentMagnetData, the
machines' defaults) run on 100 V from 1500 rpm, with load inertias of 0.15 kg.m2 loaded
by a pulse of -1.5 x 63.66 N.m (half of every second).  The quasi-static machine has
no armature transient: its current follows the load at once.

The vendored reference is MAP-LIB's result for MSL v3.2.3 (this example was
DCPM_QuasiStationary there, with the same parameters and connections): the v4.0.0
result is not in the copy of MAP-LIB this library is checked against.
"""
import acausal as ac
from acausal.library.blocks import Pulse
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical.machines import DC_PermanentMagnet, quasi_static
from acausal.library.rotational import Inertia, Torque

__all__ = ["DCPM_QuasiStatic"]

Va = 100.0                                 # V, actual armature voltage
w0 = 1500 * 2 * 3.141592653589793 / 60     # rad/s, no-load speed
TLoad = 63.66                              # N.m, nominal load torque
JLoad = 0.15                               # kg.m2, load's moment of inertia


class DCPM_QuasiStatic(ac.Component):
    """100 V; from 1500 rpm; pulsed load -95.49 N.m, period 1 s."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCPM_QuasiStatic"
    stop_time = 2.0
    tolerance = 1e-7

    dcpm1 = DC_PermanentMagnet(phiMechanical={"fixed": True}, ia={"fixed": True},
                               TaOperational=293.15,
                               wMechanical={"fixed": True, "start": w0})
    armatureVoltage = ConstantVoltage(V=Va)
    groundArmature = Ground()
    loadInertia1 = Inertia(J=JLoad)
    loadTorque1 = Torque()
    pulse = Pulse(amplitude=-1.5 * TLoad, offset=0.0, period=1.0)
    dcpm2 = quasi_static.DC_PermanentMagnet(phiMechanical={"fixed": True},
                                            wMechanical={"fixed": True, "start": w0},
                                            TaOperational=293.15)
    loadInertia2 = Inertia(J=JLoad)
    loadTorque2 = Torque()

    def equations(self):
        return [ac.connect(self.loadInertia1.flange_b, self.loadTorque1.flange),
                ac.connect(self.dcpm1.flange, self.loadInertia1.flange_a),
                ac.connect(self.armatureVoltage.n, self.groundArmature.p),
                ac.connect(self.armatureVoltage.p, self.dcpm1.pin_ap),
                ac.connect(self.armatureVoltage.n, self.dcpm1.pin_an),
                ac.connect(self.pulse.y, self.loadTorque1.tau),
                ac.connect(self.loadInertia2.flange_b, self.loadTorque2.flange),
                ac.connect(self.dcpm2.flange, self.loadInertia2.flange_a),
                ac.connect(self.pulse.y, self.loadTorque2.tau),
                ac.connect(self.armatureVoltage.p, self.dcpm2.pin_ap),
                ac.connect(self.armatureVoltage.n, self.dcpm2.pin_an)]


if __name__ == "__main__":
    res = ac.simulate(DCPM_QuasiStatic(), t_end=DCPM_QuasiStatic.stop_time,
                      rtol=DCPM_QuasiStatic.tolerance)
    print(f"loadInertia1.w, loadInertia2.w at {res.t[-1]:g} s: "
          f"{res['loadInertia1.w'][-1]:.6g}, {res['loadInertia2.w'][-1]:.6g} rad/s")
