"""Random hybrid mechanical systems, control loops and inline expressions for the hybrid
fuzzer, each with its hand-written reference (hybrid_reference.py).

* ``friction``: a mass on the ground with Coulomb friction that sticks
  (``translational.SupportFriction``, a table f = F_c + F_v v, stiction ``peak``) or
  Karnopp's friction with its band |v| < dv (``friction.translational.KarnoppFriction``),
  a linear or cubic spring (f = c1 x + c3 x^3), optionally a damper, driven by a sine
  force with a bias.  ``rotational_friction``: the same on an inertia, with
  ``rotational.BearingFriction`` (a torque table, stiction ``peak``) or
  ``friction.rotational.KarnoppFriction``, a torsion spring, a damper and a sine torque.
* ``loop``: a feedback loop r - y -> gain -> Limiter or DeadZone (Blocks.Nonlinear) ->
  FirstOrder or SecondOrder plant -> y, the reference a sine with an offset.
* ``inline``: two states, der(x_i) = -l_i x_i + c_i T_i(x1, x2, time) with T_i a random
  expression tree of sin, exp(-u^2), products, means and if_else of relations, of
  depth 1..5, written inline in one component.
* ill-posed: the inline system with x2 in no equation and its equation replaced by a
  second one of x1 (structurally singular: the culprits are the two states).
"""
from __future__ import annotations

import math

import numpy as np

import acausal as ac
from acausal.library import blocks
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.friction import rotational as rot_friction
from acausal.library.friction.translational import KarnoppFriction

from .hybrid_reference import HybridCase, integrate_modes

__all__ = ["CubicSpring", "CubicTorsionSpring", "friction", "rotational_friction", "loop",
           "inline", "ill_posed_inline"]


class CubicSpring(tr.PartialCompliant):
    """A hardening spring:  f = c1 s_rel + c3 s_rel^3."""

    c1 = ac.Parameter(1.0, unit="N/m", description="linear stiffness")
    c3 = ac.Parameter(0.0, unit="N/m3", description="cubic stiffness")

    def equations(self):
        return [ac.Eq(self.f, self.c1 * self.s_rel
                               + self.c3 * self.s_rel**3)]


class CubicTorsionSpring(rot.PartialCompliant):
    """A hardening torsion spring:  tau = c1 phi_rel + c3 phi_rel^3."""

    c1 = ac.Parameter(1.0, unit="N.m/rad", description="linear stiffness")
    c3 = ac.Parameter(0.0, unit="N.m/rad3", description="cubic stiffness")

    def equations(self):
        return [ac.Eq(self.tau, self.c1 * self.phi_rel
                               + self.c3 * self.phi_rel**3)]


def _lu(ch, lo, hi):
    return float(f"{10 ** ch.uniform(math.log10(lo), math.log10(hi)):.4g}")


# ------------------------------------------------------------------ friction
def rotational_friction(ch) -> HybridCase:
    """The friction kind on an inertia: ``BearingFriction`` (a torque table, stiction
    ``peak``) or the rotational ``KarnoppFriction``, a torsion spring, a damper and a
    sine torque; the same hand-written reference with J, phi, w, tau for m, s, v, f."""
    return friction(ch, rotational=True)


def friction(ch, rotational=False) -> HybridCase:
    f = _lu(ch, 0.2, 5.0)
    w = 2 * math.pi * f
    m = _lu(ch, 0.1, 10.0)
    F0 = _lu(ch, 1.0, 10.0)
    p = dict(law=ch.choice(["support", "karnopp"]), m=m, f=f, F0=F0,
             bias=round(ch.uniform(-0.5, 0.5) * F0, 4), phase=round(ch.uniform(0, 6.28), 4),
             Fc=round(ch.uniform(0.1, 0.9) * F0, 4), Fv=ch.choice([0.0, round(m * w * 0.1, 4)]),
             c1=float(f"{m * (w * ch.uniform(0.3, 3.0)) ** 2:.4g}"),
             d=ch.choice([0.0, round(m * w * ch.uniform(0.05, 0.5), 4)]),
             periods=ch.integer(2, 5))
    vscale = F0 / (m * w)
    p["c3"] = ch.choice([0.0, float(f"{p['c1'] * ch.uniform(0.1, 2.0) / (F0 / p['c1']) ** 2:.4g}")])
    p["v0"] = ch.choice([0.0, round(ch.uniform(-1, 1) * vscale, 6)])
    p["s0"] = round(ch.uniform(-0.5, 0.5) * F0 / p["c1"], 6)
    if p["law"] == "support":
        p["peak"] = ch.choice([1.0, 1.3])
        Fs = p["peak"] * p["Fc"]
    else:
        Fs = p["Fs"] = round(p["Fc"] * ch.uniform(1.0, 1.5), 4)
        p["vs"] = float(f"{vscale * ch.uniform(0.01, 0.3):.4g}")
        p["dv"] = float(f"{vscale * _lu(ch, 1e-6, 1e-4):.3g}")
        if abs(p["v0"]) < p["dv"]:
            p["v0"] = 0.0
    t_end = p["periods"] / f

    def force(t):
        return p["bias"] + F0 * math.sin(w * t + p["phase"])

    def applied(t, y):
        x, v = y
        return force(t) - p["c1"] * x - p["c3"] * x ** 3 - p["d"] * v

    def sliding(v, direction):
        """The sliding force in a direction (+1, -1): v may be 0 as a slide starts."""
        if p["law"] == "support":
            return direction * p["Fc"] + p["Fv"] * v
        level = p["Fc"] + (p["Fs"] - p["Fc"]) * math.exp(-(v / p["vs"]) ** 2)
        return direction * level + p["Fv"] * v

    def friction_force(t, y, mode):
        if mode != 0:
            return sliding(y[1], mode)
        return min(max(applied(t, y), -Fs), Fs)

    def rhs(t, y, mode):
        x, v = y
        if mode == 0 and p["law"] == "support":
            return [0.0, 0.0]
        return [v, (applied(t, y) - friction_force(t, y, mode)) / m]

    def guards(t, y, mode):
        v, Fa = y[1], applied(t, y)
        band = p.get("dv", 0.0)
        if mode == 1:
            return [(v - band, -1), (1.0, 1)]
        if mode == -1:
            return [(v + band, 1), (1.0, 1)]
        if p["law"] == "support":
            return [(Fa - Fs, 1), (Fa + Fs, -1)]
        return [(v - band, 1), (v + band, -1)]

    def switch(t, y, mode, k):
        y = np.array(y)
        if mode == 0:
            return y, (1 if k == 0 else -1)
        y[1] = 0.0                      # stopped (Karnopp: entering the band)
        if p["law"] == "karnopp":
            return y, 0
        Fa = applied(t, y)
        return y, (0 if abs(Fa) <= Fs else (1 if Fa > 0 else -1))

    def outputs(t, y, mode):
        return {"mass.s": y[0], "mass.v": y[1], "fric.f": friction_force(t, y, mode)}

    y0 = [p["s0"], p["v0"]]
    if p["v0"] != 0.0:
        mode0 = 1 if p["v0"] > 0 else -1
    else:
        Fa0 = applied(0.0, y0)
        mode0 = 0 if p["law"] == "karnopp" or abs(Fa0) <= Fs else (1 if Fa0 > 0 else -1)

    def model():
        return (_friction_inertia if rotational else _friction_mass)(p)

    body, (s_, v_, f_) = ("inertia", ("phi", "w", "tau")) if rotational else ("mass", ("s", "v", "f"))
    names = {"mass.s": f"{body}.{s_}", "mass.v": f"{body}.{v_}", "fric.f": f"fric.{f_}"}

    def energy(get):
        x, v = get(names["mass.s"]), get(names["mass.v"])
        stored = m * v ** 2 / 2 + p["c1"] * x ** 2 / 2 + p["c3"] * x ** 4 / 4
        return get("sine.y") * v, stored, get(names["fric.f"]) * v + p["d"] * v ** 2

    def named_outputs(t, y, mode):
        return {names[k]: val for k, val in outputs(t, y, mode).items()}

    ref = lambda: integrate_modes(rhs, guards, switch, named_outputs, y0, mode0,  # noqa: E731
                                  t_end)
    units = ("rad", "rad/s", "N.m") if rotational else ("m", "m/s", "N")
    signals = dict(zip(names.values(), units))
    return HybridCase("rotational friction" if rotational else "friction", p, t_end, model,
                      ref, signals, energy)


def _friction_mass(p):
    class FrictionMass(ac.Component):
        def __init__(self):
            super().__init__()
            self.fixed = tr.Fixed()
            self.mass = tr.Mass(m=p["m"], s={"start": p["s0"], "fixed": True},
                                v={"start": p["v0"], "fixed": True})
            if p["law"] == "support":
                self.fric = tr.SupportFriction(f_pos=((0.0, p["Fc"]), (1.0, p["Fc"] + p["Fv"])),
                                               peak=p["peak"])
            else:
                self.fric = KarnoppFriction(F_c=p["Fc"], F_s=p["Fs"], v_s=p["vs"],
                                            F_v=p["Fv"], dv=p["dv"])
            self.spring = CubicSpring(c1=p["c1"], c3=p["c3"])
            self.damper = tr.Damper(d=p["d"])
            self.force = tr.Force()
            self.sine = blocks.Sine(amplitude=p["F0"], f=p["f"], phase=p["phase"],
                                    offset=p["bias"])

        def equations(self):
            eqs = [ac.connect(self.sine.y, self.force.f),
                   ac.connect(self.force.flange, self.mass.flange_a),
                   ac.connect(self.fixed.flange, self.spring.flange_a, self.damper.flange_a),
                   ac.connect(self.mass.flange_b, self.spring.flange_b, self.damper.flange_b)]
            if p["law"] == "support":
                eqs.append(ac.connect(self.fric.flange_a, self.mass.flange_b))
            else:
                eqs += [ac.connect(self.fric.flange_a, self.fixed.flange),
                        ac.connect(self.fric.flange_b, self.mass.flange_b)]
            return eqs
    return FrictionMass()


def _friction_inertia(p):
    """The rotational twin: BearingFriction's housing is the ``support`` on the fixed
    flange, its shaft the inertia's flange_b."""
    class FrictionInertia(ac.Component):
        def __init__(self):
            super().__init__()
            self.fixed = rot.Fixed()
            self.inertia = rot.Inertia(J=p["m"], phi={"start": p["s0"], "fixed": True},
                                       w={"start": p["v0"], "fixed": True})
            if p["law"] == "support":
                self.fric = rot.BearingFriction(
                    tau_pos=((0.0, p["Fc"]), (1.0, p["Fc"] + p["Fv"])), peak=p["peak"],
                    useSupport=True)
            else:
                self.fric = rot_friction.KarnoppFriction(F_c=p["Fc"], F_s=p["Fs"], v_s=p["vs"],
                                                         F_v=p["Fv"], dv=p["dv"])
            self.spring = CubicTorsionSpring(c1=p["c1"], c3=p["c3"])
            self.damper = rot.Damper(d=p["d"])
            self.torque = rot.Torque()
            self.sine = blocks.Sine(amplitude=p["F0"], f=p["f"], phase=p["phase"],
                                    offset=p["bias"])

        def equations(self):
            eqs = [ac.connect(self.sine.y, self.torque.tau),
                   ac.connect(self.torque.flange, self.inertia.flange_a),
                   ac.connect(self.fixed.flange, self.spring.flange_a, self.damper.flange_a),
                   ac.connect(self.inertia.flange_b, self.spring.flange_b,
                              self.damper.flange_b)]
            if p["law"] == "support":
                eqs += [ac.connect(self.fric.flange_a, self.inertia.flange_b),
                        ac.connect(self.fric.support, self.fixed.flange)]
            else:
                eqs += [ac.connect(self.fric.flange_a, self.fixed.flange),
                        ac.connect(self.fric.flange_b, self.inertia.flange_b)]
            return eqs
    return FrictionInertia()


# ------------------------------------------------------------------ loop
def loop(ch) -> HybridCase:
    f = _lu(ch, 0.1, 2.0)
    p = dict(nl=ch.choice(["Limiter", "DeadZone"]), plant=ch.choice(["FirstOrder", "SecondOrder"]),
             f=f, R=_lu(ch, 0.5, 5.0), offset=round(ch.uniform(-1, 1), 3),
             phase=round(ch.uniform(0, 6.28), 4), k=_lu(ch, 0.5, 20.0),
             uMax=round(ch.uniform(0.2, 3.0), 3), kp=_lu(ch, 0.5, 3.0),
             T=float(f"{_lu(ch, 0.05, 2.0) / f:.4g}"), wn=float(f"{2 * math.pi * f * _lu(ch, 0.5, 5.0):.4g}"),
             D=round(ch.uniform(0.1, 1.5), 3), y0=round(ch.uniform(-1, 1), 3),
             periods=ch.integer(2, 4))
    p["uMin"] = -round(p["uMax"] * ch.uniform(0.3, 1.5), 3)
    w = 2 * math.pi * f
    t_end = p["periods"] / f
    second = p["plant"] == "SecondOrder"

    def u_of(t, y):
        r = p["offset"] + p["R"] * math.sin(w * t + p["phase"])
        return p["k"] * (r - y[0])

    def nl(u, region):
        if p["nl"] == "Limiter":
            return p["uMax"] if region == 1 else (p["uMin"] if region == -1 else u)
        return u - p["uMax"] if region == 1 else (u - p["uMin"] if region == -1 else 0.0)

    def rhs(t, y, mode):
        v = nl(u_of(t, y), mode)
        if second:
            return [y[1], p["wn"] * (p["wn"] * (p["kp"] * v - y[0]) - 2 * p["D"] * y[1])]
        return [(p["kp"] * v - y[0]) / p["T"]]

    def guards(t, y, mode):
        u = u_of(t, y)
        return [(u - p["uMax"], -1 if mode == 1 else 1), (u - p["uMin"], 1 if mode == -1 else -1)]

    def switch(t, y, mode, k):
        if k == 0:
            return y, (0 if mode == 1 else 1)
        return y, (0 if mode == -1 else -1)

    def outputs(t, y, mode):
        return {"plant.y": y[0], "nl.y": nl(u_of(t, y), mode)}

    y0 = [p["y0"]] + ([0.0] if second else [])
    u0 = u_of(0.0, y0)
    mode0 = 1 if u0 > p["uMax"] else (-1 if u0 < p["uMin"] else 0)

    def model():
        class Loop(ac.Component):
            def __init__(self):
                super().__init__()
                self.r = blocks.Sine(amplitude=p["R"], f=f, phase=p["phase"], offset=p["offset"])
                self.fb = blocks.Feedback()
                self.gain = blocks.Gain(k=p["k"])
                self.nl = getattr(blocks, p["nl"])(uMax=p["uMax"], uMin=p["uMin"])
                if second:
                    self.plant = blocks.SecondOrder(k=p["kp"], w=p["wn"], D=p["D"],
                                                    initType="InitialState", y_start=p["y0"])
                else:
                    self.plant = blocks.FirstOrder(k=p["kp"], T=p["T"], initType="InitialState",
                                                   y_start=p["y0"])

            def equations(self):
                return [ac.connect(self.r.y, self.fb.u1), ac.connect(self.plant.y, self.fb.u2),
                        ac.connect(self.fb.y, self.gain.u), ac.connect(self.gain.y, self.nl.u),
                        ac.connect(self.nl.y, self.plant.u)]
        return Loop()

    ref = lambda: integrate_modes(rhs, guards, switch, outputs, y0, mode0, t_end)  # noqa: E731
    return HybridCase("loop", p, t_end, model, ref, {"plant.y": "1", "nl.y": "1"})


# ------------------------------------------------------------------ inline expressions
def _tree(ch, depth, conds):
    """A random expression tree as nested tuples; ``conds`` collects the relations."""
    if depth == 0 or ch.boolean(0.2):
        leaf = ch.integer(0, 3)
        if leaf < 2:
            return ("x", leaf)
        if leaf == 2:
            return ("sin_t", round(ch.uniform(0.5, 3.0), 3), round(ch.uniform(0, 6.28), 3))
        return ("const", round(ch.uniform(-1, 1), 3))
    op = ch.integer(0, 4)
    if op == 0:
        return ("sin", round(ch.uniform(0.5, 3.0), 3), round(ch.uniform(-1, 1), 3),
                _tree(ch, depth - 1, conds))
    if op == 1:
        return ("gauss", _tree(ch, depth - 1, conds))
    if op in (2, 3):
        return ("mul" if op == 2 else "mean", _tree(ch, depth - 1, conds),
                _tree(ch, depth - 1, conds))
    left = _tree(ch, depth - 1, conds)          # (its own relations numbered first)
    cond = ("cond", len(conds), left, round(ch.uniform(-0.5, 0.5), 3))
    conds.append(cond)
    return ("if", cond, _tree(ch, depth - 1, conds), _tree(ch, depth - 1, conds))


def _num(e, t, x, mode):
    """The tree's value; a relation reads its truth from ``mode`` (None: computes it)."""
    op = e[0]
    if op == "x":
        return x[e[1]]
    if op == "sin_t":
        return math.sin(e[1] * t + e[2])
    if op == "const":
        return e[1]
    if op == "sin":
        return math.sin(e[1] * _num(e[3], t, x, mode) + e[2])
    if op == "gauss":
        return math.exp(-_num(e[1], t, x, mode) ** 2)
    if op == "mul":
        return _num(e[1], t, x, mode) * _num(e[2], t, x, mode)
    if op == "mean":
        return (_num(e[1], t, x, mode) + _num(e[2], t, x, mode)) / 2
    cond = e[1]
    truth = mode[cond[1]] if mode is not None else _num(cond[2], t, x, None) > cond[3]
    return _num(e[2] if truth else e[3], t, x, mode)


def _sym(e, x):
    op = e[0]
    if op == "x":
        return x[e[1]]
    if op == "sin_t":
        return ac.sin(e[1] * ac.time + e[2])
    if op == "const":
        return e[1]
    if op == "sin":
        return ac.sin(e[1] * _sym(e[3], x) + e[2])
    if op == "gauss":
        return ac.exp(-_sym(e[1], x) ** 2)
    if op == "mul":
        return _sym(e[1], x) * _sym(e[2], x)
    if op == "mean":
        return (_sym(e[1], x) + _sym(e[2], x)) / 2
    cond = e[1]
    return ac.if_else(_sym(cond[2], x) > cond[3], _sym(e[2], x), _sym(e[3], x))


def _show(e) -> str:
    op = e[0]
    if op == "x":
        return f"x{e[1] + 1}"
    if op == "sin_t":
        return f"sin({e[1]}*t+{e[2]})"
    if op == "const":
        return repr(e[1])
    if op == "sin":
        return f"sin({e[1]}*{_show(e[3])}+{e[2]})"
    if op == "gauss":
        return f"exp(-({_show(e[1])})^2)"
    if op in ("mul", "mean"):
        sep = "*" if op == "mul" else "+"
        return f"({_show(e[1])}{sep}{_show(e[2])}){'/2' if op == 'mean' else ''}"
    return f"if_else({_show(e[1][2])}>{e[1][3]}, {_show(e[2])}, {_show(e[3])})"


def _inline_draw(ch):
    conds: list = []
    p = dict(l1=round(ch.uniform(0.5, 3.0), 3), l2=round(ch.uniform(0.5, 3.0), 3),
             c1=round(ch.uniform(-2, 2), 3), c2=round(ch.uniform(-2, 2), 3),
             x10=round(ch.uniform(-1, 1), 3), x20=round(ch.uniform(-1, 1), 3))
    trees = (_tree(ch, ch.integer(1, 5), conds), _tree(ch, ch.integer(1, 5), conds))
    p["T1"], p["T2"] = _show(trees[0]), _show(trees[1])
    return p, trees, conds


def _inline_model(p, trees, defect=False):
    class Inline(ac.Component):
        x1 = ac.Variable(start=p["x10"], fixed=True)
        x2 = ac.Variable(start=p["x20"], fixed=not defect)

        def equations(self):
            # the defect: x2 in no equation, and a second equation of x1 alone
            x = (self.x1, self.x1 if defect else self.x2)
            eq2 = (ac.Eq(self.x1, ac.sin(ac.time)) if defect else
                   ac.Eq(ac.der(self.x2), -p["l2"] * self.x2 + p["c2"] * _sym(trees[1], x)))
            return [ac.Eq(ac.der(self.x1), -p["l1"] * self.x1 + p["c1"] * _sym(trees[0], x)),
                    eq2]

    class System(ac.Component):
        def __init__(self):
            super().__init__()
            self.sys = Inline()
    return System()


def inline(ch) -> HybridCase:
    p, trees, conds = _inline_draw(ch)
    t_end = 5.0

    def rhs(t, y, mode):
        return [-p["l1"] * y[0] + p["c1"] * _num(trees[0], t, y, mode),
                -p["l2"] * y[1] + p["c2"] * _num(trees[1], t, y, mode)]

    def guards(t, y, mode):
        return [(_num(c[2], t, y, mode) - c[3], -1 if mode[c[1]] else 1) for c in conds]

    def switch(t, y, mode, k):
        # the relation that fired flips; any other that a changed branch moved across
        # its threshold is read anew, as at an event every relation is
        mode = list(mode)
        mode[k] = not mode[k]
        for _ in range(len(conds)):
            new = [m if j == k else _num(c[2], t, y, mode) > c[3]
                   for j, (c, m) in enumerate(zip(conds, mode))]
            if new == mode:
                break
            mode = new
        return y, tuple(mode)

    def outputs(t, y, mode):
        return {"sys.x1": y[0], "sys.x2": y[1]}

    y0 = [p["x10"], p["x20"]]
    mode0 = tuple(_num(c[2], 0.0, y0, None) > c[3] for c in conds)
    ref = lambda: integrate_modes(rhs, guards, switch, outputs, y0, mode0, t_end)  # noqa: E731
    return HybridCase("inline", p, t_end, lambda: _inline_model(p, trees), ref,
                      {"sys.x1": "1", "sys.x2": "1"})


def ill_posed_inline(ch) -> HybridCase:
    p, trees, _ = _inline_draw(ch)
    return HybridCase("ill-posed inline", p, 1.0, lambda: _inline_model(p, trees, True),
                      expect="ill-posed", culprits=("sys.x1", "sys.x2"))
