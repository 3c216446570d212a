"""The Whipple bicycle, linearized about upright straight running at forward speed v.

Meijaard, Papadopoulos, Ruina & Schwab (2007), "Linearized dynamics equations for the
balance and steer of a bicycle: a benchmark and review", Proc. R. Soc. A 463,
1955-1982 (the DAE notes' chapter 6 follows it; their appendix is not legible, so the
formulas here are the paper's Appendix A).  Four rigid bodies -- rear wheel R, rear
frame with rider B, front frame (fork and handlebar) H, front wheel F -- knife-edge
wheels rolling without slip on a flat ground.  With q = (phi, delta), lean and steer,

    M q'' + v C1 q' + (g K0 + v^2 K2) q = f,    f = (T_phi, T_delta)

whose four matrices follow from the 25 parameters of Table 1 through the paper's
Appendix A, written here in its order and with its symbols: total mass and mass
centre (m_T, x_T, z_T), the whole bicycle's inertia about the rear contact point
(I_Txx, I_Txz, I_Tzz), the front assembly A = H + F with its mass centre and inertia
(m_A, x_A, z_A, I_Axx, I_Axz, I_Azz), its distance u_A ahead of the steer axis and
its inertias about that axis (I_All, I_Alx, I_Alz for the paper's I_A,lambda lambda,
I_A,lambda x, I_A,lambda z), the trail ratio mu, the gyrostatic coefficients S_R, S_F,
S_T and the static moment S_A, and the entries of M, K0, K2 and C1.  Axes as in the
paper: x forward, z down, so z_B < 0 for a mass above the ground; lambda is the steer
axis tilt from the vertical (pi/2 minus the head angle), c the trail, w the wheel
base.  I_Byy and I_Hyy (the pitch inertias) are parameters of Table 1 that do not
enter the linearized equations.

The defaults are the benchmark bicycle of Table 1, for which the paper prints M, C1,
K0, K2 to 14 digits (section 5) and the eigenvalues at 0-10 m/s (Table 2): self-stable
between the weave speed v_w = 4.29238253634111 m/s and the capsize speed v_c =
6.02426201538837 m/s. A speed of exactly 0 given at instantiation is a structural zero
(the v terms vanish); give a non-zero v and set 0 at run time to keep v tunable. A
nonlinear model assembled from the spatial bodies and joints would need rolling-
contact (non-holonomic) constraints, which the library does not have.
"""
import numpy as np

import acausal as ac
from acausal.ports import RealInput

__all__ = ["WhippleBicycle"]


class WhippleBicycle(ac.Component):
    """Linearized lean and steer of the Whipple bicycle, Meijaard et al. (2007),:

        M q'' + v C1 q' + (g K0 + v^2 K2) q = (T_phi, T_delta),   q = (phi, delta)

    M, C1, K0, K2 are derived parameters, computed from the benchmark's physical
    parameters by the paper's Appendix A; the defaults are Table 1.
    ``v`` is the forward speed (tunable), ``T_phi`` the lean torque (an external
    torque on the rear frame about the x-axis) and ``T_delta`` the steer torque
    (between rear frame and handlebar), as signal inputs.  ``phi`` and ``delta`` are
    the lean and steer angles (the elements of ``q``).
    """

    # -- Table 1: the 25 physical parameters (and the forward speed) ------------------
    w = ac.Parameter(1.02, unit="m", min=0, description="wheel base")
    c = ac.Parameter(0.08, unit="m", description="trail")
    lam = ac.Parameter(np.pi / 10, unit="rad", description="steer axis tilt lambda "
                       "(from the vertical: pi/2 - head angle)")
    g = ac.Parameter(9.81, unit="m/s2", min=0, description="gravity")
    v = ac.Parameter(5.0, unit="m/s", description="forward speed")
    r_R = ac.Parameter(0.3, unit="m", min=0, description="rear wheel radius")
    m_R = ac.Parameter(2.0, unit="kg", min=0, description="rear wheel mass")
    I_Rxx = ac.Parameter(0.0603, unit="kg.m2", min=0,
                         description="rear wheel inertia about a diameter (= I_Rzz)")
    I_Ryy = ac.Parameter(0.12, unit="kg.m2", min=0, description="rear wheel polar inertia")
    x_B = ac.Parameter(0.3, unit="m", description="rear body mass centre, x (forward)")
    z_B = ac.Parameter(-0.9, unit="m", description="rear body mass centre, z (down)")
    m_B = ac.Parameter(85.0, unit="kg", min=0, description="rear body and rider mass")
    I_Bxx = ac.Parameter(9.2, unit="kg.m2", min=0, description="rear body inertia xx")
    I_Byy = ac.Parameter(11.0, unit="kg.m2", min=0,
                         description="rear body inertia yy (does not enter)")
    I_Bzz = ac.Parameter(2.8, unit="kg.m2", min=0, description="rear body inertia zz")
    I_Bxz = ac.Parameter(2.4, unit="kg.m2", description="rear body inertia xz")
    x_H = ac.Parameter(0.9, unit="m", description="front frame mass centre, x (forward)")
    z_H = ac.Parameter(-0.7, unit="m", description="front frame mass centre, z (down)")
    m_H = ac.Parameter(4.0, unit="kg", min=0, description="front frame mass")
    I_Hxx = ac.Parameter(0.05892, unit="kg.m2", min=0, description="front frame inertia xx")
    I_Hyy = ac.Parameter(0.06, unit="kg.m2", min=0,
                         description="front frame inertia yy (does not enter)")
    I_Hzz = ac.Parameter(0.00708, unit="kg.m2", min=0, description="front frame inertia zz")
    I_Hxz = ac.Parameter(-0.00756, unit="kg.m2", description="front frame inertia xz")
    r_F = ac.Parameter(0.35, unit="m", min=0, description="front wheel radius")
    m_F = ac.Parameter(3.0, unit="kg", min=0, description="front wheel mass")
    I_Fxx = ac.Parameter(0.1405, unit="kg.m2", min=0,
                         description="front wheel inertia about a diameter (= I_Fzz)")
    I_Fyy = ac.Parameter(0.28, unit="kg.m2", min=0, description="front wheel polar inertia")

    # -- Appendix A: the whole bicycle T, about the rear contact point ------------------
    m_T = ac.Parameter(lambda b: b.m_R + b.m_B + b.m_H + b.m_F, unit="kg",
                       description="total mass")
    x_T = ac.Parameter(lambda b: (b.x_B * b.m_B + b.x_H * b.m_H + b.w * b.m_F) / b.m_T,
                       unit="m", description="total mass centre, x")
    z_T = ac.Parameter(lambda b: (-b.r_R * b.m_R + b.z_B * b.m_B + b.z_H * b.m_H
                                  - b.r_F * b.m_F) / b.m_T,
                       unit="m", description="total mass centre, z")
    I_Txx = ac.Parameter(lambda b: b.I_Rxx + b.I_Bxx + b.I_Hxx + b.I_Fxx + b.m_R * b.r_R**2
                         + b.m_B * b.z_B**2 + b.m_H * b.z_H**2 + b.m_F * b.r_F**2,
                         unit="kg.m2", description="total inertia xx")
    I_Txz = ac.Parameter(lambda b: b.I_Bxz + b.I_Hxz - b.m_B * b.x_B * b.z_B
                         - b.m_H * b.x_H * b.z_H + b.m_F * b.w * b.r_F,
                         unit="kg.m2", description="total inertia xz")
    # the wheels are axisymmetric: I_Rzz = I_Rxx, I_Fzz = I_Fxx
    I_Tzz = ac.Parameter(lambda b: b.I_Rxx + b.I_Bzz + b.I_Hzz + b.I_Fxx + b.m_B * b.x_B**2
                         + b.m_H * b.x_H**2 + b.m_F * b.w**2,
                         unit="kg.m2", description="total inertia zz")

    # -- the front assembly A = H + F ---------------------------------------------------
    m_A = ac.Parameter(lambda b: b.m_H + b.m_F, unit="kg",
                       description="front assembly mass")
    x_A = ac.Parameter(lambda b: (b.x_H * b.m_H + b.w * b.m_F) / b.m_A, unit="m",
                       description="front assembly mass centre, x")
    z_A = ac.Parameter(lambda b: (b.z_H * b.m_H - b.r_F * b.m_F) / b.m_A, unit="m",
                       description="front assembly mass centre, z")
    I_Axx = ac.Parameter(lambda b: b.I_Hxx + b.I_Fxx + b.m_H * (b.z_H - b.z_A)**2
                         + b.m_F * (b.r_F + b.z_A)**2,
                         unit="kg.m2", description="front assembly inertia xx")
    I_Axz = ac.Parameter(lambda b: b.I_Hxz - b.m_H * (b.x_H - b.x_A) * (b.z_H - b.z_A)
                         + b.m_F * (b.w - b.x_A) * (b.r_F + b.z_A),
                         unit="kg.m2", description="front assembly inertia xz")
    I_Azz = ac.Parameter(lambda b: b.I_Hzz + b.I_Fxx + b.m_H * (b.x_H - b.x_A)**2
                         + b.m_F * (b.w - b.x_A)**2,
                         unit="kg.m2", description="front assembly inertia zz")
    u_A = ac.Parameter(lambda b: (b.x_A - b.w - b.c) * ac.cos(b.lam) - b.z_A * ac.sin(b.lam),
                       unit="m", description="front assembly mass centre ahead of the "
                       "steer axis")
    I_All = ac.Parameter(lambda b: b.m_A * b.u_A**2 + b.I_Axx * ac.sin(b.lam)**2
                         + 2 * b.I_Axz * ac.sin(b.lam) * ac.cos(b.lam)
                         + b.I_Azz * ac.cos(b.lam)**2,
                         unit="kg.m2", description="I_A,lambda lambda: front assembly "
                         "inertia about the steer axis")
    I_Alx = ac.Parameter(lambda b: -b.m_A * b.u_A * b.z_A + b.I_Axx * ac.sin(b.lam)
                         + b.I_Axz * ac.cos(b.lam),
                         unit="kg.m2", description="I_A,lambda x")
    I_Alz = ac.Parameter(lambda b: b.m_A * b.u_A * b.x_A + b.I_Axz * ac.sin(b.lam)
                         + b.I_Azz * ac.cos(b.lam),
                         unit="kg.m2", description="I_A,lambda z")
    mu = ac.Parameter(lambda b: b.c / b.w * ac.cos(b.lam), unit="1",
                      description="trail ratio")
    S_R = ac.Parameter(lambda b: b.I_Ryy / b.r_R, unit="kg.m",
                       description="rear wheel gyrostatic coefficient")
    S_F = ac.Parameter(lambda b: b.I_Fyy / b.r_F, unit="kg.m",
                       description="front wheel gyrostatic coefficient")
    S_T = ac.Parameter(lambda b: b.S_R + b.S_F, unit="kg.m", description="S_R + S_F")
    S_A = ac.Parameter(lambda b: b.m_A * b.u_A + b.mu * b.m_T * b.x_T, unit="kg.m",
                       description="static moment of the steering")

    # -- the matrices of, as printed in --------------------------------
    M = ac.Parameter(lambda b: [
        [b.I_Txx, b.I_Alx + b.mu * b.I_Txz],
        [b.I_Alx + b.mu * b.I_Txz, b.I_All + 2 * b.mu * b.I_Alz + b.mu**2 * b.I_Tzz]],
        shape=(2, 2), unit="kg.m2", description="mass matrix")
    K0 = ac.Parameter(lambda b: [
        [b.m_T * b.z_T, -b.S_A],
        [-b.S_A, -b.S_A * ac.sin(b.lam)]],
        shape=(2, 2), unit="kg.m", description="gravity stiffness, times g")
    K2 = ac.Parameter(lambda b: [
        [0.0, (b.S_T - b.m_T * b.z_T) / b.w * ac.cos(b.lam)],
        [0.0, (b.S_A + b.S_F * ac.sin(b.lam)) / b.w * ac.cos(b.lam)]],
        shape=(2, 2), unit="kg", description="velocity stiffness, times v^2")
    C1 = ac.Parameter(lambda b: [
        [0.0, b.mu * b.S_T + b.S_F * ac.cos(b.lam) + b.I_Txz / b.w * ac.cos(b.lam)
         - b.mu * b.m_T * b.z_T],
        [-(b.mu * b.S_T + b.S_F * ac.cos(b.lam)),
         b.I_Alz / b.w * ac.cos(b.lam) + b.mu * (b.S_A + b.I_Tzz / b.w * ac.cos(b.lam))]],
        shape=(2, 2), unit="kg.m", description="velocity damping, times v")

    q = ac.Variable(shape=2, start=0.0, fixed=True, unit="rad",
                    description="lean phi and steer delta")
    dq = ac.Variable(shape=2, start=0.0, fixed=True, unit="rad/s",
                     description="lean and steer rates")
    phi = ac.Variable(unit="rad", description="lean angle (rightward positive)")
    delta = ac.Variable(unit="rad", description="steer angle (rightward positive)")
    T_phi = RealInput()
    T_delta = RealInput()

    def equations(self):
        q, dq = self.q, self.dq
        f = np.array([self.T_phi.signal, self.T_delta.signal], dtype=object)
        return [ac.Eq(ac.der(q), dq),
                ac.Eq(self.M @ ac.der(dq) + self.v * self.C1 @ dq
                      + (self.g * self.K0 + self.v**2 * self.K2) @ q, f),
                ac.Eq(self.phi, q[0]), ac.Eq(self.delta, q[1])]
