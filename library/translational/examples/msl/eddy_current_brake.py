"""Modelica.Mechanics.Translational.Examples.EddyCurrentBrake (MSL v4.0.0): an eddy current
brake slows down a mass.

The kinetic energy becomes heat in the brake's heat capacitor (adiabatic over the short
braking); the hotter brake has its maximum force at a higher speed.
"""
import acausal as ac
from acausal.library.electromechanical.machines.thermal import alpha20Copper
from acausal.library.translational import EddyCurrentForce, Mass
from acausal.library.thermal import HeatCapacitor

__all__ = ["EddyCurrentBrake"]


class EddyCurrentBrake(ac.Component):
    """f_nominal = 100 N at v_nominal = 10 m/s (TRef = 20 degC, copper); m = 1 kg
    from 20 m/s; C = 1 J/K from 20 degC."""

    msl_name = "Modelica.Mechanics.Translational.Examples.EddyCurrentBrake"
    stop_time = 1.0
    tolerance = 1e-6

    eddyCurrentForce = EddyCurrentForce(f_nominal=100.0, v_nominal=10.0,
                                        useHeatPort=True, TRef=293.15,
                                        alpha20=alpha20Copper)
    mass = Mass(m=1.0, s={"start": 0.0, "fixed": True}, v={"start": 20.0, "fixed": True})
    heatCapacitor = HeatCapacitor(C=1.0, T={"fixed": True})

    def equations(self):
        return [ac.connect(self.eddyCurrentForce.flange, self.mass.flange_a),
                ac.connect(self.eddyCurrentForce.heatPort, self.heatCapacitor.port)]


if __name__ == "__main__":
    res = ac.simulate(EddyCurrentBrake(), t_end=EddyCurrentBrake.stop_time,
                      rtol=EddyCurrentBrake.tolerance)
    print(f"heatCapacitor.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g} K")
