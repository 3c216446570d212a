"""Modelica.Mechanics.Translational.Examples.Sensors (MSL v4.0.0): the translational
sensors on a mass driven by a sine force.

The force acts on the mass through a force sensor and a multi-sensor in series; the
position, speed and acceleration of the mass's flanges are measured.
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.translational import (AccSensor, Force, ForceSensor, Mass, MultiSensor,
                                           PositionSensor, SpeedSensor)

__all__ = ["Sensors"]


class Sensors(ac.Component):
    """m = 1 kg, L = 1 m; force 10 N at 4 Hz."""

    msl_name = "Modelica.Mechanics.Translational.Examples.Sensors"
    stop_time = 1.0
    tolerance = 1e-6

    forceSensor = ForceSensor()
    multiSensor = MultiSensor()
    speedSensor1 = SpeedSensor()
    positionSensor1 = PositionSensor()
    accSensor1 = AccSensor()
    positionSensor2 = PositionSensor()
    mass = Mass(L=1.0, s={"fixed": True}, v={"fixed": True}, m=1.0)
    force = Force()
    sineForce = Sine(amplitude=10.0, f=4.0)

    def equations(self):
        return [ac.connect(self.sineForce.y, self.force.f),
                ac.connect(self.forceSensor.flange_a, self.force.flange),
                ac.connect(self.mass.flange_a, self.positionSensor1.flange),
                ac.connect(self.mass.flange_a, self.speedSensor1.flange),
                ac.connect(self.mass.flange_a, self.accSensor1.flange),
                ac.connect(self.mass.flange_b, self.positionSensor2.flange),
                ac.connect(self.forceSensor.flange_b, self.multiSensor.flange_a),
                ac.connect(self.multiSensor.flange_b, self.mass.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(Sensors(), t_end=Sensors.stop_time, rtol=Sensors.tolerance)
    print(f"mass.s at {res.t[-1]:g} s: {res['mass.s'][-1]:.6g} m")
