"""Modelica.Mechanics.Translational.Examples.Accelerate (MSL v4.0.0): a mass (1 m long)
driven by an acceleration source at a constant 1 m/s2 from rest."""
import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Constant

__all__ = ["Accelerate"]


class Accelerate(ac.Component):
    """m = 1 kg, L = 1 m, a_ref = 1 m/s2."""

    msl_name = "Modelica.Mechanics.Translational.Examples.Accelerate"
    stop_time = 1.0
    tolerance = 1e-6

    accelerate = tr.Accelerate()
    mass = tr.Mass(L=1.0, m=1.0)
    constantAcc = Constant(k=1.0)

    def equations(self):
        return [ac.connect(self.accelerate.flange, self.mass.flange_a),
                ac.connect(self.constantAcc.y, self.accelerate.a_ref)]


if __name__ == "__main__":
    res = ac.simulate(Accelerate(), t_end=Accelerate.stop_time, rtol=Accelerate.tolerance)
    print(f"accelerate.s at {res.t[-1]:g} s: {res['accelerate.s'][-1]:.6g} m")
