"""Modelica.Electrical.Machines.Examples.DCMachines.DCPM_Cooling (MSL v4.0.0): the
cooling of a permanent magnet DC motor.

The motor runs at no load at 1500 rpm (100 V) and is loaded by torque pulses of
1.5 x 63.66 N.m (period 1 s, half of it on).  Its thermal port heats the armature's
capacity (20 J/K), coupled to the core's (50 J/K), coupled to a pipe through which a
coolant (the default medium: rho = 1 kg/m3, cp = 1 J/(kg.K)) flows at 50 m3/s from an
inlet to an outlet at 20 degC; the ports without losses (stray load, friction, brushes,
permanent magnet) are at a fixed 20 degC.  The conductances are such that at nominal
load the coolant rises by 10 K, the core by 27.5 K and the armature by 55 K over the
coolant's mean temperature.  The model's thermal port (the MSL's protected connector
``thermalPort``) joins the machine's to the network, member by member.

MAP-LIB's reference result of this example is not in the copy this library is checked
against (not for v4.0.0, nor for v3.2.3), so it is not among the examples under
``examples.msl``; its test (``tests/library/test_electromechanical_machines.py``) solves
the machine's and the thermal network's equations independently.
"""
import math

import acausal as ac
from acausal.library.blocks import Pulse
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical.machines import DC_PermanentMagnet
from acausal.library.electromechanical.machines.interfaces import ThermalPortDCPM
from acausal.library.electromechanical.machines.thermal import alpha20Copper
from acausal.library.fluidheatflow import Ambient, Pipe, VolumeFlow
from acausal.library.rotational import Inertia, Torque
from acausal.library.thermal import FixedTemperature, HeatCapacitor, ThermalConductor

__all__ = ["DCPM_Cooling"]

Va = 100.0                        # V, actual armature voltage
w0 = 1500 * 2 * math.pi / 60      # rad/s, no-load speed
TLoad = 63.66                     # N.m, nominal load torque
JLoad = 0.15                      # kg.m2, load's moment of inertia
TAmbient = 293.15                 # K, ambient temperature
Ca = 20.0                         # J/K, armature's heat capacity
Cc = 50.0                         # J/K, core's heat capacity
CoolantFlow = 50.0                # m3/s, coolant flow

# Utilities.ParameterRecords.DcPermanentMagnetData dcpmData: the machine's defaults with
# these modifications
dcpmData = dict(alpha20a=alpha20Copper, TaNominal=353.15, TaRef=353.15)
Ra, IaNominal = 0.05, 100.0       # the data's armature resistance and nominal current
Losses = Ra * IaNominal**2        # W, nominal losses
T0 = 293.15                       # K, reference temperature 20 degC
dTCoolant = 10.0                  # K, coolant's temperature rise
dTArmature = dcpmData["TaNominal"] - T0 - dTCoolant / 2   # armature's rise over coolant
G_armature_core = 2 * Losses / dTArmature                 # W/K
G_core_cooling = 2 * Losses / dTArmature                  # W/K


class DCPM_Cooling(ac.Component):
    """Load pulses on a DC motor whose armature and core a coolant flow cools."""

    stop_time = 25.0
    tolerance = 1e-7

    dcpm = DC_PermanentMagnet(**dcpmData, useThermalPort=True, TaOperational=293.15,
                              wMechanical={"start": w0, "fixed": True},
                              phiMechanical={"fixed": True}, ia={"fixed": True})
    armatureVoltage = ConstantVoltage(V=Va)
    groundArmature = Ground()
    loadInertia = Inertia(J=JLoad)
    loadTorque = Torque()
    pulse = Pulse(amplitude=-1.5 * TLoad, offset=0.0, period=1.0)
    armature = HeatCapacitor(C=Ca, T={"start": TAmbient, "fixed": True})
    armatureCore = ThermalConductor(G=G_armature_core)
    core = HeatCapacitor(C=Cc, T={"start": TAmbient, "fixed": True})
    coreCooling = ThermalConductor(G=G_core_cooling)
    inlet = Ambient(constantAmbientTemperature=TAmbient, constantAmbientPressure=0.0)
    volumeFlow = VolumeFlow(T0=TAmbient, constantVolumeFlow=CoolantFlow, m=0.0)
    cooling = Pipe(tapT=0.5, T0=TAmbient, m=0.0, h_g=0.0, V_flowLaminar=0.1,
                   dpLaminar=0.1, V_flowNominal=1.0, dpNominal=1.0, T0fixed=False,
                   useHeatPort=True)
    outlet = Ambient(constantAmbientTemperature=TAmbient, constantAmbientPressure=0.0)
    fixedTemperature = FixedTemperature(T=TAmbient)
    thermalPort = ThermalPortDCPM()

    def equations(self):
        tp = self.thermalPort
        return [ac.connect(self.loadInertia.flange_b, self.loadTorque.flange),
                ac.connect(self.dcpm.flange, self.loadInertia.flange_a),
                ac.connect(self.armatureVoltage.n, self.groundArmature.p),
                ac.connect(self.armatureVoltage.p, self.dcpm.pin_ap),
                ac.connect(self.armatureVoltage.n, self.dcpm.pin_an),
                ac.connect(self.armature.port, self.armatureCore.port_a),
                ac.connect(self.armatureCore.port_b, self.core.port),
                ac.connect(self.core.port, self.coreCooling.port_a),
                ac.connect(self.pulse.y, self.loadTorque.tau),
                ac.connect(self.coreCooling.port_b, self.cooling.heatPort),
                ac.connect(self.cooling.flowPort_b, self.outlet.flowPort),
                ac.connect(self.inlet.flowPort, self.volumeFlow.flowPort_a),
                ac.connect(self.volumeFlow.flowPort_b, self.cooling.flowPort_a),
                ac.connect(self.armature.port, tp.heatPortArmature),
                ac.connect(self.core.port, tp.heatPortCore),
                ac.connect(self.fixedTemperature.port, tp.heatPortStrayLoad),
                ac.connect(self.fixedTemperature.port, tp.heatPortFriction),
                ac.connect(self.fixedTemperature.port, tp.heatPortBrush),
                ac.connect(self.fixedTemperature.port, tp.heatPortPermanentMagnet),
                ac.connect(self.dcpm.thermalPort, tp)]


if __name__ == "__main__":
    res = ac.simulate(DCPM_Cooling(), t_end=DCPM_Cooling.stop_time,
                      rtol=DCPM_Cooling.tolerance)
    print(f"armature.T, core.T, cooling.T at {res.t[-1]:g} s: {res['armature.T'][-1]:.6g}, "
          f"{res['core.T'][-1]:.6g}, {res['cooling.T'][-1]:.6g} K")
