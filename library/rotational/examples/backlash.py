"""Motor and load coupled by an elastic gear with a dead zone (Egeland & Gravdahl 3.6.2).

    J_m theta_m'' = T_m - T_gm,   J_L theta_L'' = T_gL,   phi = theta_m - theta_L/n_b
    T_gm = K (phi + delta) | 0 | K (phi - delta),   T_gL = T_gm/n_b          (3.116)-(3.119)

The motor starts spinning and the load at rest: the gear crosses the dead zone, the
teeth hit and bounce, an event at every |phi| = delta.  Without damping the energy
J_m w_m^2/2 + J_L w_L^2/2 + K (|phi| - delta)^2/2 (outside the dead zone) is conserved.
"""
import acausal as ac
from acausal.library.rotational import ElasticGearWithDeadzone, Inertia

__all__ = ["GearWithDeadzone"]


class GearWithDeadzone(ac.Component):
    """J_m = 0.01, J_L = 0.5 kg m^2, n = 5 (n_b = 0.2), K = 100 N m/rad, delta = 0.05 rad."""

    stop_time = 0.5
    motor = Inertia(J=0.01, phi={"start": 0.0, "fixed": True}, w={"start": 5.0, "fixed": True})
    gear = ElasticGearWithDeadzone(n=5.0, K=100.0, delta=0.05)
    load = Inertia(J=0.5, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.motor.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.load.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(GearWithDeadzone(), t_end=GearWithDeadzone.stop_time, rtol=1e-8)
    print(f"{len(res.events)} events; load speed at t_end {res['load.w'][-1]:.5f} rad/s")
