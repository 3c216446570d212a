"""Partial models of hydraulics (Egeland & Gravdahl ch. 4), and the orifice law they share.

A ``FluidPort`` carries the pressure p [Pa] (across) and the volume flow q [m3/s]
(through, positive into the component), so p q is the hydraulic power into it.
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import FluidPort

__all__ = ["PartialOnePort", "PartialTwoPort", "F_tr", "orifice_flow"]


class PartialOnePort(ac.Component):
    """One fluid port, named port."""

    port = FluidPort()


class PartialTwoPort(ac.Component):
    """A restriction between port_a and port_b (orifice, valve, pipe):

        dp = port_a.p - port_b.p,   q = port_a.q,   0 = port_a.q + port_b.q

    q flows from port_a to port_b through the element.
    """

    port_a = FluidPort()
    port_b = FluidPort()
    dp = ac.Variable(start=0.0, unit="Pa", nominal=1e6, description="pressure drop a -> b")
    q = ac.Variable(start=0.0, unit="m3/s", nominal=1e-4, description="flow from a to b")

    def equations(self):
        return [ac.Eq(self.dp, self.port_a.p - self.port_b.p),
                ac.Eq(self.q, self.port_a.q),
                ac.Eq(0, self.port_a.q + self.port_b.q)]


def F_tr(Re_tr, rho, nu, C_d):
    """Transition force F_tr = 9 Re_tr^2 rho nu^2 / (8 C_d^2) * pi/4  [N]
    (Egeland & Gravdahl (4.42); (4.12)/(4.14) print a stray factor pi).

    Parameters
    ----------
    Re_tr, rho, nu, C_d : float or sympy expression
        Transition Reynolds number, density [kg/m3], kinematic viscosity [m2/s],
        discharge coefficient.

    Returns
    -------
    sympy expression
        F_tr = p_tr A, the product of orifice area and pressure drop at the transition.
    """
    return 9 * Re_tr**2 * rho * nu**2 / (8 * C_d**2) * sp.pi / 4


# regularizations of the half powers, below any physical scale: a 0.1 nm square of
# area and 1 Pa of pressure drop
_A_REG = 1e-20     # m2
_DP_REG = 1.0      # Pa


def orifice_flow(A, dp, C_d, rho, nu, Re_tr):
    """Regularized orifice flow q(A, dp) (Ellman & Piche 1999; Egeland & Gravdahl 4.2.3,
    (4.13) with F_tr of (4.42)), extended as an odd function of dp:

        x = A dp / F_tr
        q = (3 nu Re_tr / 4) (sqrt(pi)/2) sqrt(A) x (3 - |x|)    |x| <= 1   (laminar)
        q = sign(dp) C_d A sqrt(2 |dp| / rho)                    |x| >= 1   (turbulent)

    The two branches and their slopes agree at |x| = 1, and the slope at dp = 0 is
    finite.

    Each branch is frozen between events, so the integrator evaluates it a little past
    the relation that guards it, and every branch is written to be finite there, with
    the sign of the law and a continuous derivative:

    * past dp = 0 (the sign guard of the laminar branch), and past |x| = 1: both
      branches are odd in dp, the turbulent one as dp (dp^2 + dp_r^2)^(-1/4) with
      dp_r = 1 Pa (relative error dp_r^2/(4 dp^2) < 1e-12 where the branch is active,
      |dp| >= F_tr/A);
    * past A = 0: ``A`` is often the frozen branch of a clipped opening, b x_v of
      b max(x_v, 0) (4.18), which goes negative until the spool's event is located.
      A^(3/2) = A sqrt(A) would be NaN there; the law continues as an odd function of
      A, A^(3/2) as A (A^2 + A_r^2)^(1/4) and |A| as (A^2 + A_r^2)^(1/2) with
      A_r = 1e-20 m2 (relative error below A_r^2/(2 A^2)), like the turbulent branch
      that is linear in A.  Its A-derivative is continuous and vanishes at A = 0 as
      the book's does, and in a four-way valve the flow of a metering edge keeps
      decreasing through zero as the spool passes centre, which is what the opposite
      edge does after the event.

    Parameters
    ----------
    A : sympy expression
        Opening area [m2], >= 0 where the law is meant (see above for A < 0).
    dp : sympy expression
        Pressure drop across the orifice [Pa].
    C_d, rho, nu, Re_tr : float or sympy expression
        Discharge coefficient, density [kg/m3], kinematic viscosity [m2/s] and
        transition Reynolds number.

    Returns
    -------
    sympy expression
        The flow q [m3/s] in the direction of dp; its branches are events.
    """
    Ftr = F_tr(Re_tr, rho, nu, C_d)
    x = A * dp / Ftr
    s = ac.if_else(dp >= 0, 1, -1)
    # the power goes inside a piecewise area (a spool that closes): the derivative of a
    # power of a Piecewise is taken as r u^r / u by sympy, 0/0 in the branch where the
    # area is identically 0
    A = sp.piecewise_fold(sp.sympify(A))
    if isinstance(A, sp.Piecewise):
        A32 = sp.Piecewise(*((_odd_three_halves(a), c) for a, c in A.args))
    else:
        A32 = _odd_three_halves(A)
    # |x| = |A| |dp| / F_tr, with |A| as sqrt(A^2 + A_r^2): even in A, like |dp| = s dp
    abs_x = s * dp * (A**2 + _A_REG**2)**sp.Rational(1, 2) / Ftr
    laminar = 3 * nu * Re_tr / 4 * sp.sqrt(sp.pi) / 2 * A32 * dp / Ftr * (3 - abs_x)
    # |dp|^(1/2) sign(dp) without sp.Abs, which would be differentiated into re()/im()
    turbulent = C_d * A * sp.sqrt(2 / rho) * dp * (dp**2 + _DP_REG**2)**sp.Rational(-1, 4)
    # the switch is on x, not on A dp against F_tr: F_tr alone has C_d^2 as its only
    # denominator, which the code printer emits wrongly (a / C_d * C_d)
    return ac.if_else(x > 1, turbulent, ac.if_else(x < -1, turbulent, laminar))


def _odd_three_halves(a):
    """a^(3/2) for a >= 0, continued as an odd C1 function to a < 0."""
    if a.is_zero:
        return sp.Integer(0)
    return a * (a**2 + _A_REG**2)**sp.Rational(1, 4)
