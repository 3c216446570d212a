"""The wheelset of the DAE notes, chapter 5, in the notes' own form: an index-3 DAE.

Coordinates q = (y, z, phi) in the track's lateral plane and the yaw psi, the spin
perturbation beta, the four profile parameters s = (s11, s21, s12, s32) and six
multipliers lambda of the contact constraints:

    M q'' + C_q^T lambda = Q(q, q', s, lambda),   M = diag(m, m, I_xx)       (5.5.1)
    I_zz psi'' = -I_yy phi' V/r_0 + M_z,   I_yy beta' = M_y                      (5.3.1)
    C(q, s) = 0                                                                (5.4.1)
    C_s^T lambda = 0                                                           (5.5.5)

C(q, s) puts each wheel's contact point on its rail's (R^1 + A^1 u^1k = u^rail) and
aligns the profiles' normals (n^railT A^1 t^1k = 0), with the profiles of section 5.2.
The notes reduce the index by hand (5.5.2)-(5.5.6); here the compiler does it.  The
forces are those of section 5.6: gravity, the suspension -k_s y, the flange with dead
band, and the creep forces of Shen, Hedrick & Elkins from the creepages printed there,
their magnitude saturating at mu N, N = |(lambda_1, lambda_2)| the normal load.  The
printed epsilon = |F| / |F~| is written as 1 - u/3 + u^2/27 (u < 3) and 1/u, the
same function without the 0/0 at zero creep.  The notes print b_A_cr under the name
b_A_cl a second time; the right wheel's contact frame is tilted by -delta.
"""
import numpy as np

import acausal as ac

from .wheelset import Wheelset

__all__ = ["WheelsetDAE"]


def _rot_x(angle):
    c, s = ac.cos(angle), ac.sin(angle)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]], dtype=object)


def _rot_z(angle):
    c, s = ac.cos(angle), ac.sin(angle)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]], dtype=object)


class WheelsetDAE(ac.Component):
    """The notes' wheelset DAE (module docstring); parameters as ``Wheelset``'s, plus
    the roll inertia and the friction coefficient.  The start values of ``s`` and
    ``lam`` are the notes' Newton guesses (section 5.7) for delta = 0.05; y, y', psi,
    psi' and beta are the given initial values, the rest follows from the constraints.
    The spin perturbation of centred running is V s_0 tan(delta) / (r_0 (r_0 - s_0
    tan(delta))) (0.70 rad/s at 100 m/s); started from 0 it gets there within
    milliseconds, through saturated creep."""

    m = Wheelset.m
    I_xx = ac.Parameter(529.8, unit="kg.m2", min=0, description="roll inertia")
    I_yy = Wheelset.I_yy
    I_zz = Wheelset.I_zz
    r_0 = Wheelset.r_0
    y_0 = Wheelset.y_0
    y_rail = Wheelset.y_rail
    R = Wheelset.R
    delta = Wheelset.delta
    V = Wheelset.V
    g = Wheelset.g
    k_s = Wheelset.k_s
    k_f = Wheelset.k_f
    y_f = Wheelset.y_f
    a_0 = Wheelset.a_0
    b_0 = Wheelset.b_0
    N_0 = Wheelset.N_0
    C_11 = Wheelset.C_11
    C_22 = Wheelset.C_22
    C_23 = Wheelset.C_23
    G = Wheelset.G
    mu = ac.Parameter(0.30, unit="1", min=0, description="friction coefficient")

    q = ac.Variable(shape=3, start=[0.001, 0.0, 0.0], fixed=[True, False, False],
                    description="y, z [m], phi [rad]")
    dq = ac.Variable(shape=3, start=0.0, fixed=[True, False, False],
                     description="y', z' [m/s], phi' [rad/s]")
    psi = ac.Variable(start=0.0, fixed=True, unit="rad", description="yaw")
    w_psi = ac.Variable(start=0.0, fixed=True, unit="rad/s", description="yaw rate")
    beta = ac.Variable(start=0.0, fixed=True, unit="rad/s", description="spin perturbation")
    s = ac.Variable(shape=4, start=[0.0295, 0.05, -0.0295, -0.05],
                    description="profile parameters s11, s21, s12, s32")
    # no unit: lam[0:4] are forces [N], lam[4:6] moments [N.m], and an array has one
    lam = ac.Variable(shape=6, start=[253.0, -5062.0, -253.0, -5062.0, 0.0, 0.0],
                      description="contact multipliers (forces, then moments)")
    u = ac.Variable(shape=2, start=0.0, min=0.0,
                    description="creep force / (mu N) before saturation, left and right")

    def _profiles(self):
        s11, s21, s12, s32 = self.s
        t, R = ac.tan(self.delta), self.R
        u11 = np.array([self.y_0 + s11, -self.r_0 + s11 * t], dtype=object)
        u12 = np.array([-self.y_0 + s12, -self.r_0 - s12 * t], dtype=object)
        u21 = np.array([self.y_rail - R * ac.sin(s21), R * (ac.cos(s21) - 1)], dtype=object)
        u32 = np.array([-self.y_rail - R * ac.sin(s32), R * (ac.cos(s32) - 1)], dtype=object)
        return u11, u12, u21, u32

    def _creep_force(self, N, xi_x, xi_y, xi_s, u):
        """(T_x, T_y) of the Shen-Hedrick-Elkins law (section 5.6), and the equation of
        u = |F~| / (mu N), a variable so that the relation u < 3 is judged on it."""
        cube_root = (N / self.N_0)**(1 / 3)                  # a = a_0 N^1/3, b = b_0 N^1/3
        ab = self.a_0 * self.b_0 * cube_root**2
        sqrt_ab = ac.sqrt(self.a_0 * self.b_0) * cube_root
        Fx = -ab * self.G * self.C_11 * xi_x
        Fy = -ab * self.G * (self.C_22 * xi_y + sqrt_ab * self.C_23 * xi_s)
        eps = ac.if_else(u < 3, 1 - u / 3 + u**2 / 27, 1 / u)
        return eps * Fx, eps * Fy, ac.Eq(u * self.mu * N, ac.sqrt(Fx**2 + Fy**2))

    def equations(self):
        y, z, phi = self.q
        dy, dz, dphi = self.dq
        s11, s21, s12, s32 = self.s
        lam, V, delta, t = self.lam, self.V, self.delta, ac.tan(self.delta)
        u11, u12, u21, u32 = self._profiles()
        A = np.array([[ac.cos(phi), -ac.sin(phi)], [ac.sin(phi), ac.cos(phi)]], dtype=object)
        J = np.array([[0, -1], [1, 0]], dtype=object)           # dA/dphi = A J
        R1 = np.array([y, self.r_0 + z], dtype=object)
        t11, t12 = np.array([1, t], dtype=object), np.array([1, -t], dtype=object)
        n21 = np.array([ac.sin(s21), -ac.cos(s21)], dtype=object)
        n32 = np.array([ac.sin(s32), -ac.cos(s32)], dtype=object)
        dn21 = np.array([ac.cos(s21), ac.sin(s21)], dtype=object)
        dn32 = np.array([ac.cos(s32), ac.sin(s32)], dtype=object)
        du21 = np.array([-self.R * ac.cos(s21), -self.R * ac.sin(s21)], dtype=object)
        du32 = np.array([-self.R * ac.cos(s32), -self.R * ac.sin(s32)], dtype=object)
        constraints = [*(R1 + A @ u11 - u21), *(R1 + A @ u12 - u32),
                       n21 @ A @ t11, n32 @ A @ t12]
        # C_q^T lambda for (y, z, phi)
        reaction = [lam[0] + lam[2], lam[1] + lam[3],
                    lam[0:2] @ (A @ J @ u11) + lam[2:4] @ (A @ J @ u12)
                    + lam[4] * (n21 @ A @ J @ t11) + lam[5] * (n32 @ A @ J @ t12)]
        # C_s^T lambda = 0 (the cone's t' = 0)
        normality = [lam[0:2] @ (A @ t11), -(lam[0:2] @ du21) + lam[4] * (dn21 @ A @ t11),
                     lam[2:4] @ (A @ t12), -(lam[2:4] @ du32) + lam[5] * (dn32 @ A @ t12)]

        N_l = ac.sqrt(lam[0]**2 + lam[1]**2)
        N_r = ac.sqrt(lam[2]**2 + lam[3]**2)
        spin = V / self.r_0 + self.beta
        T_l = self._creep_force(
            N_l, 1 + (spin * u11[1] - self.w_psi * u11[0]) / V,
            (-self.psi * V + dy - dphi * u11[1]) / (V * ac.cos(delta)),
            (self.w_psi * ac.cos(delta) - spin * ac.sin(delta)) / V, self.u[0])
        T_r = self._creep_force(
            N_r, 1 + (spin * u12[1] - self.w_psi * u12[0]) / V,
            (-self.psi * V + dy - dphi * u12[1]) / (V * ac.cos(delta)),
            (self.w_psi * ac.cos(delta) + spin * ac.sin(delta)) / V, self.u[1])
        F_cl = np.array([T_l[0], T_l[1], 0], dtype=object)     # normal load: lambda
        F_cr = np.array([T_r[0], T_r[1], 0], dtype=object)
        F_fl = np.array([0, ac.if_else(y > self.y_f, -self.k_f * (y - self.y_f), 0), 0],
                        dtype=object)
        F_fr = np.array([0, ac.if_else(y < -self.y_f, -self.k_f * (y + self.y_f), 0), 0],
                        dtype=object)
        T_A_b = _rot_z(self.psi) @ _rot_x(phi)
        F = (np.array([0, -self.k_s * y, -self.m * self.g], dtype=object)
             + T_A_b @ (F_fl + F_fr)
             + _rot_z(self.psi) @ _rot_x(phi + delta) @ F_cl
             + _rot_z(self.psi) @ _rot_x(phi - delta) @ F_cr)
        R_cl = np.array([0, u11[0], u11[1]], dtype=object)
        R_cr = np.array([0, u12[0], u12[1]], dtype=object)
        M = (np.cross(R_cl, _rot_x(delta) @ F_cl + F_fl)
             + np.cross(R_cr, _rot_x(-delta) @ F_cr + F_fr))

        gyro = self.I_yy * V / self.r_0
        Q = [F[1], F[2], gyro * self.w_psi + M[0]]
        inertia = [self.m, self.m, self.I_xx]
        return [
            ac.Eq(ac.der(self.q), self.dq),
            ac.Eq(ac.der(self.psi), self.w_psi),
            *[ac.Eq(inertia[i] * ac.der(self.dq[i]) + reaction[i], Q[i]) for i in range(3)],
            ac.Eq(self.I_zz * ac.der(self.w_psi), -gyro * dphi + M[2]),
            ac.Eq(self.I_yy * ac.der(self.beta), M[1]),
            *[ac.Eq(c, 0) for c in constraints],
            *[ac.Eq(c, 0) for c in normality],
            T_l[2], T_r[2],
        ]
