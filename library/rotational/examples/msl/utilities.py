"""Utilities of the rotational examples (Modelica.Mechanics.Rotational.Examples
.Utilities, MSL v4.0.0): an inertia and a spring as blocks with signal inputs and
outputs, the way a model is exported as an FMU.

``InverseInertia`` and ``SpringDamper``, which take speeds and accelerations as inputs,
need an AngleToTorqueAdaptor with use_w/use_a, which the language cannot express yet
(see ``acausal.library.rotational.adaptors``).
"""
import acausal as ac
from acausal.ports import RealInput, RealOutput
from acausal.library.rotational import Inertia, Spring as SpringElement, Torque
from acausal.library.rotational.adaptors import AngleToTorqueAdaptor, TorqueToAngleAdaptor

__all__ = ["DirectInertia", "Spring"]


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
