"""Conductor and the signal-controlled R, G, C and L (MSL Analog.Basic) against the
closed-form discharges of first-order circuits, and the energy audit (the work done by
changing C or L is booked as created power)."""
import numpy as np

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import electrical as el
from acausal.library.blocks import Ramp

V0, CAP = 10.0, 1e-3          # initial voltage [V], capacitance [F]


class ConductorDischarge(ac.Component):
    """A charged capacitor discharging through a conductor G:  C v' = -G v."""

    C = el.Capacitor(C=CAP, v={"start": V0, "fixed": True})
    G = el.Conductor(G=2e-3)
    ground = el.Ground()
    E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="heat released")

    def equations(self):
        return [ac.connect(self.C.p, self.G.p), ac.connect(self.C.n, self.G.n, self.ground.p),
                ac.Eq(ac.der(self.E_loss), self.G.loss_power())]


def test_rc_discharge_through_a_conductor():
    t = np.linspace(0, 2, 41)
    model = ConductorDischarge()
    res = ac.simulate(model, t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    exact = V0 * np.exp(-2e-3 / CAP * t)
    assert np.max(np.abs(res["C.v"] - exact)) < 1e-8 * V0
    assert np.max(np.abs(res["G.i"] - 2e-3 * res["G.v"])) < 1e-12 * 2e-3 * V0
    # the heat G v^2 integrates to the energy the capacitor lost
    lost = CAP * (V0**2 - exact**2) / 2
    assert np.max(np.abs(res["E_loss"] - lost)) < 1e-8 * CAP * V0**2 / 2
    audit = energy_balance(res, model)
    assert set(audit.dissipated) == {"G"} and not audit.violations


R0, KR = 100.0, 400.0          # R(t) = R0 + KR t  [Ohm, Ohm/s]


class VariableRDischarge(ac.Component):
    """C v' = -v / R(t) with a ramping resistance."""

    C = el.Capacitor(C=CAP, v={"start": V0, "fixed": True})
    R = el.VariableResistor()
    ramp = Ramp(offset=R0, height=KR * 2.0, duration=2.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.ramp.y, self.R.R), ac.connect(self.C.p, self.R.p),
                ac.connect(self.C.n, self.R.n, self.ground.p)]


def test_variable_resistor_discharge_closed_form():
    """v = V0 exp(-int dt/(R C)) = V0 (R0 / (R0 + k t))^(1/(k C))."""
    t = np.linspace(0, 2, 41)
    model = VariableRDischarge()
    res = ac.simulate(model, t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    exact = V0 * (R0 / (R0 + KR * t)) ** (1 / (KR * CAP))
    assert np.max(np.abs(res["C.v"] - exact)) < 1e-8 * V0
    assert not energy_balance(res, model).violations


G0, KG = 1e-3, 4e-3            # G(t) = G0 + KG t  [S, S/s]


class VariableGDischarge(ac.Component):
    C = el.Capacitor(C=CAP, v={"start": V0, "fixed": True})
    G = el.VariableConductor()
    ramp = Ramp(offset=G0, height=KG * 2.0, duration=2.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.ramp.y, self.G.G), ac.connect(self.C.p, self.G.p),
                ac.connect(self.C.n, self.G.n, self.ground.p)]


def test_variable_conductor_discharge_closed_form():
    """v = V0 exp(-(G0 t + k t^2 / 2) / C)."""
    t = np.linspace(0, 2, 41)
    res = ac.simulate(VariableGDischarge(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    exact = V0 * np.exp(-(G0 * t + KG * t**2 / 2) / CAP)
    assert np.max(np.abs(res["C.v"] - exact)) < 1e-8 * V0


C0, KC, RL = 1e-3, 2e-3, 500.0  # C(t) = C0 + KC t [F, F/s], load resistance [Ohm]


class VariableCDischarge(ac.Component):
    """A capacitor of growing capacitance discharging into R: Q' = -Q / (R C(t))."""

    C = el.VariableCapacitor(Q={"start": C0 * V0, "fixed": True})
    ramp = Ramp(offset=C0, height=KC * 2.0, duration=2.0)
    R = el.Resistor(R=RL)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.ramp.y, self.C.C), ac.connect(self.C.p, self.R.p),
                ac.connect(self.C.n, self.R.n, self.ground.p)]


def test_variable_capacitor_keeps_its_charge_law():
    """Q = Q0 (C0 / (C0 + k t))^(1/(R k)), v = Q / C(t)."""
    t = np.linspace(0, 2, 41)
    model = VariableCDischarge()
    res = ac.simulate(model, t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    Q0 = C0 * V0
    Q = Q0 * (C0 / (C0 + KC * t)) ** (1 / (RL * KC))
    assert np.max(np.abs(res["C.Q"] - Q)) < 1e-8 * Q0
    assert np.max(np.abs(res["C.v"] - Q / (C0 + KC * t))) < 1e-8 * V0
    # the work of the agent changing C, -v^2 C'/2, closes the capacitor's balance
    audit = energy_balance(res, model)
    assert not audit.violations and audit.relative_residual() < 1e-6
    assert np.all(audit.created["C"][1:] < 0)


L0, KL, RR, I0 = 0.1, 0.2, 2.0, 3.0   # L(t) = L0 + KL t [H, H/s], R [Ohm], i(0) [A]


class VariableLDecay(ac.Component):
    """Flux decaying through R with a growing inductance: Psi' = -R Psi / L(t)."""

    L = el.VariableInductor(Psi={"start": L0 * I0, "fixed": True})
    ramp = Ramp(offset=L0, height=KL * 1.0, duration=1.0)
    R = el.Resistor(R=RR)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.ramp.y, self.L.L), ac.connect(self.L.p, self.R.p),
                ac.connect(self.L.n, self.R.n, self.ground.p)]


def test_variable_inductor_flux_law():
    """Psi = Psi0 (L0 / (L0 + k t))^(R/k), i = Psi / L(t)."""
    t = np.linspace(0, 1, 41)
    model = VariableLDecay()
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    Psi0 = L0 * I0
    Psi = Psi0 * (L0 / (L0 + KL * t)) ** (RR / KL)
    assert np.max(np.abs(res["L.Psi"] - Psi)) < 1e-8 * Psi0
    assert np.max(np.abs(res["L.i"] - Psi / (L0 + KL * t))) < 1e-8 * I0
    audit = energy_balance(res, model)
    assert not audit.violations and audit.relative_residual() < 1e-6


RP, VS, RLOAD = 100.0, 10.0, 50.0      # potentiometer, supply [V], load


def divider(**options):
    class LoadedDivider(ac.Component):
        """A potentiometer across a supply, its contact loaded by a resistor."""

        supply = el.ConstantVoltage(V=VS)
        pot = el.Potentiometer(R=RP, **options)
        load = el.Resistor(R=RLOAD)
        ground = el.Ground()
        wiper = Ramp(offset=0.1, height=1.1, duration=1.0)

        def equations(self):
            eqs = [ac.connect(self.supply.p, self.pot.pin_p),
                   ac.connect(self.supply.n, self.pot.pin_n, self.load.n, self.ground.p),
                   ac.connect(self.pot.contact, self.load.p)]
            if self.pot.useRinput:
                eqs.append(ac.connect(self.wiper.y, self.pot.r))
            return eqs

    return LoadedDivider()


def test_potentiometer_loaded_divider():
    """v_c = (V/Rp) / (1/Rp + 1/Rn + 1/R_L) with Rp = R (1 - r), Rn = R r; the wiper
    r = 0.1 + 1.1 t is clipped to 1 (v_c = V) after t = 9/11."""
    t = np.linspace(0, 1, 45)
    model = divider(useRinput=True)
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    r = np.minimum(0.1 + 1.1 * t, 1.0)
    Rp, Rn = RP * (1 - r), RP * r
    with np.errstate(divide="ignore", invalid="ignore"):
        vc = np.where(Rp > 0, (VS / Rp) / (1 / Rp + 1 / Rn + 1 / RLOAD), VS)
    assert np.max(np.abs(res["load.v"] - vc)) < 1e-9 * VS
    assert not energy_balance(res, model).violations
    fixed = ac.simulate(divider(rConstant=0.25), t_end=0.1, rtol=1e-10, n_points=3)
    Rp, Rn = 0.75 * RP, 0.25 * RP
    assert np.allclose(fixed["load.v"], (VS / Rp) / (1 / Rp + 1 / Rn + 1 / RLOAD),
                       rtol=1e-9, atol=0)
