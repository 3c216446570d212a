"""Mechanical, thermal, control and chemical systems written from their published
descriptions, as a user new to acausal writes them.  References are in
``test_outsider_models.py``.

* ``First``: Modelica.Mechanics.Rotational.Examples.First (a 10 N.m, 5 Hz sine torque on
  a 0.1 kg.m2 motor, an ideal gear of ratio 10, a 2 kg.m2 inertia on a 1e4 N.m/rad
  spring to a 2 kg.m2 load, a 10 N.m.s/rad damper to the housing).
* ``InitialConditions``: Modelica.Mechanics.Translational.Examples.InitialConditions
  (initial values given on the springs' relative positions, not on the masses).
* ``DamperExample``: Modelica.Mechanics.Translational.Examples.Damper (a mass at 10 m/s
  stopped by a damper, another by a spring-damper).
* ``RollingWheel``: a constant force pulls a mass that rolls a wheel (``IdealRollingWheel``)
  with an inertia.
* ``TwoMasses``: Modelica.Thermal.HeatTransfer.Examples.TwoMasses.
* ``MotorThermal`` / ``MotorThermalSteady``: after
  Modelica.Thermal.HeatTransfer.Examples.Motor: winding and core losses from a time table
  into two heat capacitances, a conductance between them and convection to the ambient;
  the second starts in equilibrium (initial equations der(T) = 0).
* ``SpeedControl``: after Modelica.Blocks.Examples.PID_Controller: a limited PID with
  anti-windup drives an inertia with viscous loss to a speed step.
* ``CriticalFilter``: a third-order low pass 1/(0.001 s^3 + 0.03 s^2 + 0.3 s + 1) as a
  ``TransferFunction`` on a unit step.
* ``SaturatedLoop``: an algebraic loop through a limiter, y = sat(u - y/2), no state.
* ``LeadLag``: (s + 1)/(0.1 s + 1) on a step at 0.1 s, a transfer function with direct
  feedthrough.
* ``CartesianPendulum``: the planar pendulum in Cartesian coordinates with its Lagrange
  multiplier (the index-3 DAE of every DAE textbook).
* ``TorqueSliderCrank``: a slider-crank (crank r = 0.1 m with a hub inertia, a 0.3 m
  uniform rod of 0.5 kg, a 0.8 kg slider on a horizontal guide, gravity) spun up from
  rest by a constant 0.5 N.m on the crank, from planar multibody parts: a closed loop
  with no cut joint.
* ``Robertson``: Robertson's reaction kinetics with the mass balance as the algebraic
  equation (Hairer & Wanner II, IV.1 and VI.1).
* ``AkzoNobel``: the chemical Akzo Nobel problem of the Test Set for IVP Solvers
  (Mazzia & Magherini), index 1, with its published y(180).
* ``Hires``: the HIRES problem of the same test set (eight reactions, arrays), with its
  published y(321.8122).
"""
import numpy as np

import acausal as ac
from acausal.library import blocks as bl
from acausal.library import multibody as mb
from acausal.library import rotational as ro
from acausal.library import thermal as th
from acausal.library import translational as tr


class First(ac.Component):
    fixed = ro.Fixed()
    sine = bl.Sine(amplitude=10.0, f=5.0)
    torque = ro.Torque()
    inertia1 = ro.Inertia(J=0.1)
    gear = ro.IdealGear(ratio=10.0)
    inertia2 = ro.Inertia(J=2.0, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    spring = ro.Spring(c=1e4)
    inertia3 = ro.Inertia(J=2.0, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    damper = ro.Damper(d=10.0)

    def equations(self):
        return [ac.connect(self.sine.y, self.torque.tau),
                ac.connect(self.torque.flange, self.inertia1.flange_a),
                ac.connect(self.inertia1.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.inertia2.flange_a),
                ac.connect(self.inertia2.flange_b, self.spring.flange_a, self.damper.flange_a),
                ac.connect(self.spring.flange_b, self.inertia3.flange_a),
                ac.connect(self.damper.flange_b, self.fixed.flange)]


class InitialConditions(ac.Component):
    fixed = tr.Fixed(s0=-1.0)
    s1 = tr.Spring(c=1e3, s_rel0=1.0, s_rel={"start": 0.5, "fixed": True})
    m1 = tr.Mass(m=1.0, v={"start": 0.0, "fixed": True})
    sd1 = tr.SpringDamper(c=111.0, d=1.0, s_rel0=1.0, s_rel={"start": 1.0, "fixed": True})
    m2 = tr.Mass(m=1.0, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.fixed.flange, self.s1.flange_a),
                ac.connect(self.s1.flange_b, self.m1.flange_a),
                ac.connect(self.m1.flange_b, self.sd1.flange_a),
                ac.connect(self.sd1.flange_b, self.m2.flange_a)]


class DamperExample(ac.Component):
    m1 = tr.Mass(m=1.0, s={"start": 3.0, "fixed": True}, v={"start": 10.0, "fixed": True})
    d1 = tr.Damper(d=25.0)
    f1 = tr.Fixed(s0=4.5)
    m2 = tr.Mass(m=1.0, s={"start": 3.0, "fixed": True}, v={"start": 10.0, "fixed": True})
    sd = tr.SpringDamper(c=1.0, d=25.0, s_rel0=1.0)
    f2 = tr.Fixed(s0=4.5)

    def equations(self):
        return [ac.connect(self.m1.flange_b, self.d1.flange_a),
                ac.connect(self.d1.flange_b, self.f1.flange),
                ac.connect(self.m2.flange_b, self.sd.flange_a),
                ac.connect(self.sd.flange_b, self.f2.flange)]


class RollingWheel(ac.Component):
    force = tr.ConstantForce(f_constant=10.0)
    mass = tr.Mass(m=2.0, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    wheel = ro.IdealRollingWheel(radius=0.25)
    J = ro.Inertia(J=0.05)

    def equations(self):
        return [ac.connect(self.force.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.wheel.flangeT),
                ac.connect(self.wheel.flangeR, self.J.flange_a)]


class TwoMasses(ac.Component):
    mass1 = th.HeatCapacitor(C=15.0, T={"start": 373.15, "fixed": True})
    mass2 = th.HeatCapacitor(C=15.0, T={"start": 273.15, "fixed": True})
    cond = th.ThermalConductor(G=10.0)

    def equations(self):
        return [ac.connect(self.mass1.port, self.cond.port_a),
                ac.connect(self.cond.port_b, self.mass2.port)]


# time [s], winding losses [W], core losses [W]
MOTOR_LOSSES = np.array([[0, 100, 50], [360, 100, 50], [360, 1000, 500], [600, 1000, 500],
                         [600, 100, 50], [1200, 100, 50]], dtype=float)
MOTOR = dict(Cw=2500.0, Cc=25000.0, Gwc=10.0, Gc=25.0, T_amb=293.15)


class MotorThermal(ac.Component):
    losses = bl.CombiTimeTable(table=MOTOR_LOSSES, columns=[2, 3])
    Pw = th.PrescribedHeatFlow()
    Pc = th.PrescribedHeatFlow()
    winding = th.HeatCapacitor(C=MOTOR["Cw"], T={"start": MOTOR["T_amb"], "fixed": True})
    core = th.HeatCapacitor(C=MOTOR["Cc"], T={"start": MOTOR["T_amb"], "fixed": True})
    Gwc = th.ThermalConductor(G=MOTOR["Gwc"])
    conv = th.Convection()
    Gc = bl.Constant(k=MOTOR["Gc"])
    amb = th.FixedTemperature(T=MOTOR["T_amb"])

    def equations(self):
        return [ac.connect(self.losses.y[0], self.Pw.Q_flow),
                ac.connect(self.losses.y[1], self.Pc.Q_flow),
                ac.connect(self.Pw.port, self.winding.port, self.Gwc.port_a),
                ac.connect(self.Pc.port, self.core.port, self.Gwc.port_b, self.conv.solid),
                ac.connect(self.conv.fluid, self.amb.port),
                ac.connect(self.Gc.y, self.conv.Gc)]


class MotorThermalSteady(MotorThermal):
    winding = th.HeatCapacitor(C=MOTOR["Cw"], T={"start": 300.0})
    core = th.HeatCapacitor(C=MOTOR["Cc"], T={"start": 300.0})

    def initial_equations(self):
        return [ac.Eq(ac.der(self.winding.T), 0), ac.Eq(ac.der(self.core.T), 0)]


PID = dict(k=100.0, Ti=0.1, Td=0.1, Nd=10.0, Tt=0.1, yMax=12.0, J=1.0, d=0.5, t_step=0.1)


class SpeedControl(ac.Component):
    ref = bl.Step(height=1.0, startTime=PID["t_step"])
    pid = bl.PID(k=PID["k"], Ti=PID["Ti"], Td=PID["Td"], Nd=PID["Nd"], yMax=PID["yMax"],
                 yMin=-PID["yMax"], Tt=PID["Tt"])
    fb = bl.Feedback()
    sensor = ro.SpeedSensor()
    torque = ro.Torque()
    J = ro.Inertia(J=PID["J"])
    loss = ro.Damper(d=PID["d"])
    fix = ro.Fixed()

    def equations(self):
        return [ac.connect(self.ref.y, self.fb.u1), ac.connect(self.sensor.w, self.fb.u2),
                ac.connect(self.fb.y, self.pid.u), ac.connect(self.pid.y, self.torque.tau),
                ac.connect(self.torque.flange, self.J.flange_a, self.sensor.flange),
                ac.connect(self.J.flange_b, self.loss.flange_a),
                ac.connect(self.loss.flange_b, self.fix.flange)]


FILTER_DEN = (0.001, 0.03, 0.3, 1.0)


class CriticalFilter(ac.Component):
    step = bl.Step(height=1.0, startTime=0.0)
    tf = bl.TransferFunction(b=[1.0], a=list(FILTER_DEN))

    def equations(self):
        return [ac.connect(self.step.y, self.tf.u)]


class SaturatedLoop(ac.Component):
    u = bl.Sine(amplitude=2.0, f=1.0)
    add = bl.Add(k1=1.0, k2=-0.5)
    lim = bl.Limiter(uMax=1.0, uMin=-1.0)

    def equations(self):
        return [ac.connect(self.u.y, self.add.u1), ac.connect(self.add.y, self.lim.u),
                ac.connect(self.lim.y, self.add.u2)]


class LeadLag(ac.Component):
    step = bl.Step(height=1.0, startTime=0.1)
    tf = bl.TransferFunction(b=[1.0, 1.0], a=[0.1, 1.0])

    def equations(self):
        return [ac.connect(self.step.y, self.tf.u)]


class CartesianPendulum(ac.Component):
    L = ac.Parameter(1.0, unit="m", min=0, description="rod length")
    g = ac.Parameter(9.81, unit="m/s2", description="gravity")
    x = ac.Variable(start=np.sin(0.5), fixed=True, unit="m")
    y = ac.Variable(start=-np.cos(0.5), unit="m")
    vx = ac.Variable(start=0.0, fixed=True, unit="m/s")
    vy = ac.Variable(start=0.0, unit="m/s")
    lam = ac.Variable(start=1.0, unit="1/s2", description="rod force per mass and length")

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.vx), ac.Eq(ac.der(self.y), self.vy),
                ac.Eq(ac.der(self.vx), -self.lam * self.x),
                ac.Eq(ac.der(self.vy), -self.lam * self.y - self.g),
                ac.Eq(self.x ** 2 + self.y ** 2, self.L ** 2)]


class Robertson(ac.Component):
    y1 = ac.Variable(start=1.0, fixed=True)
    y2 = ac.Variable(start=0.0, fixed=True)
    y3 = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(ac.der(self.y1), -0.04 * self.y1 + 1e4 * self.y2 * self.y3),
                ac.Eq(ac.der(self.y2), 0.04 * self.y1 - 1e4 * self.y2 * self.y3
                      - 3e7 * self.y2 ** 2),
                ac.Eq(self.y1 + self.y2 + self.y3, 1)]


AKZO = dict(k1=18.7, k2=0.58, k3=0.09, k4=0.42, K=34.4, klA=3.3, Ks=115.83, pCO2=0.9, H=737.0)


class AkzoNobel(ac.Component):
    y1 = ac.Variable(start=0.444, fixed=True)
    y2 = ac.Variable(start=0.00123, fixed=True)
    y3 = ac.Variable(start=0.0, fixed=True)
    y4 = ac.Variable(start=0.007, fixed=True)
    y5 = ac.Variable(start=0.0, fixed=True)
    y6 = ac.Variable(start=AKZO["Ks"] * 0.444 * 0.007)

    def equations(self):
        y1, y2, y3, y4, y5, y6 = self.y1, self.y2, self.y3, self.y4, self.y5, self.y6
        k = AKZO
        r1 = k["k1"] * y1 ** 4 * ac.sqrt(y2)
        r2 = k["k2"] * y3 * y4
        r3 = k["k2"] / k["K"] * y1 * y5
        r4 = k["k3"] * y1 * y4 ** 2
        r5 = k["k4"] * y6 ** 2 * ac.sqrt(y2)
        f_in = k["klA"] * (k["pCO2"] / k["H"] - y2)
        return [ac.Eq(ac.der(y1), -2 * r1 + r2 - r3 - r4),
                ac.Eq(ac.der(y2), -0.5 * r1 - r4 - 0.5 * r5 + f_in),
                ac.Eq(ac.der(y3), r1 - r2 + r3),
                ac.Eq(ac.der(y4), -r2 + r3 - 2 * r4),
                ac.Eq(ac.der(y5), r2 - r3 + r5),
                ac.Eq(0, k["Ks"] * y1 * y4 - y6)]


class Hires(ac.Component):
    y = ac.Variable(shape=8, start=[1, 0, 0, 0, 0, 0, 0, 0.0057], fixed=True, nominal=1e-3)

    def equations(self):
        y = self.y
        return [ac.Eq(ac.der(y[0]), -1.71 * y[0] + 0.43 * y[1] + 8.32 * y[2] + 0.0007),
                ac.Eq(ac.der(y[1]), 1.71 * y[0] - 8.75 * y[1]),
                ac.Eq(ac.der(y[2]), -10.03 * y[2] + 0.43 * y[3] + 0.035 * y[4]),
                ac.Eq(ac.der(y[3]), 8.32 * y[1] + 1.71 * y[2] - 1.12 * y[3]),
                ac.Eq(ac.der(y[4]), -1.745 * y[4] + 0.43 * y[5] + 0.43 * y[6]),
                ac.Eq(ac.der(y[5]), -280 * y[5] * y[7] + 0.69 * y[3] + 1.71 * y[4]
                      - 0.43 * y[5] + 0.69 * y[6]),
                ac.Eq(ac.der(y[6]), 280 * y[5] * y[7] - 1.81 * y[6]),
                ac.Eq(ac.der(y[7]), -280 * y[5] * y[7] + 1.81 * y[6])]


CRANK = dict(r=0.1, l=0.3, J_hub=0.01, m_rod=0.5, m_slider=0.8, tau=0.5, g=9.81, theta0=0.3)


class TorqueSliderCrank(ac.Component):
    world = mb.FixedFrame()
    drive = ro.ConstantTorque(tau_constant=CRANK["tau"])
    crank_joint = mb.Revolute(phi={"start": CRANK["theta0"], "fixed": True},
                              w={"start": 0.0, "fixed": True})
    hub = mb.Body(m=1.0, J=CRANK["J_hub"], g=CRANK["g"])
    crank = mb.FixedTranslation(rx=CRANK["r"], ry=0.0)
    pin = mb.Revolute(phi={"start": -0.4})
    rod_a = mb.FixedTranslation(rx=CRANK["l"] / 2, ry=0.0)
    rod = mb.Body(m=CRANK["m_rod"], J=CRANK["m_rod"] * CRANK["l"] ** 2 / 12, g=CRANK["g"])
    rod_b = mb.FixedTranslation(rx=CRANK["l"] / 2, ry=0.0)
    slider_joint = mb.Revolute(phi={"start": 0.1})
    slider = mb.Body(m=CRANK["m_slider"], J=0.0, g=CRANK["g"])
    guide = mb.Prismatic(ex=1.0, ey=0.0, s={"start": 0.39})

    def equations(self):
        return [ac.connect(self.drive.flange, self.crank_joint.flange),
                ac.connect(self.world.frame, self.crank_joint.frame_a, self.guide.frame_a),
                ac.connect(self.crank_joint.frame_b, self.hub.frame, self.crank.frame_a),
                ac.connect(self.crank.frame_b, self.pin.frame_a),
                ac.connect(self.pin.frame_b, self.rod_a.frame_a),
                ac.connect(self.rod_a.frame_b, self.rod.frame, self.rod_b.frame_a),
                ac.connect(self.rod_b.frame_b, self.slider_joint.frame_a),
                ac.connect(self.slider_joint.frame_b, self.slider.frame, self.guide.frame_b)]
