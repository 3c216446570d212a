"""Three-phase transformers (Modelica.Electrical.Machines.BasicMachines.Transformers, MSL
v4.0.0): the partial transformer of primary and secondary resistances and stray
inductances around an ideal core of three windings per phase, and the vector groups
the MSL's rectifier examples use, Dy01 and Dd00; ``TransformerData`` computes the
resistances and inductances from nominal values (Machines.Utilities.TransformerData).

The plugs are polyphase plugs (:mod:`.multiphase`); the parts keep the MSL's names
(``r1``, ``l1sigma``, ``core``, ``l2sigma``, ``r2``), so ``transformer.l2sigma.inductor[0].i``
is the MSL's ``transformer.l2sigma.inductor[1].i``.  The MSL's thermal port is not
offered: the windings are at their operational temperatures (``T1Operational``,
``T2Operational``, the MSL's ``useThermalPort = false``).
"""
import math

import numpy as np

import acausal as ac
from acausal.ports import NegativePin

from . import multiphase as mp

__all__ = ["TransformerData", "IdealCore", "PartialBasicTransformer", "Dy01", "Dd00"]


class TransformerData:
    """Impedances of a three-phase transformer from its nominal values (MSL
    Machines.Utilities.TransformerData), per phase:

        V1ph = V1 (/sqrt(3) for a star primary "Y"),  I1ph = SNominal/(3 V1ph),
        Z1ph = v_sc V1ph/(2 I1ph),  R1 = P_sc/(6 I1ph^2),
        L1sigma = sqrt(Z1ph^2 - R1^2)/(2 pi f),   and the same for the secondary;
        n = V1/V2

    ``C1`` is "Y" or "D", ``C2`` "y", "d" or "z" (the vector group's letters).
    """

    def __init__(self, *, C1: str, C2: str, f: float = 50.0, V1: float = 100.0,
                 V2: float = 100.0, SNominal: float = 30e3, v_sc: float = 0.05,
                 P_sc: float = 300.0):
        if C1 not in ("Y", "D") or C2 not in ("y", "d", "z"):
            raise ac.InvalidValue(f"TransformerData: C1 = {C1!r} is 'Y' or 'D', C2 = {C2!r} "
                                  "is 'y', 'd' or 'z'")
        if not 0 <= v_sc <= 1:
            raise ac.InvalidValue(f"TransformerData: v_sc = {v_sc!r} lies outside [0, 1]")
        self.C1, self.C2, self.f, self.V1, self.V2 = C1, C2, f, V1, V2
        self.SNominal, self.v_sc, self.P_sc = SNominal, v_sc, P_sc
        self.n = V1 / V2
        self.V1ph = V1 / (1 if C1 == "D" else math.sqrt(3))
        self.I1ph = SNominal / (3 * self.V1ph)
        self.V2ph = V2 / (1 if C2 == "d" else math.sqrt(3))
        self.I2ph = SNominal / (3 * self.V2ph)
        self.Z1ph = 0.5 * v_sc * self.V1ph / self.I1ph
        self.R1 = 0.5 * P_sc / (3 * self.I1ph**2)
        self.L1sigma = math.sqrt(self.Z1ph**2 - self.R1**2) / (2 * math.pi * f)
        self.Z2ph = 0.5 * v_sc * self.V2ph / self.I2ph
        self.R2 = 0.5 * P_sc / (3 * self.I2ph**2)
        self.L2sigma = math.sqrt(self.Z2ph**2 - self.R2**2) / (2 * math.pi * f)

    def __repr__(self):
        return (f"TransformerData(n={self.n:g}, R1={self.R1:g}, L1sigma={self.L1sigma:g}, "
                f"R2={self.R2:g}, L2sigma={self.L2sigma:g})")


class IdealCore(ac.Component):
    """Ideal transformer with 3 windings per phase (MSL
    Machines.BasicMachines.Components.IdealCore, PartialCore), for each phase:

        v1 = n12 v2,   v1 = n13 v3,   im = i1 + i2/n12 + i3/n13 = 0,
        plug_pk.pin.i + plug_nk.pin.i = 0   (k = 1, 2, 3)

    with vk = plug_pk.pin.v - plug_nk.pin.v, ik = plug_pk.pin.i.
    """

    m = ac.Parameter(3, structural=True, min=1, description="number of phases")
    n12 = ac.Parameter(1.0, description="turns ratio 1:2")
    n13 = ac.Parameter(1.0, description="turns ratio 1:3")

    def build(self):
        for k in (1, 2, 3):
            setattr(self, f"plug_p{k}", mp.PositivePlug(m=self.m))
            setattr(self, f"plug_n{k}", mp.NegativePlug(m=self.m))

    def equations(self):
        eqs = []
        for j in range(int(self.m)):
            p = [None] + [getattr(self, f"plug_p{k}").pin[j] for k in (1, 2, 3)]
            n = [None] + [getattr(self, f"plug_n{k}").pin[j] for k in (1, 2, 3)]
            v = [None] + [p[k].v - n[k].v for k in (1, 2, 3)]
            eqs += [ac.Eq(p[k].i + n[k].i, 0) for k in (1, 2, 3)]
            eqs += [ac.Eq(v[1], self.n12 * v[2]), ac.Eq(v[1], self.n13 * v[3]),
                    ac.Eq(p[1].i + p[2].i / self.n12 + p[3].i / self.n13, 0)]
        return eqs


def _convert_alpha(alpha20, T_ref):
    """The temperature coefficient at T_ref of one given at 20 degC (MSL
    Machines.Thermal.convertAlpha)."""
    return alpha20 / (1 + alpha20 * (T_ref - 293.15))


class PartialBasicTransformer(ac.Component):
    """A three-phase transformer (MSL Machines.Interfaces.PartialBasicTransformer):
    plug1 -> r1 -> l1sigma -> the core's primary windings, the secondary windings ->
    l2sigma -> r2 -> plug2; a vector group (a subclass) connects the windings.  The core
    is ideal with the turns ratio

        ni = n (sqrt(3) if C2 == "z" else 2) (1 if C2 == "d" else sqrt(3))
               / (1 if C1 == "D" else sqrt(3))

    for both secondary windings.  The resistances are at the operational temperatures:
    R1 (1 + alpha1 (T1Operational - T1Ref)), alpha1 the coefficient alpha20_1 at 20 degC
    converted to T1Ref (the same for R2).
    """

    VectorGroup = "Yy00"
    m = 3
    n = ac.Parameter(1.0, description="ratio primary voltage (line-to-line) / secondary "
                                      "voltage (line-to-line)")
    R1 = ac.Parameter(5e-3, unit="Ohm", description="primary resistance per phase at T1Ref")
    T1Ref = ac.Parameter(293.15, unit="K", description="reference temperature of primary "
                                                      "resistance")
    alpha20_1 = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of "
                                                         "primary resistance at 20 degC")
    L1sigma = ac.Parameter(78e-6, unit="H", description="primary stray inductance per phase")
    R2 = ac.Parameter(5e-3, unit="Ohm", description="secondary resistance per phase at "
                                                    "T2Ref")
    T2Ref = ac.Parameter(293.15, unit="K", description="reference temperature of secondary "
                                                      "resistance")
    alpha20_2 = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of "
                                                         "secondary resistance at 20 degC")
    L2sigma = ac.Parameter(78e-6, unit="H", description="secondary stray inductance per "
                                                        "phase")
    T1Operational = ac.Parameter(293.15, unit="K", description="operational temperature of "
                                                              "primary resistance")
    T2Operational = ac.Parameter(293.15, unit="K", description="operational temperature of "
                                                              "secondary resistance")
    ni = ac.Parameter(lambda c: c.n * c.turns_factor(), description="turns ratio of the core")
    R1_actual = ac.Parameter(lambda c: c.R1 * (1 + _convert_alpha(c.alpha20_1, c.T1Ref)
                                               * (c.T1Operational - c.T1Ref)),
                             unit="Ohm", description="primary resistance at T1Operational")
    R2_actual = ac.Parameter(lambda c: c.R2 * (1 + _convert_alpha(c.alpha20_2, c.T2Ref)
                                               * (c.T2Operational - c.T2Ref)),
                             unit="Ohm", description="secondary resistance at T2Operational")
    v1 = ac.Variable(shape=(3,), unit="V", description="primary voltage")
    i1 = ac.Variable(shape=(3,), unit="A", description="primary current")
    v2 = ac.Variable(shape=(3,), unit="V", description="secondary voltage")
    i2 = ac.Variable(shape=(3,), unit="A", description="secondary current")
    plug1 = mp.PositivePlug(m=3)
    plug2 = mp.NegativePlug(m=3)
    r1 = mp.Resistor(m=3, R=ac.ref("R1_actual"))
    l1sigma = mp.Inductor(m=3, L=ac.ref("L1sigma"))
    r2 = mp.Resistor(m=3, R=ac.ref("R2_actual"))
    l2sigma = mp.Inductor(m=3, L=ac.ref("L2sigma"))
    core = IdealCore(m=3, n12=ac.ref("ni"), n13=ac.ref("ni"))

    @classmethod
    def turns_factor(cls) -> float:
        C1, C2 = cls.VectorGroup[0], cls.VectorGroup[1]
        return ((math.sqrt(3) if C2 == "z" else 2) * (1 if C2 == "d" else math.sqrt(3))
                / (1 if C1 == "D" else math.sqrt(3)))

    def equations(self):
        pins1, pins2 = self.plug1.pin, self.plug2.pin
        return [ac.Eq(self.v1, np.array([p.v for p in pins1])),
                ac.Eq(self.i1, np.array([p.i for p in pins1])),
                ac.Eq(self.v2, np.array([p.v for p in pins2])),
                ac.Eq(self.i2, np.array([p.i for p in pins2])),
                ac.connect(self.r1.plug_n, self.l1sigma.plug_p),
                ac.connect(self.plug1, self.r1.plug_p),
                ac.connect(self.r2.plug_p, self.plug2),
                ac.connect(self.l2sigma.plug_p, self.r2.plug_n)]


class Dy01(PartialBasicTransformer):
    """Transformer Dy1 (MSL Machines.BasicMachines.Transformers.Dy.Dy01): the primary in
    delta (``Delta1``), the secondary in star (``star2``, its star point ``starpoint2``),
    each secondary phase the core's second winding of one phase in series with the
    third winding of the phase before (``Rot2``)."""

    VectorGroup = "Dy01"
    star2 = mp.Star(m=3)
    starpoint2 = NegativePin()
    Delta1 = mp.Delta(m=3)
    Rot2 = mp.Delta(m=3)

    def equations(self):
        c = ac.connect
        return [c(self.star2.pin_n, self.starpoint2), c(self.l2sigma.plug_n, self.Rot2.plug_p),
                c(self.Delta1.plug_p, self.r1.plug_p), c(self.Delta1.plug_n, self.core.plug_n1),
                c(self.l1sigma.plug_n, self.core.plug_p1),
                c(self.core.plug_n2, self.core.plug_p3), c(self.core.plug_n3, self.Rot2.plug_n),
                c(self.core.plug_p2, self.star2.plug_p)]


class Dd00(PartialBasicTransformer):
    """Transformer Dd0 (MSL Machines.BasicMachines.Transformers.Dd.Dd00): primary and
    secondary in delta (``Delta1``, ``Delta2``), each secondary phase the core's second
    and third windings of that phase in series."""

    VectorGroup = "Dd00"
    Delta1 = mp.Delta(m=3)
    Delta2 = mp.Delta(m=3)

    def equations(self):
        c = ac.connect
        return [c(self.r1.plug_p, self.Delta1.plug_p), c(self.Delta2.plug_p, self.r2.plug_p),
                c(self.l1sigma.plug_n, self.core.plug_p1),
                c(self.Delta1.plug_n, self.core.plug_n1),
                c(self.core.plug_n2, self.core.plug_p3),
                c(self.core.plug_p2, self.l2sigma.plug_n),
                c(self.core.plug_n3, self.Delta2.plug_n)]
