"""Translational components after the MSL (Modelica.Mechanics.Translational v4.0.0):
the rigid mass of length L and the multi-sensor, against closed forms."""
import numpy as np

import acausal as ac
from acausal.library import translational as tr

M, F, L = 2.0, 3.0, 0.8


class PushedMass(ac.Component):
    """A constant force pushes a mass of length L through a multi-sensor."""

    push = tr.ConstantForce(f_constant=F)
    sensor = tr.MultiSensor()
    mass = tr.Mass(m=M, L=L, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.push.flange, self.sensor.flange_a),
                ac.connect(self.sensor.flange_b, self.mass.flange_a)]


def test_a_mass_of_length_L_is_pushed_at_its_left_flange_and_the_multisensor_reads_it():
    t = np.linspace(0, 2, 41)
    res = ac.simulate(PushedMass(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    s = 0.1 + F / M * t**2 / 2                   # the centre, from rest
    v = F / M * t
    assert np.max(np.abs(res["mass.s"] - s)) < 1e-9 * np.ptp(s)
    assert np.max(np.abs(res["mass.flange_a.s"] - (s - L / 2))) < 1e-9 * np.ptp(s)
    assert np.max(np.abs(res["mass.flange_b.s"] - (s + L / 2))) < 1e-9 * np.ptp(s)
    assert np.max(np.abs(res["sensor.f"] - F)) < 1e-9 * F
    assert np.max(np.abs(res["sensor.v"] - v)) < 1e-9 * np.ptp(v)
    assert np.max(np.abs(res["sensor.power"] - F * v)) < 1e-9 * F * np.ptp(v)


def bouncer(gap):
    class Bouncer(ac.Component):
        """A mass moving at V0 towards a wall through an elasto-gap (s_rel0 = G)."""

        wall = tr.Fixed()
        gap_ = gap
        mass = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": -V0, "fixed": True})
        E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="energy dissipated")

        def equations(self):
            return [ac.connect(self.wall.flange, self.gap_.flange_a),
                    ac.connect(self.gap_.flange_b, self.mass.flange_a),
                    ac.Eq(ac.der(self.E_loss), self.gap_.lossPower)]

    return Bouncer()


V0, G, CG, DG = 1.0, -0.2, 400.0, 6.0


def test_an_undamped_elasto_gap_with_a_power_law_gives_back_the_energy_it_took():
    from acausal.analysis import energy_balance
    t = np.linspace(0, 1.0, 201)
    model = bouncer(tr.ElastoGap(c=CG, d=0.0, n=2.0, s_rel0=G))
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    x = np.minimum(res["mass.s"] - G, 0.0)                  # penetration, <= 0
    E = M * res["mass.v"]**2 / 2 + CG * np.abs(x)**3 / 3
    E0 = M * V0**2 / 2
    assert np.min(x) < -0.1 * (3 * E0 / CG)**(1 / 3)        # it went into contact
    assert np.max(np.abs(E - E0)) < 1e-7 * E0
    assert abs(res["mass.v"][-1] - V0) < 1e-6 * V0          # back out at the speed it came
    assert np.all(res["gap_.f"] <= 1e-12 * CG)              # it only pushes
    assert not energy_balance(res, model).violations


def test_a_damped_elasto_gap_against_dop853_on_the_hand_written_law():
    from scipy.integrate import solve_ivp

    def force(s, v):                                  # the force of the gap on the mass
        x = s - G
        if x >= 0:
            return 0.0
        f_c, f_d2 = -CG * abs(x), DG * v
        return -(f_c + min(max(f_d2, f_c), -f_c))

    edge = lambda t, y: y[0] - G                       # noqa: E731
    edge.terminal = True
    t = np.linspace(0, 1.0, 201)
    pieces, t0, y0 = [], 0.0, [0.0, -V0]
    while t0 < 1.0:
        sol = solve_ivp(lambda t, y: [y[1], force(*y) / M], (t0, 1.0), y0, method="DOP853",
                        rtol=1e-11, atol=1e-13, events=edge, dense_output=True)
        pieces.append((t0, sol.t[-1], sol.sol))
        t0, y0 = sol.t[-1], sol.y[:, -1] + np.array([np.sign(sol.y[1, -1]) * 1e-14, 0.0])
        if sol.status == 0:
            break
    ref = np.concatenate([p[2](t[(t >= p[0]) & (t <= p[1]) & ~((t == p[0]) & (k > 0))])[0]
                          for k, p in enumerate(pieces)])
    model = bouncer(tr.ElastoGap(c=CG, d=DG, s_rel0=G))
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    assert len(ref) == len(t) and len(res.events) >= 2
    assert np.max(np.abs(res["mass.s"] - ref)) < 1e-7 * V0
    # kinetic + spring energy + what lossPower took = the initial kinetic energy
    x = np.minimum(res["mass.s"] - G, 0.0)
    E = M * res["mass.v"]**2 / 2 + CG * x**2 / 2 + res["E_loss"]
    assert np.max(np.abs(E - M * V0**2 / 2)) < 1e-7 * M * V0**2 / 2
    assert res["E_loss"][-1] > 0.05 * M * V0**2 / 2


def test_a_translational_brake_stops_a_mass_and_its_support_takes_the_force():
    from acausal.library.blocks import Constant
    V, FN, MU = 2.0, 4.0, 0.5

    class Braked(ac.Component):
        mass = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": V, "fixed": True})
        brake = tr.Brake(fn_max=FN, useSupport=True, v={"start": V})
        ground = tr.Fixed()
        press = Constant(k=1.0)

        def equations(self):
            return [ac.connect(self.mass.flange_b, self.brake.flange_a),
                    ac.connect(self.brake.support, self.ground.flange),
                    ac.connect(self.press.y, self.brake.f_normalized)]

    t = np.linspace(0, 3, 61)
    res = ac.simulate(Braked(), t_end=3.0, rtol=1e-10, atol=1e-12, t_eval=t)
    d = MU * FN / M                                      # deceleration while sliding
    t_star = V / d
    v = np.where(t < t_star, V - d * t, 0.0)
    s = np.where(t < t_star, V * t - d * t**2 / 2, V**2 / (2 * d))
    assert np.max(np.abs(res["mass.v"] - v)) < 1e-8 * V
    assert np.max(np.abs(res["mass.s"] - s)) < 1e-8 * V * t_star
    sliding = t < t_star - 0.05
    assert np.max(np.abs(res["brake.f"][sliding] - MU * FN)) < 1e-8 * MU * FN
    assert np.max(np.abs(res["ground.flange.f"] - res["brake.f"])) < 1e-9 * MU * FN


def test_support_friction_holds_a_mass_until_a_ramped_force_exceeds_its_peak():
    F0, PEAK, K = 2.0, 1.5, 4.0

    class Pushed(ac.Component):
        push = tr.Force()
        mass = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
        friction = tr.SupportFriction(f_pos=[[0, F0], [10, F0]], peak=PEAK)

        def equations(self):
            return [ac.connect(self.push.flange, self.mass.flange_a),
                    ac.connect(self.mass.flange_b, self.friction.flange_a),
                    ac.Eq(self.push.f, K * ac.time)]

    t = np.linspace(0, 2, 41)
    res = ac.simulate(Pushed(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    t_star = PEAK * F0 / K                  # breaks away at the peak, then slides on F0
    # m a = K t - F0 from t_star:  v = K (t^2 - t*^2)/(2m) - F0 (t - t*)/m
    v = np.where(t > t_star, (K * (t**2 - t_star**2) / 2 - F0 * (t - t_star)) / M, 0.0)
    assert np.max(np.abs(res["mass.v"] - v)) < 1e-7 * np.max(v)
    assert np.min(np.abs(np.asarray(res.events) - t_star)) < 1e-8


def test_a_mass_with_stop_and_friction_stops_at_its_stop_and_stays():
    FC, V0, LEN, SMAX = 1.0, 2.0, 1.0, 1.0

    class Stopped(ac.Component):
        mass = tr.MassWithStopAndFriction(m=1.0, L=LEN, smax=SMAX, smin=-SMAX, F_prop=0.0,
                                          F_Coulomb=FC, F_Stribeck=0.0,
                                          s={"start": 0.0, "fixed": True},
                                          v={"start": V0, "fixed": True})

    t = np.linspace(0, 1, 51)
    res = ac.simulate(Stopped(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    # s = V0 t - FC t^2 / 2 until the right end reaches SMAX (s = SMAX - LEN/2)
    t_hit = (V0 - np.sqrt(V0**2 - 2 * FC * (SMAX - LEN / 2))) / FC
    s = np.where(t < t_hit, V0 * t - FC * t**2 / 2, SMAX - LEN / 2)
    v = np.where(t < t_hit, V0 - FC * t, 0.0)
    assert np.min(np.abs(np.asarray(res.events) - t_hit)) < 1e-8
    assert np.max(np.abs(res["mass.s"] - s)) < 1e-8
    assert np.max(np.abs(res["mass.v"] - v)[np.abs(t - t_hit) > 1e-6]) < 1e-8


def test_the_stribeck_table_of_the_friction_example():
    from acausal.library.translational.examples.msl.utilities import \
        GenerateStribeckFrictionTable
    table = GenerateStribeckFrictionTable(F_prop=1, F_Coulomb=5, F_Stribeck=10, fexp=2,
                                          v_max=12, nTable=50)
    assert table.shape == (50, 2) and table[0, 0] == 0 and table[-1, 0] == 12
    assert np.allclose(table[:, 1], 5 + table[:, 0] + 10 * np.exp(-2 * table[:, 0]),
                       rtol=1e-15)


def test_a_sign_force_with_sine_regularization_against_its_closed_form():
    V, F, VR = 2.0, 3.0, 0.4

    class Slowed(ac.Component):
        mass = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": V, "fixed": True})
        load = tr.SignForce(f_nominal=-F, v0=VR, reg="Sine")

        def equations(self):
            return [ac.connect(self.load.flange, self.mass.flange_a)]

    t = np.linspace(0, 3, 61)
    res = ac.simulate(Slowed(), t_end=3.0, rtol=1e-10, atol=1e-12, t_eval=t)
    t1 = (V - VR) * M / F                          # constant force down to v0, then
    k = np.pi / (2 * VR)                           # m v' = -F sin(k v):
    late = 2 / k * np.arctan(np.exp(-F / M * k * (t - t1)))   # tan(k v/2) = e^(-a k t)
    v = np.where(t < t1, V - F / M * t, late)
    assert np.max(np.abs(res["mass.v"] - v)) < 1e-8 * V


def test_a_translational_eddy_current_brake_against_its_invariant():
    V, FN, VN = 20.0, 100.0, 10.0

    class Braked(ac.Component):
        mass = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": V, "fixed": True})
        brake = tr.EddyCurrentForce(f_nominal=FN, v_nominal=VN)

        def equations(self):
            return [ac.connect(self.brake.flange, self.mass.flange_a)]

    t = np.linspace(0, 1, 51)
    res = ac.simulate(Braked(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    v = res["mass.v"]
    inv = np.log(v) + v**2 / (2 * VN**2) + 2 * FN * t / (M * VN)
    assert np.max(np.abs(inv - inv[0])) < 1e-8 * abs(inv[0])
    assert np.max(np.abs(res["brake.lossPower"] - res["brake.f"] * v)) < 1e-9 * FN * V


def _driven_vehicle(T, **vehicle):
    from acausal.library import rotational as rot
    from acausal.library.blocks import Constant
    inputs = {k: vehicle.pop(k) for k in ("useInclinationInput",) if k in vehicle}

    class Driven(ac.Component):
        car = tr.Vehicle(s={"start": 0.0, "fixed": True}, v={"start": 5.0, "fixed": True},
                         **inputs, **vehicle)
        drive = rot.ConstantTorque(tau_constant=T)
        slope = Constant(k=0.1)

        def equations(self):
            eqs = [ac.connect(self.drive.flange, self.car.flangeR)]
            if inputs.get("useInclinationInput"):
                eqs.append(ac.connect(self.slope.y, self.car.inclination))
            return eqs

    return Driven()


def test_a_vehicle_climbs_at_the_acceleration_of_its_forces_and_its_equivalent_mass():
    m, J, R, T, Cr, g = 80.0, 2.0, 0.5, 300.0, 0.02, 9.80665
    t = np.linspace(0, 2, 21)
    angle = np.arctan(0.1)
    a = (T / R - Cr * m * g * np.cos(angle) - m * g * np.sin(angle)) / (m + J / R**2)
    for inputs in ({"inclinationConstant": 0.1}, {"useInclinationInput": True}):
        model = _driven_vehicle(T, m=m, J=J, R=R, Cd=0.0, CrConstant=Cr, **inputs)
        res = ac.simulate(model, t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
        assert np.max(np.abs(res["car.v"] - (5.0 + a * t))) < 1e-8 * abs(a) * 2
        assert np.max(np.abs(res["car.fRoll.f"] - Cr * m * g * np.cos(angle))) < 1e-9 * m


def test_a_coasting_vehicle_slows_down_by_its_air_drag():
    m, Cd, A, rho = 80.0, 0.4, 2.0, 1.2
    t = np.linspace(0, 10, 41)
    model = _driven_vehicle(0.0, m=m, J=0.0, Cd=Cd, A=A, rho=rho, CrConstant=0.0)
    res = ac.simulate(model, t_end=10.0, rtol=1e-10, atol=1e-12, t_eval=t)
    k = Cd * A * rho / 2                         # m v' = -k v^2
    assert np.max(np.abs(res["car.v"] - 5.0 / (1 + k * 5.0 * t / m))) < 1e-8 * 5.0
