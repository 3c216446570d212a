"""Operational amplifiers (MSL v4.0.0): the ideal ones of Modelica.Electrical.Analog.Ideal
(``IdealOpAmp``, ``IdealOpAmp3Pin``, ``IdealOpAmpLimited``, ``IdealizedOpAmpLimited``) and
the models of Modelica.Electrical.Analog.Basic (``OpAmp``, ``OpAmpDetailed``).

The MSL writes the limiters of ``OpAmpDetailed`` as functions and those of the
``strict`` ``IdealizedOpAmpLimited`` with ``noEvent``: they generate no events here
either (``ac.no_event``).  Modelica's ``homotopy`` has no counterpart here;
``IdealizedOpAmpLimited``'s ``homotopyType`` sets the Newton guess of the output
voltage for the initial system instead (the limit that the MSL's simplified model
names), which selects the same solution where the limited output has several.
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import NegativePin, PositivePin

__all__ = ["IdealOpAmp", "IdealOpAmp3Pin", "IdealOpAmpLimited", "IdealizedOpAmpLimited",
           "OpAmp", "OpAmpDetailed"]


class IdealOpAmp(ac.Component):
    """Ideal operational amplifier as a norator-nullator pair (Modelica.Electrical.
    Analog.Ideal.IdealOpAmp, MSL v4.0.0): the input port (p1, n1) is a nullator, the
    output port (p2, n2) a norator:

        v1 = 0,   i1 = 0,   0 = p1.i + n1.i,   0 = p2.i + n2.i
    """

    p1 = PositivePin()
    n1 = NegativePin()
    p2 = PositivePin()
    n2 = NegativePin()
    v1 = ac.Variable(unit="V", description="voltage drop over the left port")
    v2 = ac.Variable(unit="V", description="voltage drop over the right port")
    i1 = ac.Variable(unit="A", description="current from p1 to n1")
    i2 = ac.Variable(unit="A", description="current from p2 to n2")

    energy_role = "source"  # the output port is fed by a supply outside the model

    def equations(self):
        return [ac.Eq(self.v1, self.p1.v - self.n1.v), ac.Eq(self.v2, self.p2.v - self.n2.v),
                ac.Eq(0, self.p1.i + self.n1.i), ac.Eq(0, self.p2.i + self.n2.i),
                ac.Eq(self.i1, self.p1.i), ac.Eq(self.i2, self.p2.i),
                ac.Eq(self.v1, 0), ac.Eq(self.i1, 0)]


class IdealOpAmp3Pin(ac.Component):
    """Ideal operational amplifier with three pins (Modelica.Electrical.Analog.Ideal.
    IdealOpAmp3Pin, MSL v4.0.0), a nullator at the input and a norator to ground at the
    output:

        in_p.v = in_n.v,   in_p.i = 0,   in_n.i = 0

    The output current out.i is whatever the circuit demands; the output voltage is set
    by the feedback network, which must exist for the model to be regular.
    """

    in_p = PositivePin()
    in_n = NegativePin()
    out = PositivePin()

    energy_role = "source"  # the output stage is fed by a supply outside the model

    def equations(self):
        return [ac.Eq(self.in_p.v, self.in_n.v), ac.Eq(self.in_p.i, 0), ac.Eq(self.in_n.i, 0)]


class IdealOpAmpLimited(ac.Component):
    """Ideal operational amplifier with limitation (Modelica.Electrical.Analog.Ideal.
    IdealOpAmpLimited, MSL v4.0.0): infinite gain between the output limits VMax.v and
    VMin.v, piecewise linear in the curve parameter s:

        in_p.v - in_n.v = s + 1 (s < -1),  0 (-1 <= s <= 1),  s - 1 (s > 1)   [V]
        out.v = VMin.v (s < -1),  VMax.v (s > 1),
                (VMax.v - VMin.v) s/2 + (VMax.v + VMin.v)/2   otherwise

    and no current into in_p, in_n, VMax, VMin.
    """

    unitVoltage = ac.Parameter(1.0, unit="V", description="1 V: the unit of s as a voltage")
    in_p = PositivePin()
    in_n = NegativePin()
    out = PositivePin()
    VMax = PositivePin()
    VMin = NegativePin()
    vin = ac.Variable(unit="V", description="input voltage")
    s = ac.Variable(start=0.0, unit="1", description="curve parameter")

    energy_role = "source"  # the output stage is fed by a supply outside the model

    def equations(self):
        s = self.s
        low, high = s < -1, s > 1
        return [ac.Eq(self.in_p.i, 0), ac.Eq(self.in_n.i, 0),
                ac.Eq(self.VMax.i, 0), ac.Eq(self.VMin.i, 0),
                ac.Eq(self.vin, self.in_p.v - self.in_n.v),
                ac.Eq(self.vin, self.unitVoltage * ac.if_else(low, s + 1,
                                                              ac.if_else(high, s - 1, 0))),
                ac.Eq(self.out.v, ac.if_else(low, self.VMin.v, ac.if_else(
                    high, self.VMax.v,
                    (self.VMax.v - self.VMin.v) * s / 2 + (self.VMax.v + self.VMin.v) / 2)))]


class IdealizedOpAmpLimited(ac.Component):
    """Idealized operational amplifier with limitation (Modelica.Electrical.Analog.Ideal.
    IdealizedOpAmpLimited, MSL v4.0.0): gain V0 limited to the supply voltages,

        v_out = vps (V0 v_in > vps),  vns (V0 v_in < vns),  V0 v_in   otherwise
        in_p.i = in_n.i = 0,   v_in = in_p.v - in_n.v,   v_out = out.v
        p_s = -(p_in + p_out),   i_s = p_s/(vps - vns)

    The supply is the parameters Vps, Vns, or with ``useSupply=True`` (a constructor
    argument: it adds the pins) the pins s_p, s_n, which take the supply current
    (s_p.i = i_s, s_n.i = -i_s).  ``strict`` (structural): the limits without events
    (the MSL's noEvent), else with events.  ``homotopyType`` (a constructor argument:
    "NoHomotopy", "Linear", "UpperLimit", "LowerLimit"): the Newton guess of v_out for the initial
    system (vps for "UpperLimit", vns for "LowerLimit"), see the module docstring.
    """

    HOMOTOPY = ("NoHomotopy", "Linear", "UpperLimit", "LowerLimit")

    V0 = ac.Parameter(15000.0, description="no-load amplification")
    Vps = ac.Parameter(15.0, unit="V", description="positive supply voltage")
    Vns = ac.Parameter(-15.0, unit="V", description="negative supply voltage")
    strict = ac.Parameter(True, structural=True,
                          description="strict limits without events (the MSL's noEvent)")
    in_p = PositivePin()
    in_n = NegativePin()
    out = PositivePin()
    vps = ac.Variable(unit="V", description="positive supply voltage")
    vns = ac.Variable(unit="V", description="negative supply voltage")
    v_in = ac.Variable(unit="V", description="input voltage difference")
    v_out = ac.Variable(unit="V", description="output voltage to ground")
    p_in = ac.Variable(unit="W", description="input power")
    p_out = ac.Variable(unit="W", description="output power")
    p_s = ac.Variable(unit="W", description="supply power")
    i_s = ac.Variable(unit="A", description="supply current")

    energy_role = "source"  # the supply is outside the model unless useSupply

    def __init__(self, *, useSupply=False, homotopyType="NoHomotopy", **modifications):
        kind = homotopyType
        limit = {"UpperLimit": "Vps", "LowerLimit": "Vns"}.get(kind)
        if limit and "v_out" not in modifications:
            value = modifications.get(limit, type(self).__dict__[limit].value)
            if isinstance(value, (int, float)):
                modifications["v_out"] = {"start": float(value)}
        super().__init__(**modifications)
        if kind not in self.HOMOTOPY:
            raise ac.InvalidValue(f"IdealizedOpAmpLimited: homotopyType must be one of "
                                  f"{', '.join(self.HOMOTOPY)}, not {kind!r}")
        if not isinstance(useSupply, bool):
            raise ac.ModelError(f"IdealizedOpAmpLimited: useSupply must be True or False, "
                                f"not {useSupply!r}")
        object.__setattr__(self, "useSupply", useSupply)
        object.__setattr__(self, "homotopyType", kind)
        if useSupply:
            self.s_p = PositivePin()
            self.s_n = NegativePin()

    def equations(self):
        gain = self.V0 * self.v_in
        limited = ac.if_else(gain > self.vps, self.vps,
                             ac.if_else(gain < self.vns, self.vns, gain))
        if self.strict:
            limited = ac.no_event(limited)
        supply = ([ac.Eq(self.vps, self.s_p.v), ac.Eq(self.vns, self.s_n.v),
                   ac.Eq(self.s_p.i, self.i_s), ac.Eq(self.s_n.i, -self.i_s)]
                  if self.useSupply else
                  [ac.Eq(self.vps, self.Vps), ac.Eq(self.vns, self.Vns)])
        return [*supply,
                ac.Eq(self.v_in, self.in_p.v - self.in_n.v),
                ac.Eq(self.v_out, self.out.v),
                ac.Eq(self.p_in, self.in_p.v * self.in_p.i + self.in_n.v * self.in_n.i),
                ac.Eq(self.p_out, self.out.v * self.out.i),
                ac.Eq(self.p_s, -(self.p_in + self.p_out)),
                ac.Eq(self.i_s, self.p_s / (self.vps - self.vns)),
                ac.Eq(self.in_p.i, 0), ac.Eq(self.in_n.i, 0),
                ac.Eq(self.v_out, limited)]


class OpAmp(ac.Component):
    """Simple non-ideal operational amplifier with limitation (Modelica.Electrical.
    Analog.Basic.OpAmp, MSL v4.0.0): a gain |Slope| saturating smoothly towards the
    supply pins VMax, VMin:

        vin = in_p.v - in_n.v,   f = 2/(VMax.v - VMin.v)
        out.v = (VMax.v + VMin.v)/2 + |Slope| vin/(1 + |Slope| |f vin|)

    and no current into in_p, in_n, VMax, VMin.
    """

    Slope = ac.Parameter(1.0, description="performance of the op-amp (dVout/dVin)")
    in_p = PositivePin()
    in_n = NegativePin()
    out = PositivePin()
    VMax = PositivePin()
    VMin = NegativePin()
    vin = ac.Variable(unit="V", description="input voltage")
    f = ac.Variable(unit="1/V", description="auxiliary variable")

    energy_role = "source"  # the output stage is fed by a supply outside the model

    def equations(self):
        slope = sp.Abs(self.Slope)
        fv = self.f * self.vin
        return [ac.Eq(self.in_p.i, 0), ac.Eq(self.in_n.i, 0),
                ac.Eq(self.VMax.i, 0), ac.Eq(self.VMin.i, 0),
                ac.Eq(self.vin, self.in_p.v - self.in_n.v),
                ac.Eq(self.f, 2 / (self.VMax.v - self.VMin.v)),
                ac.Eq(self.out.v, (self.VMax.v + self.VMin.v) / 2 + slope * self.vin
                      / (1 + slope * ac.if_else(fv < 0, -fv, fv)))]


class OpAmpDetailed(ac.Component):
    """Detailed operational amplifier (Modelica.Electrical.Analog.Basic.OpAmpDetailed,
    MSL v4.0.0; Connelly & Choi, Macromodelling with SPICE, 1992): an input stage with
    offset, bias currents and input resistances and capacitance, the frequency response
    (poles fp2, fp3, fp4 and zero fz), the gain stage with the dominant pole fp1 limited
    by the supply, a slew-rate limiter and an output stage with current limits:

        p.i = i_vos,   m.i = i_4 - i_r2 - i_c3,   0 = i_3 + i_r2 + i_c3 - i_vos
        p.v - m.v = v_vos + v_in,   v_4 = m.v,   v_3 = p.v - v_vos,   v_vos = Vos
        i_3 = I1 + v_3/Rcm,   v_in = Rdm i_r2,   i_c3 = Cin der(v_in),   i_4 = I2 + v_4/Rcm
        der(q_fr1) = 2 pi fp2 (v_in - q_fr1)
        q_fr2 + der(q_fr2)/(2 pi fp3) = q_fr1 + der(q_fr1)/(2 pi fz)
        der(q_fr3) = 2 pi fp4 (q_fr2 - q_fr3)
        q_sum = Avd0_val q_fr3 + Avcm_val (v_3 + v_4)
        q_sum_help = q_sum limited to [v_neg + vcm, v_pos - vcp] (while q_fp1 is at it)
        der(q_fp1) = 2 pi fp1 (q_sum_help - q_fp1)
        der(x) = (q_fp1 - v_source)/Ts,   der(v_source) = der(x) limited to [-sr_m, sr_p]
        i_out = (v_out - v_source)/Rout limited to [-Imaxso, Imaxsi]

    with I1,2 = Ib +- Ios/2, Avd0_val = 10^(Avd0/20), Avcm_val = Avd0_val/10^(CMRR/20)/2,
    and initially v_source = q_fp1, x = 0.  The supply pins take no current.
    """

    Rdm = ac.Parameter(2.0e6, unit="Ohm", description="input resistance (differential input mode)")
    Rcm = ac.Parameter(2.0e9, unit="Ohm", description="input resistance (common mode)")
    Cin = ac.Parameter(1.4e-12, unit="F", min=0, description="input capacitance")
    Vos = ac.Parameter(1.0e-3, unit="V", description="input offset voltage")
    Ib = ac.Parameter(80.0e-9, unit="A", description="input bias current")
    Ios = ac.Parameter(20.0e-9, unit="A", description="input offset current")
    vcp = ac.Parameter(0.0, unit="V", description="correction value for limiting by p_supply")
    vcm = ac.Parameter(0.0, unit="V", description="correction value for limiting by m_supply")
    Avd0 = ac.Parameter(106.0, description="differential amplifier [dB]")
    CMRR = ac.Parameter(90.0, description="common-mode rejection [dB]")
    fp1 = ac.Parameter(5.0, unit="Hz", description="dominant pole")
    fp2 = ac.Parameter(2.0e6, unit="Hz", description="pole frequency")
    fp3 = ac.Parameter(20.0e6, unit="Hz", description="pole frequency")
    fp4 = ac.Parameter(100.0e6, unit="Hz", description="pole frequency")
    fz = ac.Parameter(5.0e6, unit="Hz", description="zero frequency")
    sr_p = ac.Parameter(0.5e6, unit="V/s", description="slew rate for increase")
    sr_m = ac.Parameter(0.5e6, unit="V/s", description="slew rate for decrease")
    Rout = ac.Parameter(75.0, unit="Ohm", description="output resistance")
    Imaxso = ac.Parameter(25.0e-3, unit="A", description="maximal output current (source current)")
    Imaxsi = ac.Parameter(25.0e-3, unit="A", description="maximal output current (sink current)")
    Ts = ac.Parameter(0.0000012, unit="s", description="sampling time")
    vcp_abs = ac.Parameter(lambda c: sp.Abs(c.vcp), unit="V",
                           description="positive correction value for limiting by p_supply")
    vcm_abs = ac.Parameter(lambda c: sp.Abs(c.vcm), unit="V",
                           description="positive correction value for limiting by m_supply")
    I1 = ac.Parameter(lambda c: c.Ib + c.Ios / 2, unit="A",
                      description="current of internal source I1")
    I2 = ac.Parameter(lambda c: c.Ib - c.Ios / 2, unit="A",
                      description="current of internal source I2")
    Avd0_val = ac.Parameter(lambda c: 10.0**(c.Avd0 / 20), description="differential mode gain")
    Avcm_val = ac.Parameter(lambda c: 10.0**(c.Avd0 / 20) / 10.0**(c.CMRR / 20) / 2,
                            description="common mode gain")
    sr_p_val = ac.Parameter(lambda c: sp.Abs(c.sr_p), unit="V/s",
                            description="value of slew rate for increase")
    sr_m_val = ac.Parameter(lambda c: -sp.Abs(c.sr_m), unit="V/s",
                            description="negative value of slew rate for decrease")
    Imaxso_val = ac.Parameter(lambda c: sp.Abs(c.Imaxso), unit="A",
                              description="orientation out outp")
    Imaxsi_val = ac.Parameter(lambda c: sp.Abs(c.Imaxsi), unit="A",
                              description="orientation into outp")

    p = PositivePin()
    m = NegativePin()
    outp = PositivePin()
    p_supply = PositivePin()
    m_supply = NegativePin()
    v_pos = ac.Variable(unit="V", description="positive supply")
    v_neg = ac.Variable(unit="V", description="negative supply")
    v_vos = ac.Variable(unit="V", description="offset voltage")
    v_3 = ac.Variable(unit="V")
    v_in = ac.Variable(unit="V", description="differential input voltage")
    v_4 = ac.Variable(unit="V")
    i_vos = ac.Variable(unit="A")
    i_3 = ac.Variable(unit="A")
    i_r2 = ac.Variable(unit="A")
    i_c3 = ac.Variable(unit="A")
    i_4 = ac.Variable(unit="A")
    q_fr1 = ac.Variable(unit="V", description="frequency response, first stage")
    q_fr2 = ac.Variable(unit="V", description="frequency response, second stage")
    q_fr3 = ac.Variable(unit="V", description="frequency response, third stage")
    q_sum = ac.Variable(unit="V", description="gain stage")
    q_sum_help = ac.Variable(unit="V", description="gain stage, limited")
    q_fp1 = ac.Variable(unit="V", description="gain stage after the dominant pole")
    v_source = ac.Variable(unit="V", description="slew-rate limited voltage")
    x = ac.Variable(unit="V", description="auxiliary variable for slew rate")
    v_out = ac.Variable(unit="V", description="output voltage")
    i_out = ac.Variable(unit="A", description="output current")

    energy_role = "source"  # the output stage is fed by a supply outside the model

    def initial_equations(self):
        return [ac.Eq(self.v_source, self.q_fp1), ac.Eq(self.x, 0)]

    def equations(self):
        two_pi = 2 * sp.pi
        top, bottom = self.v_pos - self.vcp_abs, self.v_neg + self.vcm_abs
        # FCNq_sum_limit: the sum is held at a limit while q_fp1 is at it
        sum_limit = ac.no_event(ac.if_else(
            sp.And(self.q_sum > top, self.q_fp1 >= top), top,
            ac.if_else(sp.And(self.q_sum < bottom, self.q_fp1 <= bottom), bottom,
                       self.q_sum)))
        dx = ac.der(self.x)
        slew = ac.no_event(ac.if_else(dx > self.sr_p_val, self.sr_p_val,
                                      ac.if_else(dx < self.sr_m_val, self.sr_m_val, dx)))
        # FCNiout_limit
        sink = self.v_source + self.Rout * self.Imaxsi_val
        source = self.v_source - self.Rout * self.Imaxso_val
        i_out = ac.no_event(ac.if_else(self.v_out > sink, self.Imaxsi_val,
                                       ac.if_else(self.v_out < source, -self.Imaxso_val,
                                                  (self.v_out - self.v_source) / self.Rout)))
        return [ac.Eq(self.v_pos, self.p_supply.v), ac.Eq(self.v_neg, self.m_supply.v),
                # input stage
                ac.Eq(self.p.i, self.i_vos),
                ac.Eq(self.m.i, self.i_4 - self.i_r2 - self.i_c3),
                ac.Eq(0, self.i_3 + self.i_r2 + self.i_c3 - self.i_vos),
                ac.Eq(self.p.v - self.m.v, self.v_vos + self.v_in),
                ac.Eq(self.v_4, self.m.v),
                ac.Eq(self.v_3, self.p.v - self.v_vos),
                ac.Eq(self.v_vos, self.Vos),
                ac.Eq(self.i_3, self.I1 + self.v_3 / self.Rcm),
                ac.Eq(self.v_in, self.Rdm * self.i_r2),
                ac.Eq(self.i_c3, self.Cin * ac.der(self.v_in)),
                ac.Eq(self.i_4, self.I2 + self.v_4 / self.Rcm),
                # frequency response
                ac.Eq(ac.der(self.q_fr1), two_pi * self.fp2 * (self.v_in - self.q_fr1)),
                ac.Eq(self.q_fr2 + ac.der(self.q_fr2) / (two_pi * self.fp3),
                      self.q_fr1 + ac.der(self.q_fr1) / (two_pi * self.fz)),
                ac.Eq(ac.der(self.q_fr3), two_pi * self.fp4 * (self.q_fr2 - self.q_fr3)),
                # gain stage
                ac.Eq(self.q_sum, self.Avd0_val * self.q_fr3
                      + self.Avcm_val * (self.v_3 + self.v_4)),
                ac.Eq(self.q_sum_help, sum_limit),
                ac.Eq(ac.der(self.q_fp1), two_pi * self.fp1 * (self.q_sum_help - self.q_fp1)),
                # slew rate stage
                ac.Eq(dx, (self.q_fp1 - self.v_source) / self.Ts),
                ac.Eq(ac.der(self.v_source), slew),
                # output stage
                ac.Eq(self.v_out, self.outp.v), ac.Eq(self.i_out, self.outp.i),
                ac.Eq(self.i_out, i_out),
                ac.Eq(self.p_supply.i, 0), ac.Eq(self.m_supply.i, 0)]
