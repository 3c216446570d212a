"""Modelica.Mechanics.MultiBody.Examples.Elementary.HeatLosses (MSL v4.0.0): the losses
of three spring/damper systems leave through heat ports.

Three bodies (1 kg, 0.1 kg.m2 about each axis, centre of mass 0.2 m below frame_a)
hang from points 0.3, 0.6 and 0.9 m along the world's x: the first on a spring and a
damper, the second on a spring-damper in parallel, the third on a spring-damper in
series beside a spring; each starts at rest 0.2 m below its point, turning at 2 deg/s
about z.  The dampers' heat ports meet at a convection element (Gc = 20 W/K) to an
ambient at 25 degC.  As in ``SpringDamperSystem``, each body's free-motion states are
on a FreeMotion joint from the World.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.multibody3d import (Body, Damper, FixedTranslation, FreeMotion, Spring,
                                         SpringDamperParallel, SpringDamperSeries, World)
from acausal.library.thermal import Convection
from acausal.library.thermal.celsius import FixedTemperature

from . import MSLNames

__all__ = ["HeatLosses"]

_W_0 = [0.0, 0.0, 0.034906585039887]      # 2 deg/s about z


def _body():
    return Body(m=1.0, r_CM_1=0.0, r_CM_2=-0.2, r_CM_3=0.0, I_11=0.1, I_22=0.1, I_33=0.1)


def _free(x):
    return FreeMotion(r_rel_a={"start": [x, -0.2, 0.0], "fixed": True},
                      v_rel_a={"fixed": True}, angles_fixed=True,
                      w_rel_b={"start": _W_0, "fixed": True})


class HeatLosses(ac.Component):
    """Demonstrate the modeling of heat losses."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.HeatLosses"
    stop_time = 3.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    body1 = _body()
    freeMotion1 = _free(0.3)
    bar1 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    bar2 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    spring1 = Spring(s_unstretched=0.1, c=30.0)
    damper1 = Damper(d=2.0, useHeatPort=True)
    springDamper = SpringDamperParallel(d=2.0, c=30.0, s_unstretched=0.1, useHeatPort=True)
    body2 = _body()
    freeMotion2 = _free(0.6)
    bar3 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    springDamperSeries = SpringDamperSeries(d=2.0, c=30.0, s_unstretched=0.1,
                                            useHeatPort=True)
    body3 = _body()
    freeMotion3 = _free(0.9)
    spring = Spring(s_unstretched=0.2, c=30.0)
    const = Constant(k=20.0)
    convection = Convection()
    TAmbient = FixedTemperature(T=25.0)

    def equations(self):
        solid = self.convection.solid
        return [ac.connect(self.world.frame_b, self.bar1.frame_a, self.freeMotion1.frame_a,
                           self.freeMotion2.frame_a, self.freeMotion3.frame_a),
                ac.connect(self.freeMotion1.frame_b, self.body1.frame_a),
                ac.connect(self.freeMotion2.frame_b, self.body2.frame_a),
                ac.connect(self.freeMotion3.frame_b, self.body3.frame_a),
                ac.connect(self.bar1.frame_b, self.bar2.frame_a),
                ac.connect(self.damper1.frame_a, self.bar1.frame_b),
                ac.connect(self.spring1.frame_a, self.bar1.frame_b),
                ac.connect(self.damper1.frame_b, self.body1.frame_a),
                ac.connect(self.spring1.frame_b, self.body1.frame_a),
                ac.connect(self.bar2.frame_b, self.springDamper.frame_a),
                ac.connect(self.springDamper.frame_b, self.body2.frame_a),
                ac.connect(self.bar3.frame_b, self.springDamperSeries.frame_a),
                ac.connect(self.springDamperSeries.frame_b, self.body3.frame_a),
                ac.connect(self.bar3.frame_a, self.bar2.frame_b),
                ac.connect(self.bar3.frame_b, self.spring.frame_a),
                ac.connect(self.spring.frame_b, self.body3.frame_a),
                ac.connect(self.const.y, self.convection.Gc),
                ac.connect(self.TAmbient.port, self.convection.fluid),
                ac.connect(self.damper1.heatPort, solid),
                ac.connect(self.springDamper.heatPort, solid),
                ac.connect(self.springDamperSeries.heatPort, solid)]


if __name__ == "__main__":
    res = ac.simulate(HeatLosses(), t_end=HeatLosses.stop_time, rtol=HeatLosses.tolerance)
    print(f"convection.Q_flow at {res.t[-1]:g} s: {res['convection.Q_flow'][-1]:.6g} W")
