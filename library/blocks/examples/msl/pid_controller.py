"""Modelica.Blocks.Examples.PID_Controller (MSL v4.0.0): a PI controller (LimPID, k =
100, Ti = 0.1 s, output limited to +-12 N.m, Ni = 0.1) drives an inertia through a torque
source to follow the speed of a point-to-point move (KinematicPTP, integrated to a speed
reference) of 90 degrees from 0.5 s, while a stiff spring-damper couples a second
inertia loaded by a constant 10 N.m.  The limiter is active in the run, and the
anti-windup keeps the integrator from winding up.

The MSL initializes the controller in steady state (LimPID initType = SteadyState: the
integrator's der(y) = 0) and the drive in steady state (der(spring.w_rel) = 0, with
inertia1's angle and acceleration and the spring's w_rel fixed at 0): here the
controller's steady state is the model's initial equation der(PI.I.x) = 0.
"""
import math

import acausal as ac
from acausal.library.blocks import Integrator, KinematicPTP, LimPID
from acausal.library.rotational import ConstantTorque, Inertia, SpeedSensor, SpringDamper, Torque

from . import MSLNames

__all__ = ["PID_Controller"]


class PID_Controller(ac.Component):
    """Demonstrates the usage of a Continuous.LimPID controller."""

    msl_name = "Modelica.Blocks.Examples.PID_Controller"
    stop_time = 4.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    driveAngle = ac.Parameter(1.570796326794897, unit="rad",
                              description="reference distance to move")
    PI = LimPID(controllerType="PI", k=100.0, Ti=0.1, yMax=12.0, Ni=0.1, Td=0.1)
    inertia1 = Inertia(J=1.0, phi={"fixed": True, "start": 0.0},
                       a={"fixed": True, "start": 0.0})
    torque = Torque()
    spring = SpringDamper(c=1e4, d=100.0, stateSelect="prefer", w_rel={"fixed": True})
    inertia2 = Inertia(J=2.0)
    kinematicPTP = KinematicPTP(startTime=0.5, deltaq=[math.pi / 2], qd_max=[1.0],
                                qdd_max=[1.0])
    integrator = Integrator(x={"start": 0.0, "fixed": True})
    speedSensor = SpeedSensor()
    loadTorque = ConstantTorque(tau_constant=10.0)

    def initial_equations(self):
        return [ac.Eq(ac.der(self.spring.w_rel), 0), ac.Eq(ac.der(self.PI.I.x), 0)]

    def equations(self):
        return [ac.connect(self.spring.flange_b, self.inertia2.flange_a),
                ac.connect(self.inertia1.flange_b, self.spring.flange_a),
                ac.connect(self.torque.flange, self.inertia1.flange_a),
                ac.connect(self.kinematicPTP.y[0], self.integrator.u),
                ac.connect(self.speedSensor.flange, self.inertia1.flange_b),
                ac.connect(self.loadTorque.flange, self.inertia2.flange_b),
                ac.connect(self.PI.y, self.torque.tau),
                ac.connect(self.speedSensor.w, self.PI.u_m),
                ac.connect(self.integrator.y, self.PI.u_s)]
