"""Stick-slip: a block on a rough floor pulled through a spring whose end moves at
constant speed V (Egeland & Gravdahl 5.2.5-5.2.6, Karnopp friction).

The block sticks (v = 0) until the spring force k (V t - x) reaches F_s, the first time
at t_1 = F_s / (k V); it then slides against the Stribeck curve (5.13),

    m x'' = k (V t - x) - [F_c + (F_s - F_c) exp(-(v/v_s)^2)] - F_v v,

until it stops, and sticks again until the spring force is back at F_s.
"""
import acausal as ac
from acausal.library import translational as tr

from ..translational import KarnoppFriction

__all__ = ["StickSlip"]


class StickSlip(ac.Component):
    """m = 1 kg, k = 97 N/m, V = 0.113 m/s, F_c = 1 N, F_s = 1.5 N, v_s = 0.01 m/s,
    F_v = 0.2 N s/m."""

    stop_time = 1.5
    ground = tr.Fixed()
    friction = KarnoppFriction(F_c=1.0, F_s=1.5, v_s=0.01, F_v=0.2, dv=1e-9)
    block = tr.Mass(m=1.0, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    spring = tr.Spring(c=97.0)
    puller = tr.ConstantSpeed(v_fixed=0.113, s={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.ground.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.block.flange_a),
                ac.connect(self.block.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.puller.flange)]


if __name__ == "__main__":
    res = ac.simulate(StickSlip(), t_end=StickSlip.stop_time, rtol=1e-8, max_step=1e-2)
    print(f"{len(res.events)} events; block at {res['block.s'][-1]:.5f} m")
