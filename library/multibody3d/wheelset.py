"""A railway wheelset on straight track: lateral displacement and yaw, linear creep.

Source: the DAE notes, chapter 5 ("Wheelset", the German BA004 wheelset with conical
wheels on circular rails, Cooperrider's suspension and flange).  The notes write the
full model as an index-3 DAE: the wheelset coordinates q = (y, z, phi, psi) and the
spin perturbation beta (5.3.1), two wheel-rail contacts (5.4.1) with the profile
parameters s = (s11, s21, s12, s32), multipliers for the normal forces (5.5.1), and the
nonlinear creep law of Shen, Hedrick & Elkins (5.6).  What is built here is the small-
motion form of those equations about the centred running state, which is what their
stability statements are about (their figures are lost):

    m y''     = -2 f22 ((1 + r_0 sigma) y'/V - psi) - 2 f23 cos(delta)^2 psi'/V
                - (k_s + m g sigma) y + F_flange(y)
    I_zz psi'' = -2 f11 e (e psi'/V + lambda_e y/r_0) - I_yy (V/r_0) sigma y'

Taken from the notes: the profiles and their numbers (y0 = 0.75 m, rail crown at
0.79 m, R = 0.21 m, r_0 = 0.46 m, conicity delta), the gyroscopic yaw term
-I_yy phi' V/r_0 of Q (5.3.1), the creepages xi_x, xi_y, xi_s, the creep forces
F_x = -a b G C11 xi_x, F_y = -a b G (C22 xi_y + sqrt(a b) C23 xi_s) with the contact
ellipse a = a_0 (N/N_0)^(1/3), b = b_0 (N/N_0)^(1/3) and Kalker's coefficients (5.6),
the suspension F_s = -k_s y and the flange, a stiff spring k_f with dead band y_f.

Supplied here (the linearization, not printed in the notes):

* the creep law at small creepage: u -> 0 gives |F| = mu N u, eps = 1, so T = F~:
  f11 = a b G C11, f22 = a b G C22, f23 = (a b)^(3/2) G C23, with a, b at the static
  normal load N = m g / (2 cos(delta)) (the notes' lambda_0);
* the contact geometry of the notes' constraint (5.4.1), linearized in y: in the
  centred state the wheel contact lies s_0 = (y0_rail - y0_wheel) - R sin(delta)
  outward of the r_0 circle (the notes' own Newton guess, exact there), the contacts
  are e = y0_wheel + s_0 from the centre, and with h = r_0 - s_0 tan(delta) + R cos(delta)
  the roll follows phi = sigma y, sigma = tan(delta) / (y0_rail - h tan(delta)), and the
  rolling radii r_0 -+ s tan(delta) differ by 2 lambda_e y, lambda_e = tan(delta) (1 +
  h sigma) (the effective conicity; tan(delta) for a knife-edge rail without roll);
* the lateral component of the normal forces, -m g sigma y (gravitational stiffness);
  roll inertia I_xx sigma^2 (tiny), the load transfer between the wheels and the
  angle psi in the rotation matrices are second order and left out;
* beta, the spin perturbation, decouples at first order (I_yy beta' = -2 f11 r_0^2
  beta / V): it is not a state here.

The flange force -k_f (y -+ y_f) outside the dead band is kept as the notes write it,
so the model simulates the flange-limited oscillation of the unsuspended wheelset.
In the kinematic limit (f11, f22 -> infinity, k_s = 0) the motion is Klingel's
(1883): y' (1 + r_0 sigma) = V psi, psi' = -V lambda_e y / (e r_0), a sine of wavelength
L = 2 pi sqrt(r_0 e (1 + r_0 sigma) / lambda_e), Klingel's 2 pi sqrt(r_0 e / lambda)
without roll.  ``WheelsetDAE`` (``wheelset_dae``) is the notes' full index-3 form,
against which this small-motion model is checked.
"""
import numpy as np

import acausal as ac

__all__ = ["Wheelset"]


class Wheelset(ac.Component):
    """Lateral and yaw motion of a wheelset with conical wheels on circular rails, linear
    creep, lateral suspension and flange dead band (DAE notes, chapter 5; the equations
    and what is supplied are in the module docstring).  Defaults: the BA004 wheelset,
    Cooperrider's suspension and flange, delta = 0.05, V = 100 m/s."""

    m = ac.Parameter(1032.0, unit="kg", min=0, description="wheelset mass")
    I_yy = ac.Parameter(89.9, unit="kg.m2", min=0, description="spin inertia")
    I_zz = ac.Parameter(529.8, unit="kg.m2", min=0, description="yaw inertia")
    r_0 = ac.Parameter(0.46, unit="m", min=0, description="nominal rolling radius")
    y_0 = ac.Parameter(0.75, unit="m", min=0,
                       description="lateral distance of the r_0 circle from the centre")
    y_rail = ac.Parameter(0.79, unit="m", min=0,
                          description="lateral position of the rail crown centre")
    R = ac.Parameter(0.21, unit="m", min=0, description="rail crown radius")
    delta = ac.Parameter(0.05, unit="rad", min=0, max=0.5,
                         description="conicity (cone angle; the geometry needs it small)")
    V = ac.Parameter(100.0, unit="m/s", min=0, description="speed along the track")
    g = ac.Parameter(9.81, unit="m/s2", min=0, description="gravity")
    k_s = ac.Parameter(1.823e6, unit="N/m", min=0, description="lateral suspension stiffness")
    k_f = ac.Parameter(14.60e6, unit="N/m", min=0, description="flange stiffness")
    y_f = ac.Parameter(0.0091, unit="m", min=0, description="flange clearance (dead band)")
    a_0 = ac.Parameter(2.8134e-3, unit="m", min=0, description="contact semi-axis a at N_0")
    b_0 = ac.Parameter(1.6745e-3, unit="m", min=0, description="contact semi-axis b at N_0")
    N_0 = ac.Parameter(5073.0, unit="N", min=0, description="reference normal load")
    C_11 = ac.Parameter(4.8530, unit="1", min=0, description="Kalker's coefficient C11")
    C_22 = ac.Parameter(4.5548, unit="1", min=0, description="Kalker's coefficient C22")
    C_23 = ac.Parameter(2.2666, unit="1", description="Kalker's coefficient C23")
    G = ac.Parameter(8.27e10, unit="N/m2", min=0, description="shear modulus")

    # -- contact geometry of (5.4.1), linearized about the centred state ------------------
    s_0 = ac.Parameter(lambda w: w.y_rail - w.y_0 - w.R * ac.sin(w.delta), unit="m",
                       description="centred wheel contact, outward of the r_0 circle")
    e = ac.Parameter(lambda w: w.y_0 + w.s_0, unit="m",
                     description="half the distance between the contact points")
    h = ac.Parameter(lambda w: w.r_0 - w.s_0 * ac.tan(w.delta) + w.R * ac.cos(w.delta),
                     unit="m", description="wheel contact to rail crown centre, vertical")
    sigma = ac.Parameter(lambda w: ac.tan(w.delta) / (w.y_rail - w.h * ac.tan(w.delta)),
                         unit="rad/m", description="roll per lateral displacement")
    lambda_e = ac.Parameter(lambda w: ac.tan(w.delta) * (1 + w.h * w.sigma), unit="1",
                            description="effective conicity: (r_l - r_r) / (2 y)")

    # -- linear creep coefficients (Shen-Hedrick-Elkins at small creepage) ----------------
    N = ac.Parameter(lambda w: w.m * w.g / (2 * ac.cos(w.delta)), unit="N",
                     description="static normal load per wheel")
    f_11 = ac.Parameter(lambda w: w.a_0 * w.b_0 * (w.N / w.N_0)**(2 / 3) * w.G * w.C_11,
                        unit="N", description="longitudinal creep coefficient a b G C11")
    f_22 = ac.Parameter(lambda w: w.a_0 * w.b_0 * (w.N / w.N_0)**(2 / 3) * w.G * w.C_22,
                        unit="N", description="lateral creep coefficient a b G C22")
    f_23 = ac.Parameter(lambda w: (w.a_0 * w.b_0 * (w.N / w.N_0)**(2 / 3))**1.5 * w.G
                        * w.C_23, unit="N.m",
                        description="lateral/spin creep coefficient (a b)^(3/2) G C23")

    y = ac.Variable(start=0.001, fixed=True, unit="m", description="lateral displacement")
    psi = ac.Variable(start=0.0, fixed=True, unit="rad", description="yaw angle")
    v_y = ac.Variable(start=0.0, fixed=True, unit="m/s", description="lateral velocity")
    w_psi = ac.Variable(start=0.0, fixed=True, unit="rad/s", description="yaw rate")
    F_flange = ac.Variable(unit="N", description="flange force, both flanges")

    def equations(self):
        y, psi, v_y, w_psi, V = self.y, self.psi, self.v_y, self.w_psi, self.V
        left = ac.if_else(y > self.y_f, -self.k_f * (y - self.y_f), 0.0)
        right = ac.if_else(y < -self.y_f, -self.k_f * (y + self.y_f), 0.0)
        return [
            ac.Eq(ac.der(y), v_y),
            ac.Eq(ac.der(psi), w_psi),
            ac.Eq(self.F_flange, left + right),
            ac.Eq(self.m * ac.der(v_y),
                  -2 * self.f_22 * ((1 + self.r_0 * self.sigma) * v_y / V - psi)
                  - 2 * self.f_23 * ac.cos(self.delta)**2 * w_psi / V
                  - (self.k_s + self.m * self.g * self.sigma) * y + self.F_flange),
            ac.Eq(self.I_zz * ac.der(w_psi),
                  -2 * self.f_11 * self.e * (self.e * w_psi / V + self.lambda_e * y / self.r_0)
                  - self.I_yy * V / self.r_0 * self.sigma * v_y),
        ]
