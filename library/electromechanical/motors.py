"""DC motor with constant field, built by composition (Egeland & Gravdahl 3.3)."""
import acausal as ac
from acausal.ports import NegativePin, PositivePin, RealInput, RotationalFlange

from ..electrical import Ground, Inductor, OnePort, Resistor, SignalCurrent
from ..rotational import Inertia

__all__ = ["EMF", "DCMotor", "CurrentControlledDCMotor"]


class EMF(OnePort):
    """Ideal electromechanical converter (Egeland & Gravdahl 3.3.2, (3.27)-(3.28)):

        v = k w,   tau = k i,   so  v i = tau w  (power in = power out),
        w = der(flange.phi - phi_support),  flange.tau = -tau

    The electrical side is a one-port: v is the back EMF, i the armature current.
    ``EMF(useSupport=True)`` has a ``support`` flange (the stator) that takes the
    reaction, support.tau = -flange.tau, and w is the speed relative to it (MSL EMF);
    without it the stator is fixed.
    """

    k = ac.Parameter(1.0, unit="N.m/A", description="torque (= back-EMF) constant")
    flange = RotationalFlange()
    w = ac.Variable(unit="rad/s", description="shaft speed relative to the stator")
    tau = ac.Variable(unit="N.m", description="motor torque")

    energy_role = "lossless"  # v i = tau w

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange (the stator), else it is fixed")
    support = ac.Conditional(RotationalFlange(), "useSupport")

    def equations(self):
        phi_support = self.support.phi if self.useSupport else 0
        eqs = [ac.Eq(self.w, ac.der(self.flange.phi - phi_support)),
               ac.Eq(self.v, self.k * self.w),
               ac.Eq(self.tau, self.k * self.i),
               ac.Eq(self.flange.tau, -self.tau)]
        if self.useSupport:
            eqs.append(ac.Eq(self.support.tau, -self.flange.tau))
        return eqs


class DCMotor(ac.Component):
    """DC motor with constant field (Egeland & Gravdahl (3.29)-(3.31)):

        L_a di_a/dt = u_a - R_a i_a - k w,    J dw/dt = k i_a - T_L

    made of an armature resistor and inductor, an EMF and the rotor inertia.
    ``DCMotor(useSupport=True)`` mounts the stator on a ``support`` flange that takes the
    reaction torque (a motor on a moving or elastic housing; MSL machines' useSupport).
    """

    R = ac.Parameter(1.0, unit="Ohm", description="armature resistance R_a")
    L = ac.Parameter(1e-3, unit="H", description="armature inductance L_a")
    k = ac.Parameter(0.05, unit="N.m/A", description="motor constant K_T = K_E")
    J = ac.Parameter(1e-4, unit="kg.m2", description="rotor inertia J_m")
    p = PositivePin()
    n = NegativePin()
    flange = RotationalFlange()
    Ra = Resistor(R=ac.ref("R"))
    La = Inductor(L=ac.ref("L"))
    emf = EMF(k=ac.ref("k"))
    rotor = Inertia(J=ac.ref("J"))

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange (the stator), else it is fixed")
    support = ac.Conditional(RotationalFlange(), "useSupport")

    def build(self):
        if self.useSupport:     # the stator reaction goes through the EMF's support
            self.emf = EMF(k=ac.ref("k"), useSupport=True)

    def equations(self):
        eqs = [ac.connect(self.p, self.Ra.p),
               ac.connect(self.Ra.n, self.La.p),
               ac.connect(self.La.n, self.emf.p),
               ac.connect(self.emf.n, self.n),
               ac.connect(self.emf.flange, self.rotor.flange_a),
               ac.connect(self.rotor.flange_b, self.flange)]
        if self.useSupport:
            eqs.append(ac.connect(self.emf.support, self.support))
        return eqs


class CurrentControlledDCMotor(ac.Component):
    """DC motor whose armature current is imposed by an ideal current loop (Egeland &
    Gravdahl 3.4.2, (3.58)-(3.59): with K_i -> infinity, i_a = i_d), so

        J dw/dt = k i_d - T_L

    The armature circuit is kept (a DCMotor fed by a current source), so the armature
    voltage the drive must deliver, u_a = R i_d + L di_d/dt + k w, is in the result as
    ``u_a``; L > 0 differentiates i_d, which must then be a differentiable signal.
    """

    R = ac.Parameter(1.0, unit="Ohm", description="armature resistance R_a")
    L = ac.Parameter(1e-3, unit="H", description="armature inductance L_a")
    k = ac.Parameter(0.05, unit="N.m/A", description="motor constant K_T = K_E")
    J = ac.Parameter(1e-4, unit="kg.m2", description="rotor inertia J_m")
    i_d = RealInput()
    flange = RotationalFlange()
    u_a = ac.Variable(unit="V", description="armature voltage delivered by the drive")
    drive = SignalCurrent()
    # the imposed current is not a state: the rotor's angle and speed are
    motor = DCMotor(R=ac.ref("R"), L=ac.ref("L"), k=ac.ref("k"), J=ac.ref("J"),
                    La={"i": {"state_select": "avoid"}},
                    rotor={"phi": {"state_select": "prefer"}, "w": {"state_select": "prefer"}})
    ground = Ground()

    def equations(self):
        # the source's current flows from p to n inside it, i.e. into motor.n: reverse it
        return [ac.connect(self.i_d, self.drive.i),
                ac.connect(self.drive.n, self.motor.p),
                ac.connect(self.drive.p, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.flange),
                ac.Eq(self.u_a, self.motor.p.v - self.motor.n.v)]
