"""Utilities of the rotational examples (Modelica.Mechanics.Rotational.Examples
.Utilities, MSL v4.0.0): an inertia, a spring and a spring-damper as blocks with signal
inputs and outputs, the way a model is exported as an FMU.
"""
import acausal as ac
from acausal.library.rotational import Inertia, Spring as SpringElement, Torque
from acausal.library.rotational.adaptors import AngleToTorqueAdaptor, TorqueToAngleAdaptor
from acausal.library.rotational.interfaces import PartialCompliant
from acausal.library.thermal.conditional import PartialElementaryConditionalHeatPortWithoutT
from acausal.ports import RealInput, RealOutput

__all__ = ["DirectInertia", "InverseInertia", "Spring", "SpringDamper",
           "SpringDamperNoRelativeStates"]


class DirectInertia(ac.Component):
    """Input/output block of a direct inertia model (MSL Examples.Utilities
    .DirectInertia): the torque tauDrive accelerates the inertia, against the torque
    tau its other side receives; phi, w, a are its motion."""

    J = ac.Parameter(1.0, unit="kg.m2", min=0, description="inertia")
    tauDrive = RealInput()
    tau = RealInput()
    phi = RealOutput()
    w = RealOutput()
    a = RealOutput()
    inertia = Inertia(J=ac.ref("J"), phi={"start": 0.0, "fixed": True},
                      w={"start": 0.0, "fixed": True})
    torqueSource = Torque()
    torqueToAngle = TorqueToAngleAdaptor()

    def equations(self):
        return [ac.connect(self.tauDrive, self.torqueSource.tau),
                ac.connect(self.torqueSource.flange, self.inertia.flange_a),
                ac.connect(self.inertia.flange_b, self.torqueToAngle.flange),
                ac.connect(self.torqueToAngle.phi, self.phi),
                ac.connect(self.torqueToAngle.w, self.w),
                ac.connect(self.torqueToAngle.a, self.a),
                ac.connect(self.tau, self.torqueToAngle.tau)]


class Spring(ac.Component):
    """Input/output block of a spring model (MSL Examples.Utilities.Spring): the angles
    phi1, phi2 of its flanges in, the torques tau1, tau2 needed to move them out."""

    c = ac.Parameter(1e4, unit="N.m/rad", description="spring constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")
    phi1 = RealInput()
    phi2 = RealInput()
    tau1 = RealOutput()
    tau2 = RealOutput()
    angleToTorque1 = AngleToTorqueAdaptor(use_w=False, use_a=False)
    spring = SpringElement(c=ac.ref("c"), phi_rel0=ac.ref("phi_rel0"))
    angleToTorque2 = AngleToTorqueAdaptor(use_w=False, use_a=False)

    def equations(self):
        return [ac.connect(self.angleToTorque1.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.angleToTorque2.flange),
                ac.connect(self.phi1, self.angleToTorque1.phi),
                ac.connect(self.tau1, self.angleToTorque1.tau),
                ac.connect(self.angleToTorque2.phi, self.phi2),
                ac.connect(self.angleToTorque2.tau, self.tau2)]


class InverseInertia(ac.Component):
    """Input/output block of an inverse inertia model (MSL Examples.Utilities
    .InverseInertia): the angle, speed and acceleration in, the torque that moves the
    inertia so out."""

    J = ac.Parameter(1.0, unit="kg.m2", description="inertia")
    phi = RealInput()
    w = RealInput()
    a = RealInput()
    tau = RealOutput()
    inertia = Inertia(J=ac.ref("J"), phi={"start": 0.0}, w={"start": 0.0})
    angleToTorque = AngleToTorqueAdaptor()

    def equations(self):
        return [ac.connect(self.angleToTorque.flange, self.inertia.flange_a),
                ac.connect(self.phi, self.angleToTorque.phi),
                ac.connect(self.w, self.angleToTorque.w),
                ac.connect(self.a, self.angleToTorque.a),
                ac.connect(self.tau, self.angleToTorque.tau)]


class SpringDamperNoRelativeStates(PartialCompliant,
                                   PartialElementaryConditionalHeatPortWithoutT):
    """Linear spring and damper in parallel whose relative angle and speed are not
    states (MSL Examples.Utilities.SpringDamperNoRelativeStates; no a_rel = der(w_rel),
    so an FMU of it needs no accelerations as inputs):

        w_rel = der(phi_rel),   tau_c = c (phi_rel - phi_rel0),   tau_d = d w_rel
        tau = tau_c + tau_d,    lossPower = tau_d w_rel
    """

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")
    w_rel = ac.Variable(start=0.0, unit="rad/s",
                        description="relative angular velocity (= der(phi_rel))")
    tau_c = ac.Variable(unit="N.m", description="spring torque")
    tau_d = ac.Variable(unit="N.m", description="damping torque")

    def equations(self):
        return [ac.Eq(self.w_rel, ac.der(self.phi_rel)),
                ac.Eq(self.tau_c, self.c * (self.phi_rel - self.phi_rel0)),
                ac.Eq(self.tau_d, self.d * self.w_rel),
                ac.Eq(self.tau, self.tau_c + self.tau_d),
                ac.Eq(self.lossPower, self.tau_d * self.w_rel)]


class SpringDamper(ac.Component):
    """Input/output block of a spring/damper model (MSL Examples.Utilities
    .SpringDamper): the angles and speeds of its flanges in, the torques needed to move
    them out."""

    c = ac.Parameter(1e4, unit="N.m/rad", description="spring constant")
    d = ac.Parameter(1.0, unit="N.m.s/rad", description="damping constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")
    phi1 = RealInput()
    w1 = RealInput()
    tau1 = RealOutput()
    phi2 = RealInput()
    w2 = RealInput()
    tau2 = RealOutput()
    angleToTorque1 = AngleToTorqueAdaptor(use_a=False)
    springDamper = SpringDamperNoRelativeStates(c=ac.ref("c"), d=ac.ref("d"),
                                                phi_rel0=ac.ref("phi_rel0"))
    angleToTorque2 = AngleToTorqueAdaptor(use_a=False)

    def equations(self):
        return [ac.connect(self.springDamper.flange_b, self.angleToTorque2.flange),
                ac.connect(self.angleToTorque1.flange, self.springDamper.flange_a),
                ac.connect(self.phi1, self.angleToTorque1.phi),
                ac.connect(self.w1, self.angleToTorque1.w),
                ac.connect(self.tau1, self.angleToTorque1.tau),
                ac.connect(self.angleToTorque2.phi, self.phi2),
                ac.connect(self.w2, self.angleToTorque2.w),
                ac.connect(self.angleToTorque2.tau, self.tau2)]
