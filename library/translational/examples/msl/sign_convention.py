"""Modelica.Mechanics.Translational.Examples.SignConvention (MSL v4.0.0): the sign
conventions of forces and flanges.

Three masses are pushed by a 1 N force: at flange_a, at flange_b, and with the force's
flange on the mass's flange_b and its support on the ground; all three accelerate the
same way.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.translational import Fixed, Force, Mass

__all__ = ["SignConvention"]

_REST = {"s": {"fixed": True}, "v": {"fixed": True}}


class SignConvention(ac.Component):
    """m = 1 kg, L = 1 m; each force 1 N."""

    msl_name = "Modelica.Mechanics.Translational.Examples.SignConvention"
    stop_time = 1.0
    tolerance = 1e-6

    mass1 = Mass(L=1.0, m=1.0, **_REST)
    force1 = Force()
    constant1 = Constant(k=1.0)
    mass2 = Mass(L=1.0, m=1.0, **_REST)
    force2 = Force()
    constant2 = Constant(k=1.0)
    mass3 = Mass(L=1.0, m=1.0, **_REST)
    force3 = Force(useSupport=True)
    constant3 = Constant(k=1.0)
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.constant1.y, self.force1.f),
                ac.connect(self.constant2.y, self.force2.f),
                ac.connect(self.constant3.y, self.force3.f),
                ac.connect(self.force1.flange, self.mass1.flange_a),
                ac.connect(self.force2.flange, self.mass2.flange_b),
                ac.connect(self.mass3.flange_b, self.force3.flange),
                ac.connect(self.fixed.flange, self.force3.support)]


if __name__ == "__main__":
    res = ac.simulate(SignConvention(), t_end=SignConvention.stop_time,
                      rtol=SignConvention.tolerance)
    print(f"mass3.s at {res.t[-1]:g} s: {res['mass3.s'][-1]:.6g} m")
