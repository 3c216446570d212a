"""Motor, rigid gear with backlash and load (Egeland & Gravdahl 3.6.3, (3.120)-(3.124)).

    free  (|phi| < delta):   J_m theta_m'' = T_m,   J_L theta_L'' = 0
    contact (|phi| = delta): (J_m + n_b^2 J_L) theta_m'' = T_m,   theta_L = n_b (theta_m -+ delta)

The motor torque reverses every 0.2 s, so the teeth separate, cross the dead zone, hit
the other flank (a plastic impact: momentum kept, relative speed lost) and drive the
load the other way.  In the library's terms n = 1/n_b = 5, and the dead zone is
delta = 0.01 rad at the load (0.05 rad at the motor, as in ``backlash``).
"""
import acausal as ac
from acausal.library.blocks import Pulse
from acausal.library.rotational import GearWithBacklash, Inertia, Torque

__all__ = ["RigidBacklashDrive"]


class RigidBacklashDrive(ac.Component):
    """J_m = 0.01, J_L = 0.5 kg m^2, n = 5, delta = 0.01 rad (load side); T_m = +-0.5 N m,
    a square wave of period 0.4 s; starts at rest in the middle of the dead zone."""

    stop_time = 1.0
    J_m = ac.Parameter(0.01, unit="kg.m2", description="motor inertia")
    J_L = ac.Parameter(0.5, unit="kg.m2", description="load inertia")
    motor = Inertia(J=ac.ref("J_m"), phi={"start": 0.0, "fixed": True},
                    w={"start": 0.0, "fixed": True})
    # the gear's impact law needs the inertias on its flanges: bound to the same values
    gear = GearWithBacklash(n=5.0, delta=0.01, J_a=ac.ref("J_m"), J_b=ac.ref("J_L"))
    load = Inertia(J=ac.ref("J_L"), phi={"start": 0.0, "fixed": True},
                   w={"start": 0.0, "fixed": True})
    drive = Torque()
    square = Pulse(amplitude=1.0, width=50.0, period=0.4, offset=-0.5)

    def equations(self):
        return [ac.connect(self.square.y, self.drive.tau),
                ac.connect(self.drive.flange, self.motor.flange_a),
                ac.connect(self.motor.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.load.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(RigidBacklashDrive(), t_end=RigidBacklashDrive.stop_time, rtol=1e-8,
                      max_step=0.05)
    print(f"{len(res.events)} events; load speed at t_end {res['load.w'][-1]:.6f} rad/s; "
          f"max |phi_rel| = {abs(res['gear.phi_rel']).max():.12f} rad")
