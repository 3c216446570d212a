"""Modelica.Thermal.FluidHeatFlow.Examples.TestCylinder (MSL v4.0.0): two cylinder system.

Two cylinders of the default medium are joined by their flow ports.  A force (a table:
-1 N from 0.25 s to 0.5 s, else 0) pushes the piston of cylinder1 (0.1 m2); the medium
moves the piston of cylinder2 (1 m2), which carries a mass of 1 kg held by a spring
(100 N/m) and a damper (10 N.s/m) to the ground.
"""
import acausal as ac
from acausal.library.blocks import CombiTimeTable
from acausal.library.fluidheatflow import Cylinder
from acausal.library.translational import Fixed, Force, Mass, SpringDamper

__all__ = ["TestCylinder"]


class TestCylinder(ac.Component):
    """cylinder1: A = 0.1 m2, L = 10 m; cylinder2: A = 1 m2, L = 1 m; mass 1 kg."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.TestCylinder"
    stop_time = 2.0
    tolerance = 1e-6

    combiTimeTable = CombiTimeTable(table=[[0, 0], [0.25, -1], [0.5, 0], [0.75, 0]],
                                    smoothness="constant")
    force = Force()
    cylinder1 = Cylinder(A=0.1, L=10.0, s={"fixed": True, "start": 10.0 / 2},
                         T0=313.15, T0fixed=True)
    cylinder2 = Cylinder(T={"fixed": True}, A=1.0, L=1.0, T0=313.15, T0fixed=True)
    mass = Mass(m=1.0)
    springDamper = SpringDamper(s_rel0=1.0 / 2, c=100.0, s_rel={"fixed": True,
                                                                "start": 1.0 / 2},
                                v_rel={"fixed": True, "start": 0.0}, d=10.0)
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.cylinder1.flowPort, self.cylinder2.flowPort),
                ac.connect(self.force.flange, self.cylinder1.flange),
                ac.connect(self.combiTimeTable.y[0], self.force.f),
                ac.connect(self.cylinder2.flange, self.mass.flange_a),
                ac.connect(self.springDamper.flange_b, self.mass.flange_b),
                ac.connect(self.springDamper.flange_a, self.fixed.flange)]


if __name__ == "__main__":
    res = ac.simulate(TestCylinder(), t_end=TestCylinder.stop_time,
                      rtol=TestCylinder.tolerance)
    print(f"springDamper.s_rel at {res.t[-1]:g} s: {res['springDamper.s_rel'][-1]:.6g} m")
