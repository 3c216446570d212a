"""Hydraulic laws evaluated past the relations that guard their branches: valves,
orifices, compensators and pumps swept through zero openings and reversing flows
(Egeland & Gravdahl ch. 4), checked against the orifice law and mass conservation."""
import numpy as np
import pytest

import acausal as ac
from acausal.library import hydraulics as hy
from acausal.library import rotational as rot
from acausal.library.blocks import Ramp, Sine
from acausal.library.hydraulics.examples import valve_motor as vm

from .test_hydraulics import _ellman_piche


# -- guarded branches evaluated past their relation ----------------------------------------
# A branch is frozen between events, so the integrator evaluates it a little beyond the
# relation that guards it (a spool opening b x_v with x_v < 0 before x_v > 0 is located).
# Each rig sweeps openings and pressure drops through zero; every run must reach t_end,
# with the flows given by the orifice law and the volumes conserving mass.

BETA = 7e8


def _orifice(A, dp):
    """(4.9)-(4.10) for an opening of area max(A, 0) (a closed edge passes nothing)."""
    A = np.maximum(np.asarray(A, dtype=float), 0.0)
    D = np.sqrt(4 * np.where(A > 0, A, 1.0) / np.pi)
    return np.where(A > 0, _ellman_piche(dp, D)[0], 0.0)


def _integral(t, y):
    return float(np.sum(np.diff(t) * (y[1:] + y[:-1]) / 2))


def _assert_mass_conserved(res, net_flow, p, V):
    """int net flow dt = (V / beta) (p(T) - p(0)) (Egeland & Gravdahl (4.64), dV = 0),
    relative to the larger of the stored volume change and the flow's own throughput
    (trapezoidal rule on the dense output)."""
    stored = V / BETA * (p[-1] - p[0])
    scale = max(abs(stored), _integral(res.t, np.abs(net_flow)))
    assert abs(_integral(res.t, net_flow) - stored) < 1e-4 * scale


def _run(model, t_end, n=8001, **kw):
    """n output points (interpolated), or with n=None every step, where the algebraic
    equations hold to the Newton tolerance and not only to the interpolation error."""
    res = ac.simulate(model, t_end=t_end, rtol=1e-8, n_points=n, **kw)
    assert res.success, res.message
    assert res.t[-1] == pytest.approx(t_end, rel=1e-12)
    return res


@pytest.mark.parametrize("p_s", [5e6, 1e7, 2e7, 3e7])
@pytest.mark.parametrize("height", [1.0, -1.0, 0.25])
def test_valve_motor_runs_through_the_centred_spool_at_any_supply_pressure(p_s, height):
    """The P-controlled motor of 4.4.3 with the supply pressure (K_v grows as sqrt(p_s),
    still below 2 zeta_h w_h (4.112) at 3e7 Pa) and the reference swept: the spool
    command crosses zero as the angle settles, and each line volume integrates the net
    flow the valve (4.16)-(4.17) and the motor (4.72) put into it."""
    res = _run(vm.ValveControlledMotor(), 0.5,
               parameters={"supply.p": p_s, "reference.height": height})
    assert abs(res["load.phi"][-1] - height) < 5e-3 * abs(height)
    # above 1.5e7 Pa the angle overshoots: the spool passes centre (the reported stop at
    # t = 0.0907 s with p_s = 2e7 Pa was there)
    x_v = res["valve.x_v.signal"]
    assert np.any(np.diff(np.sign(x_v)) != 0) or p_s < 2e7
    _assert_mass_conserved(res, res["valve.q_1"] - res["motor.port_a.q"], res["line_1.p"],
                           vm.V_0)
    _assert_mass_conserved(res, -res["motor.port_b.q"] - res["valve.q_2"], res["line_2.p"],
                           vm.V_0)


class SpoolThroughCentre(ac.Component):
    """A four-way valve between supply and tank whose spool oscillates through centre,
    feeding two line volumes joined by a laminar load (the load flow reverses)."""

    supply = hy.FixedPressure(p=2e7)
    tank = hy.FixedPressure(p=0.0)
    line_1 = hy.Volume(V=1e-5, p={"start": 1e7, "fixed": True})
    line_2 = hy.Volume(V=1e-5, p={"start": 1e7, "fixed": True})
    load = hy.LaminarOrifice(C_l=1e-12)

    def __init__(self, valve, amplitude, **mods):
        super().__init__(**mods)
        self.valve = valve
        self.spool = Sine(amplitude=amplitude, f=10.0)

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_s),
                ac.connect(self.tank.port, self.valve.port_r),
                ac.connect(self.spool.y, self.valve.x_v),
                ac.connect(self.valve.port_1, self.line_1.port, self.load.port_a),
                ac.connect(self.valve.port_2, self.line_2.port, self.load.port_b)]


@pytest.mark.parametrize("p_s", [5e6, 2e7, 4e7])
@pytest.mark.parametrize("kind, amplitude", [("critical", 1e-4), ("critical", 3e-6),
                                             ("open", 1e-4)])
def test_four_way_valves_through_centre_4_15_to_4_22(p_s, kind, amplitude):
    """Critical centre (4.18)-(4.20) and open centre, underlap U = 20 um (4.21)-(4.22),
    with the spool swept over +-amplitude (3 um keeps the metering edges laminar, 0.1 mm
    takes them turbulent): q_1 = q(A_a, p_s - p_1) - q(A_c, p_1 - p_r) with (4.9) at the
    simulated pressures, and each line conserves mass."""
    if kind == "critical":
        valve, U = hy.CriticalCentreValve(b=1e-3), 0.0
    else:
        valve, U = hy.OpenCentreValve(b=1e-3, U=2e-5), 2e-5
    res = _run(SpoolThroughCentre(valve, amplitude, supply={"p": p_s}), 0.3)
    x_v, p_1, p_2 = res["valve.x_v.signal"], res["line_1.p"], res["line_2.p"]
    q_1 = _orifice(1e-3 * (U + x_v), p_s - p_1) - _orifice(1e-3 * (U - x_v), p_1)
    q_2 = _orifice(1e-3 * (U + x_v), p_2) - _orifice(1e-3 * (U - x_v), p_s - p_2)
    scale = np.max(np.abs(q_1))
    assert np.max(np.abs(res["valve.q_1"] - q_1)) < 1e-9 * scale
    assert np.max(np.abs(res["valve.q_2"] - q_2)) < 1e-9 * scale
    assert np.ptp(np.sign(res["load.q"])) == 2        # the load flow reverses
    _assert_mass_conserved(res, res["valve.q_1"] - res["load.q"], p_1, 1e-5)
    _assert_mass_conserved(res, res["load.q"] - res["valve.q_2"], p_2, 1e-5)


class ClosingOrifice(ac.Component):
    """A variable orifice, its area ramped from 1 mm2 through 0 to -1 mm2, between an
    oscillating pressure (the flow reverses) and a volume."""

    source = hy.PressureSource()
    orifice = hy.VariableOrifice()
    volume = hy.Volume(V=1e-5, p={"start": 0.0, "fixed": True})

    def __init__(self, p_0, **mods):
        super().__init__(**mods)
        self.drive = Sine(amplitude=4e6, f=20.0, offset=p_0)
        self.area = Ramp(offset=1e-6, height=-2e-6, duration=0.1, startTime=0.02)

    def equations(self):
        return [ac.connect(self.drive.y, self.source.p_ref),
                ac.connect(self.area.y, self.orifice.A_in),
                ac.connect(self.source.port, self.orifice.port_a),
                ac.connect(self.orifice.port_b, self.volume.port)]


@pytest.mark.parametrize("p_0", [-1e6, 1e6, 1e7])
def test_variable_orifice_closes_through_zero_area_4_13(p_0):
    """q = q(max(A_in, 0), dp) of (4.9); after closure at t = 0.07 s the volume is
    sealed, its pressure constant; the volume conserves mass."""
    res = _run(ClosingOrifice(p_0), 0.2)
    q = _orifice(res["orifice.A_in.signal"], res["orifice.dp"])
    assert np.max(np.abs(res["orifice.q"] - q)) < 1e-9 * np.max(np.abs(q))
    assert np.ptp(np.sign(res["orifice.q"])) == 2
    sealed = res.t > 0.0701
    p = res["volume.p"]
    assert np.ptp(p[sealed]) < 1e-9 * np.max(np.abs(p))
    _assert_mass_conserved(res, res["orifice.q"], p, 1e-5)


class CompensatedValveReversing(ac.Component):
    """A pressure-compensated valve between an oscillating inlet (the flow reverses) and
    a volume, its command swept through zero to negative openings."""

    inlet = hy.PressureSource()
    valve = hy.PressureCompensatedValve(A_leak=1e-10, K_c=200.0, F_c0=50.0, A_c=1e-4,
                                        b=0.01, b_c=0.01, p_c={"start": 1.5e6},
                                        x_c={"start": 5e-4})
    volume = hy.Volume(V=1e-4, p={"start": 1e6, "fixed": True})
    spool = Sine(amplitude=1e-3, f=3.0)

    def __init__(self, p_0, **mods):
        super().__init__(**mods)
        self.drive = Sine(amplitude=8e6, f=5.0, offset=p_0)

    def equations(self):
        return [ac.connect(self.drive.y, self.inlet.p_ref),
                ac.connect(self.inlet.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.volume.port),
                ac.connect(self.spool.y, self.valve.x_v)]


@pytest.mark.parametrize("p_0", [2e6, 1e7])
def test_pressure_compensated_valve_with_negative_commands_4_45_to_4_47(p_0):
    """q = q(b_c x_c + A_leak, p_1 - p_c) = q(b max(x_v, 0) + A_leak, p_c - p_2) with
    (4.9); the volume conserves mass.  The flows are compared to 1e-3 of their size: the
    static compensator (4.47) makes x_c = -(A_c/K_c) p_c + ..., so the Newton tolerance
    on p_c (rtol 1e-8 of 1e7 Pa) moves x_c, hence q, by up to ~1e-4 of q."""
    res = _run(CompensatedValveReversing(p_0), 1.0, n=None)
    p_1, p_2, p_c = res["inlet.port.p"], res["volume.p"], res["valve.p_c"]
    x_v, x_c, q = res["valve.x_v.signal"], res["valve.x_c"], res["valve.q"]
    scale = np.max(np.abs(q))
    assert np.max(np.abs(q - _orifice(0.01 * x_c + 1e-10, p_1 - p_c))) < 1e-3 * scale
    assert np.max(np.abs(q - _orifice(0.01 * np.maximum(x_v, 0) + 1e-10, p_c - p_2))) \
        < 1e-3 * scale
    assert np.ptp(np.sign(q)) == 2 and np.sum(x_v < 0) > 100
    # closed by a negative command: only the two leaks in series pass flow
    closed = x_v < 0
    assert np.max(np.abs(q[closed])) < 1e-3 * scale
    _assert_mass_conserved(res, q, p_2, 1e-4)


class BalanceValveReversing(ac.Component):
    """A balance valve (pilot at 40 bar) between an oscillating load pressure and a
    volume: pilot-opened flow 1 -> 2 and check-valve flow 2 -> 1 alternate."""

    load = hy.PressureSource()
    pilot = hy.FixedPressure(p=4e6)
    valve = hy.BalanceValve(A=2e-4, A_p=1.5e-4, K=1e5, F_0=600.0, x_v_max=2e-3, b=0.01,
                            A_ch=1e-6)
    volume = hy.Volume(V=1e-5, p={"start": 3e6, "fixed": True})

    def __init__(self, p_0, **mods):
        super().__init__(**mods)
        self.drive = Sine(amplitude=8e6, f=10.0, offset=p_0)

    def equations(self):
        return [ac.connect(self.drive.y, self.load.p_ref),
                ac.connect(self.load.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.volume.port),
                ac.connect(self.pilot.port, self.valve.port_p)]


@pytest.mark.parametrize("p_0", [2e6, 8e6])
def test_balance_valve_reversing_flow_4_58_to_4_60(p_0):
    """x_v of (4.59) clipped to the stroke; q = q(b x_v, dp) for dp > 0 and q(A_ch, dp)
    for dp < 0 (4.60) with (4.9); the volume conserves mass.  A clip is a relation with
    a tolerance: within it (here 1e-6 m of the stops) the frozen branch, the unclipped
    opening, is what the solver holds, and the flow law must accept it."""
    res = _run(BalanceValveReversing(p_0), 0.3, n=None)
    p_1, p_2, dp, x_v = res["load.port.p"], res["volume.p"], res["valve.dp"], res["valve.x_v"]
    A_r, R = 0.5e-4, 3.0
    free = (A_r * (p_1 + R * 4e6 - p_2 * (R + 1)) - 600.0) / 1e5
    clipped = np.clip(free, 0.0, 2e-3)
    near_stop = (np.abs(free) < 2e-6) | (np.abs(free - 2e-3) < 2e-6)
    assert np.allclose(x_v[~near_stop], clipped[~near_stop], rtol=1e-9, atol=1e-9 * 2e-3)
    frozen = np.isclose(x_v, free, rtol=1e-9, atol=1e-9 * 2e-3)
    assert np.all(np.isclose(x_v, clipped, rtol=1e-9, atol=1e-9 * 2e-3) | frozen)
    # the law at the opening the solver holds: (4.9) for x_v >= 0, and for the frozen
    # x_v < 0 its odd continuation, -q(|b x_v|, dp)
    q = np.where(dp > 0, _orifice(0.01 * x_v, dp), _orifice(1e-6, dp))
    scale = np.max(np.abs(q))
    shut = (x_v < 0) & (dp > 0)
    assert np.max(np.abs(res["valve.q"] - q)[~shut]) < 1e-9 * scale
    assert np.allclose(res["valve.q"][shut], -_orifice(0.01 * np.abs(x_v[shut]),
                                                        dp[shut]), rtol=1e-9, atol=0)
    assert np.sum(q > 1e-3 * scale) > 50 and np.sum(q < -1e-3 * scale) > 50
    _assert_mass_conserved(res, res["valve.q"], p_2, 1e-5)


class ReversingPumpRig(ac.Component):
    """A variable pump (swash plate swept through zero: the flow reverses) between a tank
    and a volume, which a relief valve vents to the tank above its cracking pressure."""

    tank = hy.FixedPressure(p=0.0)
    swash = Sine(amplitude=1.0, f=5.0)
    pump = hy.VariablePump(D_max=1e-6, C_i=1e-13)
    volume = hy.Volume(V=1e-4, p={"start": 0.0, "fixed": True})
    relief = hy.ReliefValve(p_crack=1e7, G_open=1e-11, G_closed=1e-14)

    def __init__(self, w, **mods):
        super().__init__(**mods)
        self.drive = rot.ConstantSpeed(w_fixed=w)

    def equations(self):
        return [ac.connect(self.drive.flange, self.pump.flange),
                ac.connect(self.swash.y, self.pump.phi_p),
                ac.connect(self.tank.port, self.pump.port_a, self.relief.port_b),
                ac.connect(self.pump.port_b, self.volume.port, self.relief.port_a)]


@pytest.mark.parametrize("w", [50.0, 150.0, 300.0])
def test_reversing_pump_and_relief_valve_4_4_5(w):
    """Delivery -port_b.q = phi_p D_max w - C_i (p_b - p_a) (4.67) through phi_p = 0,
    the relief law on both sides of its cracking point and for dp < 0, and the volume
    conserving mass."""
    res = _run(ReversingPumpRig(w), 0.4, n=None)
    p, phi = res["volume.p"], res["pump.phi_p.signal"]
    delivered = -res["pump.port_b.q"]
    expected = phi * 1e-6 * w - 1e-13 * p
    assert np.max(np.abs(delivered - expected)) < 1e-9 * np.max(np.abs(expected))
    dp = res["relief.dp"]
    relief = np.where(dp > 1e7, 1e-11 * (dp - 1e7), 0.0) + 1e-14 * dp
    off_crack = np.abs(dp - 1e7) > 1e-6 * 1e7     # within the relation's tolerance, frozen
    assert np.max(np.abs(res["relief.q"] - relief)[off_crack]) \
        < 1e-9 * np.max(np.abs(relief))
    assert p.min() < 0 < 1e7 < p.max()
    _assert_mass_conserved(res, delivered - res["relief.q"], p, 1e-4)
