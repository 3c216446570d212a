"""The pneumatic spring: masses on a column of air (Egeland & Gravdahl 14.4.5 and
14.5.9, (14.97)-(14.107), (14.144)-(14.150)).

A vertical cylinder of area A = 0.01 m2 holds air, isentropic (kappa = 1.4), at
p_0 = 2e5 Pa when the piston is at x_0 = 1 m; a mass m = 200 kg sits on the piston,
g = 10 m/s2, so m g = A p_0 and x = 1 m is the equilibrium:

    p = p_0 (x_0/x)^kappa,   m x'' = A p - m g             (14.98)-(14.100)

small oscillations at omega_0 = sqrt(g kappa) = 3.74 rad/s (14.104).  The stiff variant
splits the mass in m_1 = m_2 = 100 kg joined by a spring K = m_1 omega_2^2/2,
omega_2 = 1000 rad/s (Figure 14.19, (14.144)-(14.145)): eigenvalues +-j3.7 and
+-j1000 (14.149)-(14.150).  The chamber is a ``PneumaticCylinder`` with its port left
closed; its pressure is a state, and the gas mass it keeps adds a zero eigenvalue.
"""
import acausal as ac
from acausal.library import translational as tr

from ..volumes import PneumaticCylinder

__all__ = ["PneumaticSpring", "TwoMassPneumaticSpring", "A", "M", "KAPPA", "P_0", "G",
           "M_1", "M_2", "OMEGA_2", "K"]

A, M, KAPPA, P_0, G = 0.01, 200.0, 1.4, 2e5, 10.0
M_1 = M_2 = 100.0
OMEGA_2 = 1000.0
K = M_1 * OMEGA_2**2 / 2
X_START = 1.2          # the piston starts 0.2 m above the equilibrium, at rest


def _cylinder(x):
    """The closed isentropic chamber of (14.98), V = A x, started at the pressure of x."""
    return PneumaticCylinder(A=A, V_0=0.0, n=KAPPA, p_0=P_0, rho_0=2.4,
                             p={"start": P_0 * x**-KAPPA, "fixed": True})


class PneumaticSpring(ac.Component):
    """One mass m = 200 kg on the air column, released at x = 1.2 m (14.100)."""

    stop_time = 10.0
    cylinder = _cylinder(X_START)
    load = tr.Mass(m=M, s={"start": X_START, "fixed": True}, v={"start": 0.0, "fixed": True})
    gravity = tr.ConstantForce(f_constant=-M * G)

    def equations(self):
        return [ac.connect(self.cylinder.flange, self.load.flange_a),
                ac.connect(self.load.flange_b, self.gravity.flange)]


class TwoMassPneumaticSpring(ac.Component):
    """m_1 on the air column, m_2 on a spring K = m_1 omega_2^2/2 above it (Figure 14.19);
    released with x_1 = 1.2 m and the spring 1e-4 m longer than at equilibrium."""

    stop_time = 0.5
    cylinder = _cylinder(X_START)
    mass_1 = tr.Mass(m=M_1, s={"start": X_START, "fixed": True},
                     v={"start": 0.0, "fixed": True})
    spring = tr.Spring(c=K)          # x_1 = x_2 unloaded: the book's offset of x_2
    mass_2 = tr.Mass(m=M_2, s={"start": X_START - M_2 * G / K + 1e-4, "fixed": True},
                     v={"start": 0.0, "fixed": True})
    gravity_1 = tr.ConstantForce(f_constant=-M_1 * G)
    gravity_2 = tr.ConstantForce(f_constant=-M_2 * G)

    def equations(self):
        return [ac.connect(self.cylinder.flange, self.mass_1.flange_a),
                ac.connect(self.mass_1.flange_b, self.spring.flange_a, self.gravity_1.flange),
                ac.connect(self.spring.flange_b, self.mass_2.flange_a),
                ac.connect(self.mass_2.flange_b, self.gravity_2.flange)]


if __name__ == "__main__":
    sys = ac.linearize(TwoMassPneumaticSpring(),
                       at={"mass_1.s": 1.0, "mass_2.s": 1.0 - M_2 * G / K, "cylinder.p": P_0})
    print("eigenvalues at x* = 1:", sorted(sys.poles(), key=abs))
    res = ac.simulate(PneumaticSpring(), t_end=PneumaticSpring.stop_time, rtol=1e-8)
    print(f"one mass: x in [{res['load.s'].min():.4f}, {res['load.s'].max():.4f}] m")
