"""Modelica.Mechanics.Translational.Examples.Vehicle (MSL v4.0.0): a one-dimensional
vehicle with driving resistances.

A table gives the wheel torque (in units of the torque that holds 25/3.5 m/s on the
level) and the inclination.  ``vehicle`` is driven alone; ``vehicle1`` is driven with
twice that torque and pulls ``trailer`` (a vehicle without drive) through a
multi-sensor.  Both have the same speed, as the trailer doubles the resistances.
"""
import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import CombiTimeTable, Gain
from acausal.library.rotational import Torque

__all__ = ["Vehicle"]

TABLE = [[0, 0, 0], [5, 0, 0], [5, 5.6, 0], [10.8, 5.6, 0], [10.8, 1, 0], [20, 1, 0],
         [20, 2.8, 0.05], [25, 2.8, 0.05], [25, 1, 0], [50, 1, 0], [50, -5, 0], [55, -5, 0],
         [55, 0, 0], [60, 0, 0]]


def _vehicle(fixed: bool):
    return tr.Vehicle(m=ac.ref("m"), J=0.0, R=ac.ref("R"), A=ac.ref("A"), Cd=ac.ref("Cd"),
                      CrConstant=ac.ref("Cr"), vWindConstant=ac.ref("vWind"),
                      useInclinationInput=True, s={"fixed": fixed}, v={"fixed": fixed})


class Vehicle(ac.Component):
    """m = 100 kg, R = 0.25 m, A = 1 m2, Cd = 0.5, Cr = 0.01, rho = 1.18 kg/m3 (the
    nominal force's; the vehicles keep their default 1.2)."""

    msl_name = "Modelica.Mechanics.Translational.Examples.Vehicle"
    stop_time = 60.0
    tolerance = 1e-6

    g_n = ac.Parameter(9.80665, unit="m/s2", description="standard gravity "
                                                        "(Modelica.Constants.g_n)")
    m = ac.Parameter(100.0, unit="kg", description="mass of vehicle")
    R = ac.Parameter(0.25, unit="m", description="radius of wheel")
    A = ac.Parameter(1.0, unit="m2", description="cross section of vehicle")
    Cd = ac.Parameter(0.5, description="drag resistance coefficient")
    rho = ac.Parameter(1.18, unit="kg/m3", description="density of air")
    vWind = ac.Parameter(0.0, unit="m/s", description="constant wind velocity")
    Cr = ac.Parameter(0.01, description="rolling resistance coefficient")
    inclination = ac.Parameter(0.0, description="constant inclination = tan(angle)")
    vNom = ac.Parameter(25 / 3.5, unit="m/s", description="nominal velocity")
    fDrag = ac.Parameter(lambda c: c.Cd * c.A * c.rho * (c.vNom - c.vWind)**2 / 2, unit="N",
                         description="drag resistance")
    alpha = ac.Parameter(lambda c: ac.atan(c.inclination), unit="rad",
                         description="inclination angle")
    fRoll = ac.Parameter(lambda c: c.Cr * c.m * c.g_n * ac.cos(c.alpha), unit="N",
                         description="roll resistance")
    fGrav = ac.Parameter(lambda c: c.m * c.g_n * ac.sin(c.alpha), unit="N",
                         description="grav resistance")
    torqueGain = ac.Parameter(lambda c: (c.fDrag + c.fRoll + c.fGrav) * c.R, unit="N.m",
                              description="the gain's k")

    vehicle = _vehicle(True)
    vehicle1 = _vehicle(True)
    trailer = _vehicle(False)
    multiSensor = tr.MultiSensor()
    timeTableTorqueInclination = CombiTimeTable(table=TABLE, extrapolation="hold")
    torque = Torque()
    torque1 = Torque()
    gain = Gain(k=ac.ref("torqueGain"))
    gain1 = Gain(k=2.0)

    def equations(self):
        table = self.timeTableTorqueInclination
        return [ac.connect(table.y[0], self.gain.u),
                ac.connect(table.y[1], self.vehicle.inclination),
                ac.connect(self.gain.y, self.torque.tau),
                ac.connect(self.torque.flange, self.vehicle.flangeR),
                ac.connect(self.torque1.flange, self.vehicle1.flangeR),
                ac.connect(table.y[1], self.vehicle1.inclination, self.trailer.inclination),
                ac.connect(self.gain.y, self.gain1.u),
                ac.connect(self.gain1.y, self.torque1.tau),
                ac.connect(self.vehicle1.flangeT, self.multiSensor.flange_a),
                ac.connect(self.multiSensor.flange_b, self.trailer.flangeT)]


if __name__ == "__main__":
    res = ac.simulate(Vehicle(), t_end=Vehicle.stop_time, rtol=Vehicle.tolerance)
    print(f"vehicle.v at {res.t[-1]:g} s: {res['vehicle.v'][-1]:.6g} m/s")
