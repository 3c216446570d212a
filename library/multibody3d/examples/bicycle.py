"""The benchmark bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007), rolling
uncontrolled at a forward speed inside its self-stable range (4.29 < v < 6.02 m/s).

``BenchmarkBicycle``: the ``WhippleBicycle`` with the benchmark parameters (Table 1),
at v = 4.6 m/s, given a lean rate of 0.5 rad/s (a sideways push) and a small constant
steer torque T_delta.  The weave oscillation (period about 1.6 s) dies out, and the
bicycle settles on the steady turn the torque holds it in, M and C1 not entering it:

    (g K0 + v^2 K2) q_ss = (0, T_delta)

``python -m acausal.library.multibody3d.examples.bicycle`` simulates it and prints the
eigenvalues of the linearization at a few speeds (the paper's Table 2).
"""
import numpy as np

import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.multibody3d.bicycle import WhippleBicycle

__all__ = ["BenchmarkBicycle"]


class BenchmarkBicycle(ac.Component):
    """The benchmark bicycle at v = 4.6 m/s, started with lean rate 0.5 rad/s, with a
    constant steer torque of 0.05 N m and no lean torque."""

    stop_time = 10.0
    bike = WhippleBicycle(v=4.6, dq={"start": [0.5, 0.0], "fixed": True})
    lean_torque = Constant(k=0.0)
    steer_torque = Constant(k=0.05)

    def equations(self):
        return [ac.connect(self.lean_torque.y, self.bike.T_phi),
                ac.connect(self.steer_torque.y, self.bike.T_delta)]


if __name__ == "__main__":
    compiled = ac.compile(BenchmarkBicycle())
    res = ac.simulate(compiled, BenchmarkBicycle.stop_time, rtol=1e-8)
    print(f"lean {res['bike.phi'][-1]:.5f} rad, steer {res['bike.delta'][-1]:.5f} rad "
          f"at t = {BenchmarkBicycle.stop_time} s")
    for v in (0.0, 2.0, 4.0, 5.0, 6.0, 8.0):
        poles = np.sort_complex(ac.linearize(compiled, at={"bike.v": v}).poles())
        print(f"v = {v:4.1f} m/s:", "  ".join(f"{p:.5f}" for p in poles))
