"""Random lumped networks: a netlist, how to draw one, and how to build it in acausal.

A netlist is a list of elements between numbered nodes; node 0 is the ground
(electrical) or the housing (mechanical, a ``Fixed``).  Element kinds:

* electrical: ``R``, ``C``, ``L``, ``V`` (voltage source), ``I`` (current source);
  ``a`` is pin p, ``b`` pin n;
* translational and rotational: ``mass`` (``Mass`` / ``Inertia``; flange_a at ``a``,
  flange_b at ``b`` or free: a mass with both flanges connected is a rigid coupling),
  ``spring``, ``damper``, ``force`` (``Force`` / ``Torque`` on node ``a``, driven by
  ``blocks.Sine``), ``gear`` (rotational ``IdealGear``, ratio phi_a / phi_b).

Sources are sums of sines u(t) = sum a sin(2 pi f t), zero at t = 0: a single term is a
library ``SineVoltage`` / ``SineCurrent`` (or a ``Signal*`` source fed by a
``blocks.Sine``), two terms a ``Signal*`` source fed by ``blocks.Add`` of two sines.

Parameter values are decimal strings from the E12 series over a few decades, so the
reference can take them exactly (``Fraction("4.7e3")``) while acausal gets the nearest
double; the difference (1e-16 relative) is far below every tolerance used.

Drawing goes through a ``Chooser``: ``SeededChooser`` for the fixed-seed benchmark,
``HypothesisChooser`` inside a hypothesis strategy, so that failures shrink.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Dict, List, Optional, Sequence, Tuple

__all__ = ["Element", "Netlist", "Chooser", "SeededChooser", "HypothesisChooser",
           "e12", "to_source", "build_model", "SOURCE_KINDS"]

E12 = ("1.0", "1.2", "1.5", "1.8", "2.2", "2.7", "3.3", "3.9", "4.7", "5.6", "6.8", "8.2")
SOURCE_KINDS = ("V", "I", "force")


# --------------------------------------------------------------------------- drawing
class Chooser:
    """What a generator may ask for; every answer shrinks towards the first option."""

    def integer(self, lo: int, hi: int) -> int:
        raise NotImplementedError

    def uniform(self, lo: float, hi: float) -> float:
        raise NotImplementedError

    def boolean(self, p: float) -> bool:
        """True with probability p (shrinks to False)."""
        return self.integer(0, 99) >= 100 - round(100 * p)

    def choice(self, options: Sequence):
        return options[self.integer(0, len(options) - 1)]

    def weighted(self, table: Sequence[Tuple[object, int]]):
        """An option of ``table`` ((option, weight), ...) with probability by weight."""
        total = sum(w for _, w in table)
        k = self.integer(0, total - 1)
        for opt, w in table:
            if k < w:
                return opt
            k -= w
        raise AssertionError


class SeededChooser(Chooser):
    def __init__(self, seed):
        self.rng = random.Random(seed)

    def integer(self, lo, hi):
        return self.rng.randint(lo, hi)

    def uniform(self, lo, hi):
        return self.rng.uniform(lo, hi)


class HypothesisChooser(Chooser):
    """Answers drawn from hypothesis strategies (``draw`` of an ``st.composite``)."""

    def __init__(self, draw):
        from hypothesis import strategies as st
        self.draw, self.st = draw, st

    def integer(self, lo, hi):
        return self.draw(self.st.integers(lo, hi))

    def uniform(self, lo, hi):
        return self.draw(self.st.floats(lo, hi, allow_nan=False, allow_infinity=False))


def e12(ch: Chooser, lo_exp: int, hi_exp: int) -> str:
    """A value m 10^k, m from the E12 series, lo_exp <= k <= hi_exp, as an exact string."""
    return f"{ch.choice(E12)}e{ch.integer(lo_exp, hi_exp)}"


# --------------------------------------------------------------------------- netlist
@dataclass(frozen=True)
class Element:
    """One branch: its kind and name, its nodes (``b`` None for a free flange or a
    one-flange source), its parameter and, for a source, its sine terms and how the
    acausal model realizes it."""

    kind: str
    name: str
    a: int
    b: Optional[int] = None
    value: Optional[str] = None            # the parameter, a decimal string
    terms: Tuple[Tuple[float, float], ...] = ()   # sources: ((amplitude, f in Hz), ...)
    realize: str = "library"               # sources: "library", "signal" or "open"

    def exact(self) -> Fraction:
        return Fraction(self.value)

    def number(self) -> float:
        return float(self.value)


@dataclass(frozen=True)
class Netlist:
    """A network and what is expected of it.

    ``expect`` is "regular" (a unique solution exists) or "ill-posed"; for a network
    made ill-posed on purpose, ``defect`` names the construction and ``culprits`` the
    elements an error message may name.  ``extra`` = (element, variable) adds the
    equation element.variable = 0 (an over-determined model).
    """

    domain: str
    elements: Tuple[Element, ...]
    t_end: float = 1.0
    expect: str = "regular"
    defect: str = ""
    culprits: Tuple[str, ...] = ()
    extra: Optional[Tuple[str, str]] = None

    def nodes(self) -> List[int]:
        used = {el.a for el in self.elements} | {el.b for el in self.elements
                                                 if el.b is not None}
        return sorted(used | {0})

    def with_elements(self, elements) -> "Netlist":
        return replace(self, elements=tuple(elements))

    def describe(self) -> str:
        head = f"{self.domain} network, t_end = {self.t_end:.6g} s, expect {self.expect}"
        if self.defect:
            head += f" ({self.defect}; culprits {', '.join(self.culprits)})"
        lines = [head]
        for el in self.elements:
            where = f"{el.a}-{el.b if el.b is not None else 'free'}"
            if el.kind in SOURCE_KINDS:
                wave = " + ".join(f"{a:.6g} sin(2 pi {f:.6g} t)" for a, f in el.terms)
                what = f"{wave} [{el.realize}]"
            else:
                what = el.value
            lines.append(f"  {el.name:8s} {el.kind:7s} {where:8s} {what}")
        if self.extra:
            lines.append(f"  extra equation {self.extra[0]}.{self.extra[1]} = 0")
        return "\n".join(lines)


# --------------------------------------------------------------------------- acausal model
_CLASSES = {
    "electrical": {"R": ("el.Resistor", "R"), "C": ("el.Capacitor", "C"),
                   "L": ("el.Inductor", "L")},
    "translational": {"mass": ("tr.Mass", "m"), "spring": ("tr.Spring", "c"),
                      "damper": ("tr.Damper", "d")},
    "rotational": {"mass": ("rot.Inertia", "J"), "spring": ("rot.Spring", "c"),
                   "damper": ("rot.Damper", "d"), "gear": ("rot.IdealGear", "ratio")},
}
_PINS = {"electrical": ("p", "n"), "translational": ("flange_a", "flange_b"),
         "rotational": ("flange_a", "flange_b")}


def _source_lines(net: Netlist, el: Element, decl: List[str], links: List[str]):
    """Declarations and signal connections of one source element."""
    mech = net.domain != "electrical"
    if not mech and el.realize == "library" and len(el.terms) == 1:
        (amp, f), = el.terms
        cls, par = ("el.SineVoltage", "V") if el.kind == "V" else ("el.SineCurrent", "I")
        decl.append(f"{el.name} = {cls}({par}={amp!r}, f={f!r})")
        return
    if mech:
        cls, port = ("rot.Torque", "tau") if net.domain == "rotational" else ("tr.Force", "f")
    else:
        cls, port = (("el.SignalVoltage", "v") if el.kind == "V"
                     else ("el.SignalCurrent", "i"))
    decl.append(f"{el.name} = {cls}()")
    if el.realize == "open":                # the input left unconnected
        return
    sines = []
    for k, (amp, f) in enumerate(el.terms, 1):
        decl.append(f"{el.name}_s{k} = blocks.Sine(amplitude={amp!r}, f={f!r})")
        sines.append(f"self.{el.name}_s{k}.y")
    if len(sines) == 1:
        links.append(f"ac.connect({sines[0]}, self.{el.name}.{port})")
    else:
        decl.append(f"{el.name}_add = blocks.Add()")
        links.append(f"ac.connect({sines[0]}, self.{el.name}_add.u1)")
        links.append(f"ac.connect({sines[1]}, self.{el.name}_add.u2)")
        links.append(f"ac.connect(self.{el.name}_add.y, self.{el.name}.{port})")


def to_source(net: Netlist, name: str = "RandomNetwork") -> str:
    """Python source of the acausal model of ``net`` (a class named ``name``); the
    tests build their models from this text, so a printed case reruns as it ran."""
    decl: List[str] = []
    links: List[str] = []
    at: Dict[int, List[str]] = {n: [] for n in net.nodes()}
    if net.domain == "electrical":
        decl.append("gnd = el.Ground()")
        at[0].append("self.gnd.p")
    else:
        decl.append(f"fixed = {'rot' if net.domain == 'rotational' else 'tr'}.Fixed()")
        at[0].append("self.fixed.flange")
    pa, pb = _PINS[net.domain]
    for el in net.elements:
        if el.kind in SOURCE_KINDS:
            _source_lines(net, el, decl, links)
            if net.domain == "electrical":
                at[el.a].append(f"self.{el.name}.p")
                at[el.b].append(f"self.{el.name}.n")
            else:
                at[el.a].append(f"self.{el.name}.flange")
            continue
        cls, par = _CLASSES[net.domain][el.kind]
        decl.append(f"{el.name} = {cls}({par}={el.number()!r})")
        at[el.a].append(f"self.{el.name}.{pa}")
        if el.b is not None:
            at[el.b].append(f"self.{el.name}.{pb}")
    body = [f"ac.connect({', '.join(pins)}),  # node {n}"
            for n, pins in at.items() if len(pins) > 1]
    body += [f"{link}," for link in links]
    if net.extra:
        body.append(f"ac.Eq(self.{net.extra[0]}.{net.extra[1]}, 0),  # one equation too many")
    lines = ["import acausal as ac",
             "from acausal.library import blocks",
             "from acausal.library import electrical as el",
             "from acausal.library import rotational as rot",
             "from acausal.library import translational as tr",
             "", "", f"class {name}(ac.Component):",
             *(f"    {d}" for d in decl), "",
             "    def equations(self):", "        return ["]
    lines += [f"            {b}" for b in body]
    lines.append("        ]")
    return "\n".join(lines) + "\n"


def build_model(net: Netlist):
    """An instance of the acausal model of ``net``, built from ``to_source(net)``."""
    namespace: dict = {}
    exec(compile(to_source(net), "<random network>", "exec"), namespace)
    return namespace["RandomNetwork"]()
