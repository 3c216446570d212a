"""Random hybrid circuits and hydraulic networks for the hybrid fuzzer, each with its
hand-written reference (hybrid_reference.py).

* ``rectifier``: a sine source, R1, optionally an inductor L with a resistor Rp to
  ground, an ideal diode (Ron, Goff, Vknee: Modelica.Electrical.Analog.Ideal.IdealDiode),
  a capacitor C with a load Rl, optionally a nonlinear conductor i = g u + g3 u^3 across
  it, optionally a load R2 switched at a time (ideal opening or closing switch), and
  optionally a branch R3 + controlled switch + C2 closed while the capacitor voltage
  exceeds a level (the branch fed from the capacitor or from the source).
* ``orifices``: 2-4 hydraulic volumes with random initial pressures joined in a chain
  by laminar or turbulent (regularized) orifices; no source, so the stored energy plus
  the energy dissipated stays the initial energy.
* ill-posed: the rectifier with a second voltage source in parallel with the first, or
  with its capacitor's fixed start contradicting a voltage source across it; or (``loop``)
  with a second, constant voltage source joined to the first through an ideal diode or
  two ideal closing switches in series, each with Ron = 0: once the diode conducts (the
  sine passes the second source's voltage plus the knee within the first period) or both
  switches have closed (at times within the run), the loop of sources has no resistance,
  its current is undetermined and the voltages contradict each other.

The diode and the switches are piecewise linear (closed: a resistance, open: a
conductance), so each mode of a circuit is linear in the node potentials: the reference
solves the node equations of the mode by hand.
"""
from __future__ import annotations

import math

import numpy as np

import acausal as ac
from acausal.library import electrical as el
from acausal.library import hydraulics as hy
from acausal.library.blocks import Step
from acausal.library.electrical.interfaces import OnePort
from acausal.library.hydraulics.interfaces import F_tr

from .hybrid_reference import HybridCase, integrate_modes

__all__ = ["CubicConductor", "rectifier", "orifices", "ill_posed_circuit", "ill_posed_loop"]


class CubicConductor(OnePort):
    """A nonlinear conductor:  i = g v + g3 v^3."""

    g = ac.Parameter(1e-3, unit="S", description="linear conductance")
    g3 = ac.Parameter(0.0, unit="S/V2", description="cubic conductance")

    def equations(self):
        return [ac.Eq(self.i, self.g * self.v + self.g3 * self.v**3)]


def _log_uniform(ch, lo, hi):
    return float(f"{10 ** ch.uniform(math.log10(lo), math.log10(hi)):.4g}")


def _draw_rectifier(ch) -> dict:
    f = _log_uniform(ch, 20.0, 200.0)
    A = _log_uniform(ch, 1.0, 20.0)
    p = dict(f=f, A=A, offset=round(ch.uniform(-0.3, 0.3) * A, 4),
             phase=round(ch.uniform(0.2, 6.0), 4), R1=_log_uniform(ch, 1.0, 100.0),
             Rl=_log_uniform(ch, 100.0, 1e4), Ron=ch.choice([1e-5, 1e-4, 1e-3]),
             Goff=ch.choice([1e-5, 1e-4, 1e-3]), Vknee=ch.choice([0.0, 0.3, 0.7]),
             periods=ch.integer(2, 5))
    p["C"] = float(f"{_log_uniform(ch, 0.2, 5.0) / (f * p['Rl']):.4g}")
    p["vC0"] = round(ch.uniform(-0.5, 0.5) * A, 4)
    if ch.boolean(0.4):
        p["L"] = float(f"{_log_uniform(ch, 0.05, 1.0) * p['R1'] / f:.4g}")
        p["Rp"] = _log_uniform(ch, 100.0, 1e4)
        p["iL0"] = round(ch.uniform(-0.5, 0.5) * A / p["R1"], 6)
    if ch.boolean(0.4):
        p["g"] = _log_uniform(ch, 1e-4, 1e-2)
        p["g3"] = float(f"{p['g'] * ch.uniform(0.1, 1.0) / A ** 2:.4g}")
    if ch.boolean(0.4):
        p["R2"] = float(f"{p['Rl'] * _log_uniform(ch, 0.3, 3.0):.4g}")
        p["t_sw"] = round(ch.uniform(0.2, 0.8) * p["periods"] / f, 6)
        p["closing"] = ch.boolean(0.5)
    if ch.boolean(0.5):
        p["level"] = round(ch.uniform(0.1, 0.8) * A, 4)
        p["R3"] = _log_uniform(ch, 10.0, 1e3)
        p["C2"] = float(f"{p['C'] * _log_uniform(ch, 0.1, 2.0):.4g}")
        p["share"] = ch.boolean(0.5)
    return p


def _rectifier_model(p, defect=None):
    has = p.__contains__

    class Rectifier(ac.Component):
        def __init__(self):
            super().__init__()
            self.gnd = el.Ground()
            self.src = el.SineVoltage(V=p["A"], f=p["f"], phase=p["phase"], offset=p["offset"])
            self.R1 = el.Resistor(R=p["R1"])
            self.D = el.IdealDiode(Ron=p["Ron"], Goff=p["Goff"], Vknee=p["Vknee"])
            self.C = el.Capacitor(C=p["C"], v={"start": p["vC0"], "fixed": True})
            self.Rl = el.Resistor(R=p["Rl"])
            if has("L"):
                self.L = el.Inductor(L=p["L"], i={"start": p["iL0"], "fixed": True})
                self.Rp = el.Resistor(R=p["Rp"])
            if has("g"):
                self.NL = CubicConductor(g=p["g"], g3=p["g3"])
            if has("R2"):
                cls = el.IdealClosingSwitch if p["closing"] else el.IdealOpeningSwitch
                self.sw = cls(booleanControl=False, Ron=p["Ron"], Goff=p["Goff"])
                self.ctl = Step(height=1.0, startTime=p["t_sw"])
                self.R2 = el.Resistor(R=p["R2"])
            if has("level"):
                self.csw = el.ControlledIdealClosingSwitch(level=p["level"], Ron=p["Ron"],
                                                          Goff=p["Goff"])
                self.R3 = el.Resistor(R=p["R3"])
                self.C2 = el.Capacitor(C=p["C2"], v={"start": 0.0, "fixed": True})
            if defect == "parallel sources":
                self.src2 = el.ConstantVoltage(V=p["A"] / 2)
            if defect == "source across the capacitor":
                self.src2 = el.ConstantVoltage(V=p["vC0"] + 1.0)
            if defect in ("diode loop", "switch loop"):
                self.src2 = el.ConstantVoltage(V=p["V2"])
            if defect == "diode loop":
                self.D2 = el.IdealDiode(Ron=0.0, Goff=p["Goff"], Vknee=p["Vknee"])
            if defect == "switch loop":
                for k in (1, 2):
                    # open at the start: ``off`` starts true (its default start, false,
                    # is read by the relation in ``off`` before its equation has set it)
                    setattr(self, f"sw{k}", el.IdealClosingSwitch(
                        booleanControl=False, Ron=0.0, Goff=p["Goff"],
                        off={"start": True}))
                    setattr(self, f"ctl{k}", Step(height=1.0, startTime=p[f"t{k}"]))

        def equations(self):
            g, n3 = self.gnd.p, (self.Rp.p if has("L") else self.R1.n)
            eqs = [ac.connect(self.src.n, g), ac.connect(self.src.p, self.R1.p),
                   ac.connect(n3, self.D.p),
                   ac.connect(self.D.n, self.C.p, self.Rl.p),
                   ac.connect(self.C.n, self.Rl.n, g)]
            if has("L"):
                eqs += [ac.connect(self.R1.n, self.L.p), ac.connect(self.L.n, self.Rp.p),
                        ac.connect(self.Rp.n, g)]
            if has("g"):
                eqs += [ac.connect(self.NL.p, self.C.p), ac.connect(self.NL.n, g)]
            if has("R2"):
                eqs += [ac.connect(self.C.p, self.R2.p), ac.connect(self.R2.n, self.sw.p),
                        ac.connect(self.sw.n, g), ac.connect(self.ctl.y, self.sw.control)]
            if has("level"):
                feed = self.C.p if p["share"] else self.src.p
                eqs += [ac.connect(feed, self.R3.p), ac.connect(self.R3.n, self.csw.p),
                        ac.connect(self.csw.n, self.C2.p), ac.connect(self.C2.n, g),
                        ac.connect(self.csw.control, self.C.p)]
            if defect == "parallel sources":
                eqs += [ac.connect(self.src2.p, self.src.p), ac.connect(self.src2.n, g)]
            if defect == "source across the capacitor":
                eqs += [ac.connect(self.src2.p, self.C.p), ac.connect(self.src2.n, g)]
            if defect == "diode loop":
                eqs += [ac.connect(self.src.p, self.D2.p), ac.connect(self.D2.n, self.src2.p),
                        ac.connect(self.src2.n, g)]
            if defect == "switch loop":
                eqs += [ac.connect(self.src.p, self.sw1.p), ac.connect(self.sw1.n, self.sw2.p),
                        ac.connect(self.sw2.n, self.src2.p), ac.connect(self.src2.n, g),
                        ac.connect(self.ctl1.y, self.sw1.control),
                        ac.connect(self.ctl2.y, self.sw2.control)]
            return eqs
    return Rectifier()


def _diode_line(p, on):
    """The diode's i = a v + b in a mode (MSL characteristic with the knee)."""
    if on:
        return 1.0 / p["Ron"], -p["Vknee"] / p["Ron"] + p["Goff"] * p["Vknee"]
    return p["Goff"], 0.0


def _rectifier_reference(p):
    has = p.__contains__
    iL, iv5 = (1, 2 if has("L") else 1) if has("L") else (None, 1)
    w = 2 * math.pi * p["f"]

    def vs(t):
        return p["offset"] + p["A"] * math.sin(w * t + p["phase"])

    def r_switch(closed):
        return p["Ron"] if closed else 1.0 / p["Goff"]

    def solve(t, y, mode):
        d_on, passed, c_closed = mode
        sw_closed = passed == p.get("closing")
        a, b = _diode_line(p, d_on)
        v4, u = y[0], vs(t)
        if has("L"):
            v3 = (y[iL] + a * v4 - b) / (1.0 / p["Rp"] + a)
            i1 = y[iL]
        else:
            v3 = (u / p["R1"] + a * v4 - b) / (1.0 / p["R1"] + a)
            i1 = (u - v3) / p["R1"]
        i_d = a * (v3 - v4) + b
        i2 = v4 / (p["R2"] + r_switch(sw_closed)) if has("R2") else 0.0
        i3 = 0.0
        if has("level"):
            i3 = ((v4 if p["share"] else u) - y[iv5]) / (p["R3"] + r_switch(c_closed))
        return dict(u=u, v3=v3, v4=v4, i1=i1, i_d=i_d, i2=i2, i3=i3)

    def rhs(t, y, mode):
        s = solve(t, y, mode)
        i_nl = p["g"] * s["v4"] + p["g3"] * s["v4"] ** 3 if has("g") else 0.0
        i_out = s["v4"] / p["Rl"] + i_nl + s["i2"] + (s["i3"] if p.get("share") else 0.0)
        dy = [(s["i_d"] - i_out) / p["C"]]
        if has("L"):
            dy.append((s["u"] - p["R1"] * y[iL] - s["v3"]) / p["L"])
        if has("level"):
            dy.append(s["i3"] / p["C2"])
        return dy

    def guards(t, y, mode):
        d_on, passed, c_closed = mode
        s = solve(t, y, mode)
        vd = s["v3"] - s["v4"]
        return [((s["i_d"] - p["Goff"] * p["Vknee"]) if d_on else (vd - p["Vknee"]),
                 -1 if d_on else 1),
                ((1.0 if passed else t - p["t_sw"]) if has("R2") else 1.0, 1),
                ((y[0] - p["level"]) if has("level") else 1.0, -1 if c_closed else 1)]

    def switch(t, y, mode, k):
        mode = list(mode)
        mode[k] = not mode[k]
        return y, tuple(mode)

    def outputs(t, y, mode):
        s = solve(t, y, mode)
        out = {"C.v": y[0], "D.i": s["i_d"], "R1.i": s["i1"]}
        if has("L"):
            out["L.i"] = y[iL]
        if has("level"):
            out["C2.v"] = y[iv5]
        return out

    y0 = [p["vC0"]] + ([p["iL0"]] if has("L") else []) + ([0.0] if has("level") else [])
    off_mode = (False, False, p["vC0"] >= p.get("level", math.inf))
    s = solve(0.0, y0, off_mode)
    d_on = s["v3"] - s["v4"] - p["Vknee"] >= 0
    mode0 = (d_on,) + off_mode[1:]
    return lambda: integrate_modes(rhs, guards, switch, outputs, y0, mode0,
                                   p["periods"] / p["f"])


def _rectifier_energy(p):
    has = p.__contains__
    lossy = ["R1", "D", "Rl"] + (["Rp"] if has("L") else []) + (["NL"] if has("g") else []) \
        + (["R2", "sw"] if has("R2") else []) + (["R3", "csw"] if has("level") else [])

    def energy(get):
        supplied = -get("src.v") * get("src.i")
        stored = p["C"] * get("C.v") ** 2 / 2
        if has("L"):
            stored = stored + p["L"] * get("L.i") ** 2 / 2
        if has("level"):
            stored = stored + p["C2"] * get("C2.v") ** 2 / 2
        dissipated = sum(get(f"{n}.v") * get(f"{n}.i") for n in lossy)
        return supplied, stored, dissipated
    return energy


def rectifier(ch) -> HybridCase:
    p = _draw_rectifier(ch)
    signals = {"C.v": "V", "D.i": "A", "R1.i": "A"}
    if "L" in p:
        signals["L.i"] = "A"
    if "level" in p:
        signals["C2.v"] = "V"
    return HybridCase("rectifier", p, p["periods"] / p["f"], lambda: _rectifier_model(p),
                      _rectifier_reference(p), signals, _rectifier_energy(p))


def ill_posed_circuit(ch) -> HybridCase:
    p = _draw_rectifier(ch)
    defect = ch.choice(["parallel sources", "source across the capacitor"])
    culprits = ("src", "src2") if defect == "parallel sources" else ("C", "src2")
    p["defect"] = defect
    return HybridCase("ill-posed circuit", p, p["periods"] / p["f"],
                      lambda: _rectifier_model(p, defect), expect="ill-posed",
                      culprits=culprits)


def ill_posed_loop(ch) -> HybridCase:
    p = _draw_rectifier(ch)
    # without the branch switched by the capacitor's voltage, which may slide (and stop
    # the run, rightly, naming its relation) before the loop closes
    for key in ("level", "R3", "C2", "share"):
        p.pop(key, None)
    defect = p["defect"] = ch.choice(["diode loop", "switch loop"])
    t_end = p["periods"] / p["f"]
    if defect == "diode loop":
        # the diode conducts once src.v - V2 > Vknee, which the sine reaches in a period
        p["V2"] = round(p["offset"] + p["A"] * ch.uniform(-0.8, 0.8) - p["Vknee"], 4)
        culprits = ("D2",)
    else:
        # the switches may close at the same instant
        p["t1"] = round(ch.uniform(0.1, 0.9) * t_end, 6)
        p["t2"] = p["t1"] if ch.boolean(0.3) else round(ch.uniform(0.1, 0.9) * t_end, 6)
        p["V2"] = round(p["A"] * ch.uniform(-1.0, 1.0), 4)
        culprits = ("sw1", "sw2")
    return HybridCase("ill-posed loop", p, t_end, lambda: _rectifier_model(p, defect),
                      expect="ill-posed", culprits=culprits)


# ------------------------------------------------------------------ hydraulics
RHO, NU, C_D, RE_TR, BETA = 900.0, 30e-6, 0.6, 1000.0, 7e8


def orifice_flow(A, dp):
    """The regularized orifice law of Egeland & Gravdahl (4.13) with F_tr of (4.42),
    from the book: laminar below the transition force, turbulent above."""
    ftr = float(F_tr(RE_TR, RHO, NU, C_D))
    x = A * dp / ftr
    if abs(x) >= 1:
        return math.copysign(C_D * A * math.sqrt(2 * abs(dp) / RHO), dp)
    return 3 * NU * RE_TR / 4 * math.sqrt(math.pi) / 2 * math.sqrt(A) * x * (3 - abs(x))


def orifices(ch) -> HybridCase:
    n = ch.integer(2, 4)
    p = {"n": n}
    for k in range(n):
        p[f"V{k}"] = _log_uniform(ch, 1e-4, 1e-2)
        p[f"p{k}"] = round(ch.uniform(0.0, 1e7), -2)
    for k in range(n - 1):
        p[f"turb{k}"] = ch.boolean(0.7)
        # areas from very small (laminar throughout) to large (turbulent)
        p[f"A{k}"] = _log_uniform(ch, 1e-9, 1e-5)
        p[f"Cl{k}"] = _log_uniform(ch, 1e-13, 1e-10)
    ftr = float(F_tr(RE_TR, RHO, NU, C_D))

    def flows(y):
        q = []
        for k in range(n - 1):
            dp = y[k] - y[k + 1]
            q.append(orifice_flow(p[f"A{k}"], dp) if p[f"turb{k}"] else p[f"Cl{k}"] * dp)
        return q

    def rhs(t, y, mode):
        q = flows(y)
        return [BETA / p[f"V{k}"] * ((q[k - 1] if k else 0.0) - (q[k] if k < n - 1 else 0.0))
                for k in range(n)]

    def guards(t, y, mode):
        # the laminar/turbulent corners |x| = 1: the law's second derivative jumps there
        out = []
        for k in range(n - 1):
            if p[f"turb{k}"]:
                x = p[f"A{k}"] * (y[k] - y[k + 1]) / ftr
                out += [(x - 1, 1 if mode[k] != 1 else -1), (x + 1, -1 if mode[k] != -1 else 1)]
        return out

    turbulent = [k for k in range(n - 1) if p[f"turb{k}"]]

    def switch(t, y, mode, k):
        j, upper = turbulent[k // 2], k % 2 == 0
        mode = list(mode)
        mode[j] = (1 if upper else -1) if mode[j] == 0 else 0
        return y, tuple(mode)

    def outputs(t, y, mode):
        q = flows(y)
        out = {f"vol{k}.p": y[k] for k in range(n)}
        out.update({f"orf{k}.q": q[k] for k in range(n - 1)})
        return out

    y0 = [p[f"p{k}"] for k in range(n)]
    mode0 = tuple(_region(p, y0, ftr, j) for j in range(n - 1))
    # the time for the largest pressure difference to settle, at the initial flow
    q0 = np.abs(flows(y0)) + 1e-30
    dp0 = np.abs(np.diff(y0)) + 1.0
    tau = min(float(np.min(dp0 * min(p[f"V{k}"] for k in range(n)) / BETA / q0)), 10.0)
    t_end = float(f"{3 * tau:.3g}")

    def model():
        class Orifices(ac.Component):
            def __init__(self):
                super().__init__()
                for k in range(n):
                    setattr(self, f"vol{k}", hy.Volume(V=p[f"V{k}"], beta=BETA,
                                                       p={"start": p[f"p{k}"], "fixed": True}))
                for k in range(n - 1):
                    setattr(self, f"orf{k}",
                            hy.TurbulentOrifice(A=p[f"A{k}"], rho=RHO, nu=NU, C_d=C_D,
                                                Re_tr=RE_TR) if p[f"turb{k}"]
                            else hy.LaminarOrifice(C_l=p[f"Cl{k}"]))

            def equations(self):
                eqs = []
                for k in range(n - 1):
                    o = getattr(self, f"orf{k}")
                    eqs += [ac.connect(getattr(self, f"vol{k}").port, o.port_a),
                            ac.connect(o.port_b, getattr(self, f"vol{k + 1}").port)]
                return eqs
        return Orifices()

    def energy(get):
        stored = sum(p[f"V{k}"] * get(f"vol{k}.p") ** 2 / (2 * BETA) for k in range(n))
        dissipated = sum(get(f"orf{k}.dp") * get(f"orf{k}.q") for k in range(n - 1))
        return 0 * stored, stored, dissipated

    signals = {f"vol{k}.p": "Pa" for k in range(n)}
    signals.update({f"orf{k}.q": "m3/s" for k in range(n - 1)})
    p["t_end"] = t_end
    ref = lambda: integrate_modes(rhs, guards, switch, outputs, y0, mode0, t_end,  # noqa: E731
                                  method="Radau")
    return HybridCase("orifices", p, t_end, model, ref, signals, energy)


def _region(p, y, ftr, k):
    if not p[f"turb{k}"]:
        return 0
    x = p[f"A{k}"] * (y[k] - y[k + 1]) / ftr
    return 1 if x >= 1 else (-1 if x <= -1 else 0)
