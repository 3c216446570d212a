"""Modelica.Mechanics.Translational.Examples.HeatLosses (MSL v4.0.0): the losses of a
chain of masses leave through heat ports.

Every dissipating element (dampers, spring-dampers, an elasto-gap, support friction, a
brake and a mass with stops and friction) has its heat port enabled; the ports meet
at a convection element (Gc = 20 W/K) to an ambient at 25 degC, whose heat flow is the
total loss.

The dampers, spring-dampers and the elasto-gap keep the MSL's default
``stateSelect=StateSelect.prefer`` (``stateSelect="prefer"`` here, whose default is
"default"): their relative position and speed are states.  It matters at the hard stop
of massWithStopAndFriction (t = 0.4285 s), whose ``reinit(v, 0)`` then leaves
springDamper1's relative speed as it was, so that mass3 stops with the mass, as in the
reference; with mass3's own speed as a state, the reinit leaves mass3 moving at
0.68 m/s into the stiff springDamper1 (d = 1000 N.s/m), which compresses it by a further
0.68 mm, and the chain downstream differs (springDamper1.s_rel by 0.47 x amplitude).
"""
import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Constant, Sine
from acausal.library.thermal import Convection
from acausal.library.thermal.celsius import FixedTemperature

__all__ = ["HeatLosses"]


class HeatLosses(ac.Component):
    """Masses of 1 kg and length 0.1 m; springDamper c = 100 N/m, d = 10 N.s/m;
    elastoGap c = 100 N/m, d = 20 N.s/m, s_rel0 = -0.02 m; brake fn_max = 10 N pressed by
    a 10-unit 2 Hz sine; a mass with friction between stops at 0 and 0.4 m."""

    msl_name = "Modelica.Mechanics.Translational.Examples.HeatLosses"
    stop_time = 2.0
    tolerance = 1e-6

    mass1 = tr.Mass(m=1.0, s={"fixed": True}, L=0.1, v={"fixed": True})
    # stateSelect="prefer" is the MSL's default (module docstring)
    springDamper = tr.SpringDamper(s_rel={"fixed": True}, v_rel={"fixed": True}, c=100.0,
                                   d=10.0, useHeatPort=True, stateSelect="prefer")
    damper = tr.Damper(d=10.0, useHeatPort=True, stateSelect="prefer")
    elastoGap = tr.ElastoGap(c=100.0, d=20.0, s_rel0=-0.02, useHeatPort=True,
                             stateSelect="prefer")
    fixed1 = tr.Fixed()
    force = tr.Force()
    sine1 = Sine(f=1.0, amplitude=20.0)
    mass2 = tr.Mass(m=1.0, L=0.1, s={"fixed": False}, v={"fixed": False})
    supportFriction = tr.SupportFriction(useHeatPort=True)
    spring = tr.Spring(c=100.0, s_rel={"fixed": True})
    mass3 = tr.Mass(m=1.0, L=0.1, s={"fixed": False}, v={"fixed": True})
    brake = tr.Brake(fn_max=10.0, useHeatPort=True)
    sine2 = Sine(amplitude=10.0, f=2.0)
    massWithStopAndFriction = tr.MassWithStopAndFriction(
        L=0.1, m=1.0, F_prop=0.5, F_Coulomb=1.0, F_Stribeck=2.0, fexp=2.0, smin=0.0,
        smax=0.4, v={"fixed": True}, useHeatPort=True)
    convection = Convection()
    const = Constant(k=20.0)
    TAmbient = FixedTemperature(T=25.0)
    fixed2 = tr.Fixed()
    springDamper1 = tr.SpringDamper(c=10000.0, d=1000.0, useHeatPort=True,
                                    s_rel={"fixed": True}, stateSelect="prefer")

    def equations(self):
        solid = self.convection.solid
        return [ac.connect(self.mass1.flange_b, self.springDamper.flange_a),
                ac.connect(self.sine1.y, self.force.f),
                ac.connect(self.force.flange, self.mass1.flange_a),
                ac.connect(self.mass1.flange_a, self.damper.flange_a),
                ac.connect(self.damper.flange_b, self.fixed1.flange),
                ac.connect(self.springDamper.flange_b, self.mass2.flange_a),
                ac.connect(self.mass2.flange_b, self.supportFriction.flange_a),
                ac.connect(self.supportFriction.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass3.flange_a),
                ac.connect(self.mass3.flange_b, self.brake.flange_a),
                ac.connect(self.sine2.y, self.brake.f_normalized),
                ac.connect(self.elastoGap.flange_b, self.mass1.flange_a),
                ac.connect(self.const.y, self.convection.Gc),
                ac.connect(self.TAmbient.port, self.convection.fluid),
                ac.connect(self.elastoGap.flange_a, self.fixed2.flange),
                ac.connect(self.elastoGap.heatPort, solid),
                ac.connect(self.damper.heatPort, solid),
                ac.connect(self.springDamper.heatPort, solid),
                ac.connect(self.supportFriction.heatPort, solid),
                ac.connect(self.brake.heatPort, solid),
                ac.connect(self.massWithStopAndFriction.heatPort, solid),
                ac.connect(self.brake.flange_b, self.springDamper1.flange_a),
                ac.connect(self.springDamper1.flange_b,
                           self.massWithStopAndFriction.flange_a),
                ac.connect(self.springDamper1.heatPort, solid)]


if __name__ == "__main__":
    res = ac.simulate(HeatLosses(), t_end=HeatLosses.stop_time, rtol=HeatLosses.tolerance)
    print(f"convection.Q_flow at {res.t[-1]:g} s: {res['convection.Q_flow'][-1]:.6g} W")
