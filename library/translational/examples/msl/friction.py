"""Modelica.Mechanics.Translational.Examples.Friction (MSL v4.0.0): Stribeck friction and
hard stops.

1) A sine force (25 N, 0.25 Hz) pushes a mass with Stribeck friction between stops at
+-25 m (never reached).  2) The same force pushes a Mass on a SupportFriction whose
table is the same Stribeck curve: it moves as the first.  3) A mass with friction
between close stops (+-0.9 m, length 1 m) starts at -5 m/s on a stiff spring: it hits
the stops.

Not yet compared with its reference: MAP-LIB compares the elements' ``mode`` (Integer)
and ``startForward``/``startBackward`` (Boolean) besides their Real signals, and the
language has no Integer or Boolean variables yet.
"""
import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Sine

from .utilities import GenerateStribeckFrictionTable

__all__ = ["Friction"]

_STRIBECK = {"F_prop": 1.0, "F_Coulomb": 5.0, "F_Stribeck": 10.0, "fexp": 2.0}


class Friction(ac.Component):
    """stop1, mass: m = 1 kg, L = 1 m, F_prop 1 N.s/m, F_Coulomb 5 N, F_Stribeck 10 N,
    fexp 2 s/m; stop2: F_Coulomb 3 N, F_Stribeck 5 N, stops at +-0.9 m, v0 = -5 m/s, on
    a spring c = 500 N/m from -1.75 m."""

    stop_time = 5.0
    tolerance = 1e-6

    stop1 = tr.MassWithStopAndFriction(L=1.0, s={"fixed": True}, v={"fixed": True},
                                       smax=25.0, smin=-25.0, m=1.0, **_STRIBECK)
    force = tr.Force()
    sineForce = Sine(amplitude=25.0, f=0.25)
    stop2 = tr.MassWithStopAndFriction(L=1.0, smax=0.9, smin=-0.9, F_Coulomb=3.0,
                                       F_Stribeck=5.0, s={"start": 0.0, "fixed": True},
                                       m=1.0, F_prop=1.0, fexp=2.0,
                                       v={"start": -5.0, "fixed": True})
    spring = tr.Spring(s_rel0=1.0, c=500.0)
    fixed2 = tr.Fixed(s0=-1.75)
    force2 = tr.Force()
    mass = tr.Mass(m=1.0, L=1.0, s={"fixed": True}, v={"fixed": True})
    supportFriction = tr.SupportFriction(
        f_pos=GenerateStribeckFrictionTable(v_max=12.0, nTable=50, **_STRIBECK))

    def equations(self):
        return [ac.connect(self.spring.flange_b, self.stop2.flange_a),
                ac.connect(self.sineForce.y, self.force.f),
                ac.connect(self.spring.flange_a, self.fixed2.flange),
                ac.connect(self.force.flange, self.stop1.flange_a),
                ac.connect(self.force2.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.supportFriction.flange_a),
                ac.connect(self.sineForce.y, self.force2.f)]


if __name__ == "__main__":
    res = ac.simulate(Friction(), t_end=Friction.stop_time, rtol=Friction.tolerance)
    print(f"stop2.s at {res.t[-1]:g} s: {res['stop2.s'][-1]:.6g} m")
