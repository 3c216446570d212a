"""Modelica.Mechanics.Rotational.Examples.EddyCurrentBrake (MSL v4.0.0): an eddy current
brake slows down an inertia.

The kinetic energy becomes heat in the brake's heat capacitor (adiabatic over the short
braking); the hotter brake has its maximum torque at a higher speed.
"""
import acausal as ac
from acausal.library.electromechanical.machines.thermal import alpha20Copper
from acausal.library.rotational import EddyCurrentTorque, Inertia
from acausal.library.thermal import HeatCapacitor

__all__ = ["EddyCurrentBrake"]


class EddyCurrentBrake(ac.Component):
    """tau_nominal = 100 N.m at w_nominal = 10 rad/s (TRef = 20 degC, copper); J = 1
    kg.m2 from 20 rad/s; C = 1 J/K from 20 degC."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.EddyCurrentBrake"
    stop_time = 1.0
    tolerance = 1e-6

    eddyCurrentTorque = EddyCurrentTorque(tau_nominal=100.0, w_nominal=10.0,
                                          useSupport=False, alpha20=alpha20Copper,
                                          TRef=293.15, useHeatPort=True)
    inertia = Inertia(phi={"start": 0.0, "fixed": True}, J=1.0,
                      w={"start": 20.0, "fixed": True})
    heatCapacitor = HeatCapacitor(C=1.0, T={"fixed": True})

    def equations(self):
        return [ac.connect(self.eddyCurrentTorque.flange, self.inertia.flange_a),
                ac.connect(self.eddyCurrentTorque.heatPort, self.heatCapacitor.port)]


if __name__ == "__main__":
    res = ac.simulate(EddyCurrentBrake(), t_end=EddyCurrentBrake.stop_time,
                      rtol=EddyCurrentBrake.tolerance)
    print(f"heatCapacitor.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g} K")
