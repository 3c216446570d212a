"""Three inertias coupled by two clutches and braked to the housing, engaged and
released by time tables (after Modelica.Mechanics.Rotational.Examples.CoupledClutches).

    torque -> J1 -- clutch1 -- J2 -- clutch2 -- J3 -- brake -| housing

J1 spins at 6 rad/s and is driven by 30 sin(2 pi 3 t) N.m; J2 and J3 start at rest.
clutch1 closes at t = 0.1 s, clutch2 at 0.25 s, the brake at 0.45 s; clutch1 opens at
0.9 s and the brake at 1.1 s.  Each element has mu = 0.5 and peak = 1.1, so a sliding
element carries 0.5 fn_max and a stuck one holds up to 0.55 fn_max.  The run shows every
mode: sliding both ways, lock-up when a relative speed reaches zero, break-away when the
torque a stuck element must carry exceeds what it holds, and the free modes.
"""
import acausal as ac
from acausal.library.blocks import CombiTimeTable, Sine
from acausal.library.rotational import Inertia, Torque
from acausal.library.rotational.clutches import Brake, Clutch

__all__ = ["CoupledClutches", "ENGAGEMENT"]


def _closed(t_on, t_off=None, t_end=2.0):
    """f_normalized of an element closed from t_on (to t_off): jumps at both times."""
    rows = [[0.0, 0.0], [t_on, 0.0], [t_on, 1.0]]
    if t_off is not None:
        rows += [[t_off, 1.0], [t_off, 0.0]]
    return rows + [[t_end, rows[-1][1]]]


# (t_on, t_off) of clutch1, clutch2 and the brake
ENGAGEMENT = {"clutch1": (0.1, 0.9), "clutch2": (0.25, None), "brake": (0.45, 1.1)}


class CoupledClutches(ac.Component):
    """J1 = 1, J2 = 0.6, J3 = 0.35 kg.m2; fn_max = 20 N (clutch1), 15 N (clutch2),
    30 N (brake), cgeo = 1 m, mu = 0.5, peak = 1.1; J1 starts at 6 rad/s."""

    stop_time = 1.5
    J1 = Inertia(J=1.0, phi={"start": 0.0, "fixed": True}, w={"start": 6.0, "fixed": True})
    J2 = Inertia(J=0.6, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    J3 = Inertia(J=0.35, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    clutch1 = Clutch(mu_pos=[[0.0, 0.5]], peak=1.1, fn_max=20.0)
    clutch2 = Clutch(mu_pos=[[0.0, 0.5]], peak=1.1, fn_max=15.0)
    brake = Brake(mu_pos=[[0.0, 0.5]], peak=1.1, fn_max=30.0)
    drive = Torque()
    sine = Sine(amplitude=30.0, f=3.0)
    press1 = CombiTimeTable(table=_closed(*ENGAGEMENT["clutch1"]))
    press2 = CombiTimeTable(table=_closed(*ENGAGEMENT["clutch2"]))
    press3 = CombiTimeTable(table=_closed(*ENGAGEMENT["brake"]))

    def equations(self):
        return [ac.connect(self.sine.y, self.drive.tau),
                ac.connect(self.drive.flange, self.J1.flange_a),
                ac.connect(self.J1.flange_b, self.clutch1.flange_a),
                ac.connect(self.clutch1.flange_b, self.J2.flange_a),
                ac.connect(self.J2.flange_b, self.clutch2.flange_a),
                ac.connect(self.clutch2.flange_b, self.J3.flange_a),
                ac.connect(self.J3.flange_b, self.brake.flange_a),
                ac.connect(self.press1.y[0], self.clutch1.f_normalized),
                ac.connect(self.press2.y[0], self.clutch2.f_normalized),
                ac.connect(self.press3.y[0], self.brake.f_normalized)]


if __name__ == "__main__":
    res = ac.simulate(CoupledClutches(), t_end=CoupledClutches.stop_time, rtol=1e-8)
    print(f"{len(res.events)} events; w1, w2, w3 at t_end: {res['J1.w'][-1]:.6f}, "
          f"{res['J2.w'][-1]:.6f}, {res['J3.w'][-1]:.6f} rad/s")
