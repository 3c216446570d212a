"""The heat ports of the dissipating elements of the 1-D mechanics (``useHeatPort``, as the
MSL's PartialElementaryConditionalHeatPort(WithoutT)), against a conservation law: a
body moving at v0 is stopped by the element, whose losses flow into a heat capacitor
of capacity C from T0, so at every instant

    E_kin(0) - E_kin(t) - E_spring(t) = C (T(t) - T0)

and the element's lossPower is what the heat port carries (heatPort.Q_flow =
-lossPower).  The temperature-dependent eddy current brake is checked against the same
balance with its speed of maximum torque moving with T.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.blocks import Constant
from acausal.library.electromechanical.machines.thermal import alpha20Copper
from acausal.library.thermal import HeatCapacitor

C, T0 = 2.0, 300.0
SHAFTS = (rot.Brake, rot.BearingFriction, rot.LossyGear, tr.Brake, tr.SupportFriction)


def _braked(domain, element, pressed=False):
    """A body at speed 5 between ``element`` (flange_a to the body; flange_b fixed,
    unless it is the shaft through the element or a gear's free output) and a heat
    capacitor on the element's heat port."""
    body_cls = rot.Inertia if domain == "rot" else tr.Mass
    fixed_cls = rot.Fixed if domain == "rot" else tr.Fixed
    speed = "w" if domain == "rot" else "v"
    size = {"J": 0.5} if domain == "rot" else {"m": 0.5}

    class Braked(ac.Component):
        body = body_cls(**size, **{speed: {"start": 5.0, "fixed": True}},
                        **({"phi": {"start": 0.0, "fixed": True}} if domain == "rot" else
                           {"s": {"start": 0.0, "fixed": True}}))
        brake = element
        fixed = fixed_cls()
        capacitor = HeatCapacitor(C=C, T={"start": T0, "fixed": True})
        if pressed:
            normal = Constant(k=1.0)

        def equations(self):
            eqs = [ac.connect(self.body.flange_b, self.brake.flange_a),
                   ac.connect(self.brake.heatPort, self.capacitor.port)]
            if not isinstance(self.brake, SHAFTS):
                eqs.append(ac.connect(self.brake.flange_b, self.fixed.flange))
            if pressed:
                eqs.append(ac.connect(self.normal.y, self.brake.f_normalized))
            return eqs

    return Braked()


CASES = [
    ("rot", lambda: rot.Damper(d=0.3, useHeatPort=True), False, 0.0),
    ("rot", lambda: rot.SpringDamper(c=20.0, d=0.3, useHeatPort=True), False, 20.0),
    # its damping is limited by the spring torque without events (the MSL's noEvent):
    # the kinks cost accuracy, so it runs at a tighter tolerance
    ("rot", lambda: rot.ElastoBacklash(c=20.0, d=0.3, b=0.2, useHeatPort=True), False, None),
    ("rot", lambda: rot.Brake(fn_max=2.0, useHeatPort=True), True, 0.0),
    ("rot", lambda: rot.BearingFriction(tau_pos=[[0.0, 1.0], [1.0, 1.5]],
                                        useHeatPort=True), False, 0.0),
    ("rot", lambda: rot.Clutch(fn_max=2.0, useHeatPort=True), True, 0.0),
    ("rot", lambda: rot.LossyGear(ratio=2.0, lossTable=[[0.0, 0.8, 0.8, 0.3, 0.3]],
                                  useHeatPort=True), False, 0.0),
    ("tr", lambda: tr.Damper(d=0.3, useHeatPort=True), False, 0.0),
    ("tr", lambda: tr.SpringDamper(c=20.0, d=0.3, useHeatPort=True), False, 20.0),
    ("tr", lambda: tr.Brake(fn_max=2.0, useHeatPort=True), True, 0.0),
    ("tr", lambda: tr.SupportFriction(f_pos=[[0.0, 1.0], [1.0, 1.5]], useHeatPort=True),
     False, 0.0),
]


def _spring_energy(res, domain, c):
    if not c:
        return 0.0
    rel = res["brake.phi_rel"] if domain == "rot" else res["brake.s_rel"]
    return c * rel**2 / 2


@pytest.mark.parametrize("domain,make,pressed,c", CASES,
                         ids=[f"{d}-{i}" for i, (d, *_) in enumerate(CASES)])
def test_the_heat_port_carries_the_losses(domain, make, pressed, c):
    element = make()
    rtol = 1e-10 if c is None else 1e-8
    res = ac.simulate(_braked(domain, element, pressed), t_end=3.0, rtol=rtol,
                      t_eval=np.linspace(0.0, 3.0, 301))
    assert res.success
    speed = res["body.w"] if domain == "rot" else res["body.v"]
    kinetic = 0.5 * 0.5 * speed**2
    if c is None:                        # the backlash: c (|phi_rel| - b/2)^2 / 2 in contact
        phi = res["brake.phi_rel"]
        stored = np.where(np.abs(phi) > 0.1, 20.0 * (np.abs(phi) - 0.1)**2 / 2, 0.0)
    else:
        stored = _spring_energy(res, domain, c)
    heat = C * (res["capacitor.T"] - T0)
    initial = kinetic[0]
    assert np.max(np.abs(initial - kinetic - stored - heat)) <= 1e-5 * initial
    assert heat[-1] > 0.5 * initial          # most of the energy has become heat
    # lossPower is the heat flow into the capacitor
    np.testing.assert_allclose(res["brake.lossPower"], res["capacitor.port.Q_flow"],
                               atol=1e-7 * np.max(np.abs(res["brake.lossPower"])))


def test_without_the_heat_port_the_element_has_none():
    damper = rot.Damper(d=1.0)
    with pytest.raises(ac.AbsentComponent, match="useHeatPort"):
        damper.heatPort.T  # noqa: B018


@pytest.mark.parametrize("domain", ["rot", "tr"])
def test_eddy_current_brake_energy_and_its_temperature(domain):
    """The losses heat the brake, which moves its speed of maximum torque up: the
    kinetic energy lost is the heat gained, and the torque at each instant is Kloss's
    law at the capacitor's temperature."""
    if domain == "rot":
        brake = rot.EddyCurrentTorque(tau_nominal=10.0, w_nominal=2.0, TRef=293.15,
                                      alpha20=alpha20Copper, useHeatPort=True)
    else:
        brake = tr.EddyCurrentForce(f_nominal=10.0, v_nominal=2.0, TRef=293.15,
                                    alpha20=alpha20Copper, useHeatPort=True)

    body_cls = rot.Inertia if domain == "rot" else tr.Mass
    speed = "w" if domain == "rot" else "v"
    flange = "flange_a"

    class Braked(ac.Component):
        body = body_cls(**({"J": 0.5} if domain == "rot" else {"m": 0.5}),
                        **{speed: {"start": 5.0, "fixed": True}})
        eddy = brake
        capacitor = HeatCapacitor(C=0.05, T={"start": 293.15, "fixed": True})

        def equations(self):
            return [ac.connect(self.eddy.flange, getattr(self.body, flange)),
                    ac.connect(self.eddy.heatPort, self.capacitor.port)]

    res = ac.simulate(Braked(), t_end=2.0, rtol=1e-9, t_eval=np.linspace(0, 2, 201))
    assert res.success
    v = res[f"body.{speed}"]
    T = res["capacitor.T"]
    kinetic = 0.25 * v**2
    heat = 0.05 * (T - 293.15)
    assert np.max(np.abs(kinetic[0] - kinetic - heat)) <= 1e-6 * kinetic[0]
    assert T[-1] - 293.15 > 10.0             # hot enough for alpha to matter
    alpha = alpha20Copper / (1 + alpha20Copper * (293.15 - 293.15))
    vn = v / (2.0 * (1 + alpha * (T - 293.15)))
    law = 2 * 10.0 * vn / (1 + vn**2)
    force = res["eddy.tau"] if domain == "rot" else res["eddy.f"]
    np.testing.assert_allclose(force, law, rtol=1e-7, atol=1e-9)


def test_rotational_heat_losses_balance_the_work_of_the_source():
    """Rotational.Examples.HeatLosses (no MAP-LIB reference available): the work of the
    torque source is the kinetic and spring energy of the train plus the heat that left
    through the convection.  At t0 the lossy gear, clutch, one-way clutch and brake are
    stuck together (four lock constraints on three inertias): the split of their torques
    is indeterminate, and the integrator solves the consistent rank-deficient system."""
    from acausal.library.rotational.examples.heat_losses import HeatLosses

    class Audited(HeatLosses):
        work = ac.Variable(start=0.0, fixed=True, unit="J")
        heat = ac.Variable(start=0.0, fixed=True, unit="J")

        def equations(self):
            return [ac.Eq(ac.der(self.work), self.torque.tau * self.inertia1.w),
                    ac.Eq(ac.der(self.heat), self.convection.Q_flow)]

    res = ac.simulate(Audited(), t_end=1.0, rtol=1e-8)
    assert res.success
    kinetic = sum(0.5 * 2.0 * res[f"inertia{k}.w"]**2 for k in range(1, 7))
    springs = (0.5 * 1e4 * res["springDamper.phi_rel"]**2
               + 0.5 * 1e4 * res["spring3.phi_rel"]**2)
    backlash = res["elastoBacklash.phi_rel"]
    springs += np.where(np.abs(backlash) > 5e-4, 0.5 * 1e5 * (np.abs(backlash) - 5e-4)**2, 0)
    balance = res["work"] - kinetic - springs - res["heat"]
    assert np.max(np.abs(balance)) <= 1e-5 * np.max(np.abs(res["work"]))


# -- the MultiBody force elements ------------------------------------------------------

def _hanging(element):
    """A 2 kg body on a horizontal Prismatic (no gravity along it), pulled back by
    ``element`` from the World, its heat port on a heat capacitor."""
    from acausal.library import multibody3d as mb

    class Hanging(ac.Component):
        world = mb.World(g=9.81)
        guide = mb.Prismatic(n_1=1.0, n_2=0.0, s={"start": 0.8, "fixed": True},
                             v={"start": 1.5, "fixed": True})
        body = mb.Body(m=2.0)
        force = element
        capacitor = HeatCapacitor(C=C, T={"start": T0, "fixed": True})

        def equations(self):
            return [ac.connect(self.world.frame_b, self.guide.frame_a, self.force.frame_a),
                    ac.connect(self.guide.frame_b, self.body.frame_a, self.force.frame_b),
                    ac.connect(self.force.heatPort, self.capacitor.port)]
    return Hanging()


@pytest.mark.parametrize("kind", ["Damper", "SpringDamperParallel", "SpringDamperSeries"])
def test_multibody_force_elements_send_their_losses_to_the_heat_port(kind):
    """m v^2/2 + the spring's energy + C (T - T0) is constant; for the damper alone the
    motion is v = v0 exp(-d t / m)."""
    from acausal.library import multibody3d as mb
    element = {"Damper": lambda: mb.Damper(d=3.0, useHeatPort=True),
               "SpringDamperParallel": lambda: mb.SpringDamperParallel(
                   c=50.0, d=3.0, s_unstretched=0.5, useHeatPort=True),
               "SpringDamperSeries": lambda: mb.SpringDamperSeries(
                   c=50.0, d=3.0, s_unstretched=0.5, useHeatPort=True,
                   s_damper={"start": 0.1})}[kind]()
    t = np.linspace(0.0, 2.0, 201)
    res = ac.simulate(_hanging(element), t_end=2.0, rtol=1e-9, t_eval=t)
    assert res.success
    v, s = res["guide.v"], res["guide.s"]
    if kind == "Damper":
        np.testing.assert_allclose(v, 1.5 * np.exp(-3.0 * t / 2.0), rtol=1e-6)
        stored = 0.0
    elif kind == "SpringDamperParallel":
        stored = 50.0 * (s - 0.5)**2 / 2
    else:
        stored = 50.0 * (s - 0.5 - res["force.s_damper"])**2 / 2
    energy = 0.5 * 2.0 * v**2 + stored + C * (res["capacitor.T"] - T0)
    assert np.max(np.abs(energy - energy[0])) <= 1e-6 * energy[0]
    assert res["capacitor.T"][-1] - T0 > 0.1 * energy[0] / C
