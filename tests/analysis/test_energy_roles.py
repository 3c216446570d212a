"""Every component owns its energy: the audit classifies each leaf and flags what breaks
its declaration (analysis/energy.py), against closed forms of Egeland & Gravdahl."""
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import energy_balance, register_storage
from acausal.analysis.energy import classify
from acausal.library import rotational as rot
from acausal.library import thermal as th
from acausal.library import translational as tr
from acausal.library.electrical import Capacitor, Ground, Resistor, StepVoltage
from acausal.library.electrical.interfaces import OnePort
from acausal.library.friction import rotational as frot
from acausal.library.friction import translational as ftr
from acausal.library.friction.examples.stick_slip import StickSlip

J, W0, F_C, F_V = 0.05, 2.0, 0.2, 0.05


class WrongFriction(frot.StribeckFriction):
    """A friction law with the sign error tau = -(F_c sgn(w) + F_v w): it pushes."""

    def law(self, w, tau):
        return [ac.Eq(tau, -(self.F_c * ac.sign(w) + self.F_v * w))]


class Coasting(ac.Component):
    """A wheel spun up to w0 and left to the friction in its bearing."""

    housing = rot.Fixed()
    wheel = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True}, w={"start": W0, "fixed": True})
    bearing = frot.StribeckFriction(F_c=F_C, F_s=F_C, v_s=0.1, F_v=F_V)

    def equations(self):
        return [ac.connect(self.housing.flange, self.bearing.flange_a),
                ac.connect(self.bearing.flange_b, self.wheel.flange_a)]


class WronglyCoasting(Coasting):
    bearing = WrongFriction(F_c=F_C, F_s=F_C, v_s=0.1, F_v=F_V)


def test_friction_that_delivers_power_is_flagged():
    model = WronglyCoasting()
    res = ac.simulate(model, t_end=0.5, rtol=1e-9, atol=1e-12, n_points=51)
    assert res["wheel.w"][-1] > W0                  # it speeds the wheel up: wrong
    audit = energy_balance(res, model)
    assert audit.roles["bearing"] == "dissipation"   # it says it is friction ...
    assert not audit.ok
    kinds = {(v.kind, v.path) for v in audit.violations}
    assert kinds == {("negative loss", "bearing")}    # ... and the audit sees it push
    worst = audit.violations[0].worst
    tau = -(F_C + F_V * res["wheel.w"])               # its law, w > 0 throughout
    assert worst == pytest.approx(np.min(tau * res["wheel.w"]), rel=1e-6)
    # the balance itself closes: the books are right, the element is wrong
    assert audit.balance_closes


def test_friction_that_takes_power_passes_and_matches_the_closed_form():
    """J w' = -(F_c + F_v w): w = (w0 + F_c/F_v) exp(-F_v t / J) - F_c/F_v while w > 0,
    i.e. until t = (J/F_v) ln(1 + w0 F_v/F_c) = 0.405 s."""
    model = Coasting()
    res = ac.simulate(model, t_end=0.35, rtol=1e-9, atol=1e-12, n_points=51)
    audit = energy_balance(res, model)
    assert audit.ok, audit.summary()
    w = (W0 + F_C / F_V) * np.exp(-F_V * res.t / J) - F_C / F_V
    assert np.allclose(audit.stored["wheel"], 0.5 * J * w**2, rtol=1e-6)
    assert np.allclose(audit.dissipated["bearing"], (F_C + F_V * w) * w, rtol=1e-6)
    assert np.max(np.abs(audit.residual)) < 1e-8 * audit.power_scale


@pytest.mark.parametrize("domain", [frot, ftr])
def test_library_friction_elements_are_dissipative(domain):
    for cls in (domain.StribeckFriction, domain.KarnoppFriction):
        assert callable(getattr(cls, "loss_power", None)), cls
        assert not callable(getattr(cls, "stored_energy", None)), cls
    for cls in (domain.DahlFriction, domain.LuGreFriction, domain.ElastoPlasticFriction):
        assert callable(getattr(cls, "loss_power", None))     # with bristle storage
        assert callable(getattr(cls, "stored_energy", None))


def test_stick_slip_audit_karnopp_friction_never_delivers_power():
    model = StickSlip()
    res = ac.simulate(model, t_end=StickSlip.stop_time, rtol=1e-8, max_step=1e-2)
    audit = energy_balance(res, model)
    assert audit.roles == {"ground": "lossless", "friction": "dissipation", "block": "storage",
                           "spring": "storage", "puller": "source"}
    assert audit.ok, audit.summary()
    assert np.min(audit.dissipated["friction"]) >= -1e-9 * audit.power_scale
    # sliding, the loss is f v with f on the Stribeck curve; stuck, v = 0 and no loss
    v = res["friction.v"]
    assert np.max(audit.dissipated["friction"]) > 0.1 * audit.power_scale
    assert np.all(audit.dissipated["friction"][np.abs(v) < 1e-12] == 0)


class NegativeResistor(OnePort):
    """v = -R i, declaring nothing."""

    R = ac.Parameter(1.0)

    def equations(self):
        return [ac.Eq(self.v, -self.R * self.i)]


class ClaimsLossless(NegativeResistor):
    energy_role = "lossless"


class HalfCapacitor(Capacitor):
    """A capacitor whose declared energy is twice the right one."""

    def stored_energy(self):
        return self.C * self.v**2


class Circuit(ac.Component):
    source = StepVoltage(V=1.0)
    ground = Ground()
    load = Resistor(R=2.0)
    other = Resistor(R=1.0)
    cap = Capacitor(C=1e-3)

    def equations(self):
        return [ac.connect(self.source.p, self.load.p),
                ac.connect(self.load.n, self.other.p, self.cap.p),
                ac.connect(self.other.n, self.cap.n, self.source.n, self.ground.p)]


def _audit(**replace):
    model = Circuit()
    for name, comp in replace.items():
        setattr(model, name, comp)
    res = ac.simulate(model, t_end=0.01, rtol=1e-9, atol=1e-12, n_points=41)
    return energy_balance(res, model)


def test_circuit_every_leaf_classified():
    audit = _audit()
    assert audit.roles == {"source": "source", "ground": "lossless", "load": "dissipation",
                           "other": "dissipation", "cap": "storage"}
    assert audit.ok and not audit.violations and not audit.unclassified


def test_an_unclassified_component_is_named_not_hidden():
    audit = _audit(other=NegativeResistor(R=5.0))
    assert audit.unclassified == ["other"] and audit.roles["other"] == "unclassified"
    assert [v.kind for v in audit.violations] == ["unclassified"]
    assert "other" in audit.sources and not audit.ok


def test_a_lossless_claim_that_fails_is_flagged():
    audit = _audit(other=ClaimsLossless(R=5.0))
    assert [(v.kind, v.path) for v in audit.violations] == [("not lossless", "other")]


def test_a_declaration_that_does_not_match_the_equations_is_flagged():
    audit = _audit(cap=HalfCapacitor(C=1e-3))
    assert [(v.kind, v.path) for v in audit.violations] == [("inconsistent declaration", "cap")]


def test_class_registry_still_overrides():
    try:
        register_storage(HalfCapacitor, lambda v, p: 0.5 * p("C") * v("v") ** 2)
        audit = _audit(cap=HalfCapacitor(C=1e-3))
        assert audit.ok, audit.summary()
    finally:
        from acausal.analysis import energy
        energy._STORAGE.pop(HalfCapacitor, None)


def test_classify_descends_into_structural_composites_only():
    from acausal.library.electromechanical import DCMotor
    from acausal.library.hydraulics.lines import LumpedLine

    class Drive(ac.Component):
        motor = DCMotor()
        line = LumpedLine(n=3)

    roles = classify(Drive())
    assert roles == {"motor.Ra": "dissipation", "motor.La": "storage", "motor.emf": "lossless",
                     "motor.rotor": "storage", "line": "storage+dissipation"}


def test_mass_on_a_spring_conserves_energy():
    """x'' = -(c/m) x from x0: E = c x0^2 / 2 at all times, the spring's share c x^2 / 2."""
    m, c, x0 = 0.5, 200.0, 0.02

    class Oscillator(ac.Component):
        wall = tr.Fixed()
        spring = tr.Spring(c=c)
        mass = tr.Mass(m=m, s={"start": x0, "fixed": True}, v={"start": 0.0, "fixed": True})

        def equations(self):
            return [ac.connect(self.wall.flange, self.spring.flange_a),
                    ac.connect(self.spring.flange_b, self.mass.flange_a)]

    model = Oscillator()
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-13, n_points=101)
    audit = energy_balance(res, model)
    assert audit.ok
    E0 = 0.5 * c * x0**2
    assert np.max(np.abs(audit.E - E0)) < 1e-7 * E0
    x = x0 * np.cos(np.sqrt(c / m) * res.t)
    assert np.allclose(audit.stored["spring"], 0.5 * c * x**2, rtol=0, atol=1e-6 * E0)


class CircuitBesideAWarmBody(Circuit):
    """The circuit and, unconnected, a 1 kJ/K body at 300 K: C T = 3e5 J stored, constant
    (its energy is measured from 0 K)."""

    body = th.HeatCapacitor(C=1e3, T={"start": 300.0, "fixed": True})


def test_a_violation_is_not_hidden_by_an_energy_far_from_its_datum():
    """The power scale is set by the change of the stored energy, not its level: the
    300 K body must not lift the violation limit above the circuit's milliwatts."""
    model = CircuitBesideAWarmBody()
    model.other = ClaimsLossless(R=5.0)
    res = ac.simulate(model, t_end=0.01, rtol=1e-9, atol=1e-12, n_points=41)
    audit = energy_balance(res, model)
    assert audit.roles["body"] == "storage"
    assert [(v.kind, v.path) for v in audit.violations] == [("not lossless", "other")]


class DoubleLossResistor(Resistor):
    """A resistor whose declared loss is twice R i^2."""

    def loss_power(self):
        return 2 * self.R * self.i**2


def test_a_loss_declaration_that_does_not_match_the_port_power_is_flagged():
    """The resistor's loss is declared in its constitutive form R i^2, so the audit's
    comparison with the port power v i is a real check, not 0 = 0."""
    assert _audit().ok
    audit = _audit(other=DoubleLossResistor(R=1.0))
    assert [(v.kind, v.path) for v in audit.violations] == [("inconsistent declaration",
                                                              "other")]
