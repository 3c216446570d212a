"""Modelica.Electrical.Machines.Examples.DCMachines.DCPM_CurrentControlled (MSL v4.0.0):
a permanent magnet DC machine started by a current controller.

A PI current controller (LimPID with the induced voltage kPhi w fed forward, output
limited to the nominal voltage), tuned by the absolute optimum (k = Ra Ta/(2 Ts), Ti =
Ta = La/Ra) for an inverter of dead time Ts = 1 ms (a first-order lag), drives the
armature voltage.  At 0.1 s the current reference steps to the nominal current 100 A and
the machine accelerates its load inertia against a load torque quadratic in speed.  The
controller and the inverter start at their outputs, 0 (initType = InitialOutput).

The vendored reference is MAP-LIB's result for MSL v3.2.3 (the v4.0.0 result is not in
the copy of MAP-LIB this library is checked against); the example's source is the same in
both versions but for the units' package names and v3.2.3's name of the initialization
choice (Types.InitPID.InitialOutput, of the same meaning).
"""
import acausal as ac
from acausal.library.blocks import FirstOrder, LimPID, Step
from acausal.library.electrical import CurrentSensor, Ground, SignalVoltage
from acausal.library.electromechanical.machines import DC_PermanentMagnet
from acausal.library.electromechanical.machines.thermal import convertResistance
from acausal.library.rotational import Inertia, QuadraticSpeedDependentTorque, SpeedSensor

__all__ = ["DCPM_CurrentControlled"]

# Utilities.ParameterRecords.DcPermanentMagnetData dcpmData: the machine's defaults
VaNominal, IaNominal, wNominal = 100.0, 100.0, 1425 * 2 * 3.141592653589793 / 60
Ra_data, TaRef, alpha20a, TaNominal, La, Jr = 0.05, 293.15, 0.0, 293.15, 0.0015, 0.15

Ra = convertResistance(Ra_data, TaRef, alpha20a, TaNominal)   # warm armature resistance
ViNominal = VaNominal - Ra * IaNominal                         # nominal induced voltage
TLoad = ViNominal * IaNominal / wNominal                       # N.m, nominal load torque
wLoad = wNominal                                               # rad/s, nominal load speed
JLoad = Jr                                                     # kg.m2, load's inertia
Ta = La / Ra                                                   # s, armature time constant
Ts = 1e-3                                                      # s, dead time of inverter
k = Ra * Ta / (2 * Ts)                                         # Ohm, controller gain
Ti = Ta                                                        # s, integral time constant
kPhi = ViNominal / wNominal                                    # Wb, voltage constant


class DCPM_CurrentControlled(ac.Component):
    """Current step 0 -> 100 A at 0.1 s through a PI controller and an inverter lag."""

    msl_name = "Modelica.Electrical.Machines.Examples.DCMachines.DCPM_CurrentControlled"
    stop_time = 2.0
    tolerance = 1e-7

    dcpm = DC_PermanentMagnet(TaOperational=293.15, phiMechanical={"fixed": True},
                              wMechanical={"fixed": True}, ia={"fixed": True})
    step = Step(height=IaNominal, offset=0.0, startTime=0.1)
    signalVoltage = SignalVoltage()
    ground = Ground()
    loadInertia = Inertia(J=JLoad)
    loadTorque = QuadraticSpeedDependentTorque(tau_nominal=-TLoad, TorqueDirection=False,
                                               w_nominal=wLoad)
    currentSensor = CurrentSensor()
    speedSensor = SpeedSensor()
    firstOrder = FirstOrder(k=1.0, T=Ts, initType="InitialOutput", y_start=0.0)
    PID = LimPID(withFeedForward=True, initType="InitialOutput", controllerType="PI",
                 k=k, Ti=Ti, yMax=VaNominal, kFF=kPhi)

    def equations(self):
        return [ac.connect(self.signalVoltage.n, self.ground.p),
                ac.connect(self.loadInertia.flange_b, self.loadTorque.flange),
                ac.connect(self.dcpm.flange, self.loadInertia.flange_a),
                ac.connect(self.dcpm.pin_an, self.ground.p),
                ac.connect(self.signalVoltage.p, self.currentSensor.p),
                ac.connect(self.currentSensor.n, self.dcpm.pin_ap),
                ac.connect(self.dcpm.flange, self.speedSensor.flange),
                ac.connect(self.firstOrder.y, self.signalVoltage.v),
                ac.connect(self.PID.y, self.firstOrder.u),
                ac.connect(self.step.y, self.PID.u_s),
                ac.connect(self.currentSensor.i, self.PID.u_m),
                ac.connect(self.speedSensor.w, self.PID.u_ff)]


if __name__ == "__main__":
    res = ac.simulate(DCPM_CurrentControlled(), t_end=DCPM_CurrentControlled.stop_time,
                      rtol=DCPM_CurrentControlled.tolerance)
    print(f"dcpm.ia, loadInertia.w at {res.t[-1]:g} s: {res['dcpm.ia'][-1]:.6g} A, "
          f"{res['loadInertia.w'][-1]:.6g} rad/s")
