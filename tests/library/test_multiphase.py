"""Polyphase components and three-phase transformers (library/electrical/multiphase.py,
transformers.py): a symmetric source into star and delta resistor loads against Ohm's law
on the phase and line-to-line voltages; the transformers' vector groups (the phase shift
of Dy1 is -30 degrees, of Dd0 none) at no load; a short-circuit test that gives back the
nominal data the impedances were computed from (rated current at v_sc, losses P_sc)."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library.electrical import Ground
from acausal.library.electrical import multiphase as mp
from acausal.library.electrical.transformers import Dd00, Dy01, TransformerData

W = 2 * math.pi * 50
V = 10.0


class StarAndDelta(ac.Component):
    source = mp.SineVoltage(m=3, V=V, f=50.0)
    starS = mp.Star(m=3)
    ground = Ground()
    starLoad = mp.Resistor(m=3, R=2.0)
    starL = mp.Star(m=3)
    deltaLoad = mp.Resistor(m=3, R=5.0)
    delta = mp.Delta(m=3)
    sensor = mp.CurrentSensor(m=3)

    def equations(self):
        c = ac.connect
        return [c(self.source.plug_n, self.starS.plug_p), c(self.starS.pin_n, self.ground.p),
                c(self.source.plug_p, self.sensor.plug_p),
                c(self.sensor.plug_n, self.starLoad.plug_p, self.delta.plug_p),
                c(self.starLoad.plug_n, self.starL.plug_p),
                c(self.deltaLoad.plug_p, self.sensor.plug_n),
                c(self.deltaLoad.plug_n, self.delta.plug_n)]


def test_star_and_delta_loads_follow_ohms_law():
    t = np.linspace(0, 0.04, 201)
    res = ac.simulate(StarAndDelta(), t_end=0.04, t_eval=t)
    phase = [W * t - 2 * math.pi * k / 3 for k in range(3)]
    v = [V * np.sin(p) for p in phase]
    for k in range(3):
        assert np.max(np.abs(res[f"starLoad.resistor[{k}].i"] - v[k] / 2.0)) < 1e-9 * V
        line = v[k] - v[(k + 1) % 3]                # resistor k: pin k to pin k + 1
        assert np.max(np.abs(res[f"deltaLoad.resistor[{k}].i"] - line / 5.0)) < 1e-9 * V
        i_line = v[k] / 2.0 + line / 5.0 - (v[k - 1] - v[k]) / 5.0
        assert np.max(np.abs(res[f"sensor.i[{k}]"] - i_line)) < 1e-9 * V
    # the star load's star point floats at 0: the phases sum to zero
    assert np.max(np.abs(res["starL.pin_n.v"])) < 1e-9 * V


def test_plugs_of_different_phase_counts_do_not_connect():
    class Mismatch(ac.Component):
        a = mp.Resistor(m=3)
        b = mp.Resistor(m=2)

        def equations(self):
            return [ac.connect(self.a.plug_n, self.b.plug_p)]

    with pytest.raises(ac.InvalidConnection, match="different types"):
        ac.simulate(Mismatch(), t_end=0.1)


def _transformer(cls, data):
    return cls(n=data.n, R1=data.R1, L1sigma=data.L1sigma, R2=data.R2, L2sigma=data.L2sigma)


class Fed(ac.Component):
    """A transformer fed by a star source of amplitude Vs, its secondary into a star
    resistor load RL (the load's star point and the secondary's grounded)."""

    Vs = ac.Parameter(100 * math.sqrt(2 / 3))
    RL = ac.Parameter(1e6)
    source = mp.SineVoltage(m=3, V=ac.ref("Vs"), f=50.0)
    starS = mp.Star(m=3)
    ground = Ground()
    load = mp.Resistor(m=3, R=ac.ref("RL"))
    starL = mp.Star(m=3)

    def equations(self):
        c = ac.connect
        return [c(self.source.plug_n, self.starS.plug_p), c(self.starS.pin_n, self.ground.p),
                c(self.source.plug_p, self.transformer.plug1),
                c(self.transformer.plug2, self.load.plug_p),
                c(self.load.plug_n, self.starL.plug_p), c(self.starL.pin_n, self.ground.p)]


@pytest.mark.parametrize("cls, shift", [(Dy01, -math.pi / 6), (Dd00, 0.0)])
def test_vector_group_phase_shift_at_no_load(cls, shift):
    data = TransformerData(C1=cls.VectorGroup[0], C2=cls.VectorGroup[1])

    class NoLoad(Fed):
        transformer = _transformer(cls, data)

        def equations(self):
            if cls is Dy01:
                return [ac.connect(self.transformer.starpoint2, self.ground.p)]
            return []

    t = np.linspace(0.06, 0.08, 101)
    res = ac.simulate(NoLoad(), t_end=0.08, t_eval=t, rtol=1e-8)
    Vs = 100 * math.sqrt(2 / 3)                   # V1 = V2 = 100 V line-to-line
    for k in range(3):
        expected = Vs * np.sin(W * t - 2 * math.pi * k / 3 + shift)
        assert np.max(np.abs(res[f"load.resistor[{k}].v"] - expected)) < 1e-4 * Vs


@pytest.mark.parametrize("cls", [Dy01, Dd00])
def test_short_circuit_gives_rated_current_and_losses(cls):
    data = TransformerData(C1=cls.VectorGroup[0], C2=cls.VectorGroup[1], SNominal=30e3,
                           v_sc=0.05, P_sc=300)

    class Shorted(Fed):
        Vs = ac.Parameter(0.05 * 100 * math.sqrt(2 / 3))      # v_sc x rated voltage
        RL = ac.Parameter(1e-9)
        transformer = _transformer(cls, data)

    T = 0.02
    t = np.linspace(0.3 - T, 0.3, 2001)       # the stray L/R decays in ~16 ms
    res = ac.simulate(Shorted(), t_end=0.3, t_eval=t, rtol=1e-9)
    i = [res[f"transformer.i1[{k}]"] for k in range(3)]
    v = [res[f"source.sineVoltage[{k}].v"] for k in range(3)]
    mean = lambda x: np.trapezoid(x, t) / T                            # noqa: E731
    rms = [math.sqrt(mean(x**2)) for x in i]
    power = mean(sum(vk * ik for vk, ik in zip(v, i)))
    I_line = 30e3 / (math.sqrt(3) * 100)
    assert rms == pytest.approx([I_line] * 3, rel=1e-4)
    assert power == pytest.approx(300.0, rel=1e-4)
