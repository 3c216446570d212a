"""Drawing random networks: well-posed ones (with the motifs that exercise index
reduction) and ill-posed ones made on purpose.

Well-posed electrical networks are a random spanning tree over the nodes plus extra
branches, then motifs: capacitor triangles off ground, capacitors across voltage
sources (loops of C and V: index 2), inductors in series through a node of their own
and inductors in series with a current source (cutsets of L, and of L and I: index 2),
parallel and series pairs.  The two structures that make a network singular are then
repaired: a voltage source closing a loop of voltage sources, and a current source
on a cutset of current sources, become resistors.

Well-posed mechanical networks: nodes with or without a mass (inertia), a spanning tree
of springs, dampers, spring-damper pairs and rigid couplings (a mass whose two flanges
join two nodes; a rotational ideal gear), force (torque) sources, and motifs: a
massless node between two springs, a spring in series with a damper (a massless node
with a first-order state), a gear to a second inertia (index 3), two gears of different
ratios in parallel (a locked mechanism with determinate torques), a mass coupled
rigidly to the housing.  A rigid coupling that would close a loop of rigid couplings
becomes a spring.

Whether a network is really regular is decided by the reference (reference.py), not
here: these rules only make singular networks rare in the well-posed strategy.

Ill-posed networks are a small well-posed one plus one defect: a floating part (no
path to ground or housing; for mechanics, massless), two voltage sources in parallel,
two current sources in series, a loop of voltage sources, a cutset of current sources
(an island fed only by them), a shorted voltage source, a massless node with only a
force on it, a loop of rigid couplings, an extra equation (over-determined) or a
signal source with its input left open (under-determined).  Their pencils are singular
(or their equation count wrong), and acausal must refuse them with a typed error that
names a culprit.

Two voltage sources in parallel with equal waves are consistent, yet still ill-posed:
the current divides between them in any proportion, so the solution is not unique
(the pencil is singular whatever the inputs).  Modelica tools reject the model as
structurally singular, and so must acausal; the generator draws equal and different
waves alike, and expects a typed error for both (likewise two equal current sources in
series, where the potential of the node between them is free).
"""
from __future__ import annotations

from dataclasses import replace
from typing import List

from .netlists import Chooser, Element, Netlist, e12

__all__ = ["electrical_network", "mechanical_network", "ill_posed_network",
           "ELECTRICAL_DEFECTS", "MECHANICAL_DEFECTS"]

PREFIX = {"electrical": {"R": "R", "C": "C", "L": "L", "V": "V", "I": "I"},
          "translational": {"mass": "M", "spring": "S", "damper": "D", "force": "F"},
          "rotational": {"mass": "J", "spring": "S", "damper": "D", "gear": "G",
                         "force": "T"}}
RANGES = {"electrical": {"R": (0, 3), "C": (-6, -4), "L": (-3, -1)},
          "translational": {"mass": (-1, 0), "spring": (1, 3), "damper": (-1, 1)},
          "rotational": {"mass": (-3, -1), "spring": (0, 2), "damper": (-2, 0)}}
AMPLITUDE = {"V": (-1, 0), "I": (-3, -1), "force": (-1, 0)}
GEAR_RATIOS = ("2", "3", "0.5", "-2", "4", "1.5", "0.25")
ELECTRICAL_DEFECTS = ("floating", "V||V", "I in series", "V loop", "I cutset",
                      "V shorted", "over-determined", "under-determined")
MECHANICAL_DEFECTS = ("floating", "force on a massless node", "rigid loop",
                      "over-determined", "under-determined")


class _Draft:
    """A netlist under construction; names are given at the end, in order of kind."""

    def __init__(self, ch: Chooser, domain: str, n_nodes: int):
        self.ch, self.domain = ch, domain
        self.items: List[dict] = []
        self.next_node = n_nodes + 1

    def new_node(self) -> int:
        self.next_node += 1
        return self.next_node - 1

    def add(self, kind, a, b=None, value=None, culprit=False, **kw) -> dict:
        if value is None and kind in RANGES[self.domain]:
            value = e12(self.ch, *RANGES[self.domain][kind])
        if value is None and kind == "gear":
            value = self.ch.choice(GEAR_RATIOS)
        item = dict(kind=kind, a=a, b=b, value=value, culprit=culprit, **kw)
        if kind in ("V", "I", "force") and "terms" not in item:
            item["terms"] = sine_terms(self.ch, kind, 1)
            item["realize"] = "signal" if self.ch.boolean(0.3) else "library"
        self.items.append(item)
        return item

    def finalize(self, **kw) -> Netlist:
        count: dict = {}
        elements, culprits = [], []
        for it in self.items:
            prefix = PREFIX[self.domain][it["kind"]]
            count[prefix] = count.get(prefix, 0) + 1
            name = f"{prefix}{count[prefix]}"
            elements.append(Element(it["kind"], name, it["a"], it["b"], it["value"],
                                    tuple(it.get("terms", ())), it.get("realize", "library")))
            if it["culprit"]:
                culprits.append(name)
            it["name"] = name
        extra = kw.pop("extra", None)
        if extra is not None:
            kw["extra"] = (extra[0]["name"], extra[1])
        return Netlist(self.domain, tuple(elements), culprits=tuple(culprits), **kw)


def sine_terms(ch: Chooser, kind: str, n_terms: int):
    """Terms (amplitude, relative frequency): frequencies are in units of 1/t_end and
    are scaled when t_end is known.  Two terms get a1 f1 + a2 f2 = 0: zero slope at 0."""
    sign = -1.0 if ch.boolean(0.5) else 1.0
    amp = sign * float(e12(ch, *AMPLITUDE[kind]))
    f1 = round(ch.uniform(0.5, 4.0), 3)
    if n_terms == 1:
        return ((amp, f1),)
    f2 = round(f1 + ch.uniform(0.3, 3.0), 3)
    return ((amp, f1), (-amp * f1 / f2, f2))


class _UnionFind:
    def __init__(self):
        self.parent: dict = {}

    def find(self, x):
        self.parent.setdefault(x, x)
        while self.parent[x] != x:
            self.parent[x] = self.parent[self.parent[x]]
            x = self.parent[x]
        return x

    def union(self, a, b) -> bool:
        ra, rb = self.find(a), self.find(b)
        if ra == rb:
            return False
        self.parent[max(ra, rb)] = min(ra, rb)
        return True


# --------------------------------------------------------------------------- electrical
def _electrical_branch(d: _Draft, a: int, b: int):
    kind = d.ch.weighted((("R", 6), ("C", 4), ("L", 3), ("V", 2), ("I", 2)))
    if d.ch.boolean(0.5):
        a, b = b, a
    return d.add(kind, a, b)


def _electrical_motifs(d: _Draft, n: int):
    ch = d.ch
    if ch.boolean(0.3):                       # capacitor triangle not touching ground
        x = ch.integer(1, n)
        if n >= 3 and ch.boolean(0.5):
            y, z = [k for k in range(1, n + 1) if k != x][:2]
        else:
            y, z = d.new_node(), d.new_node()
        for p, q in ((x, y), (y, z), (z, x)):
            d.add("C", p, q)
    if ch.boolean(0.3):                       # a loop of capacitors and a voltage source
        x, y = ch.integer(1, n), ch.integer(0, n)
        if x != y:
            d.add("V", x, y)
            if ch.boolean(0.5):
                d.add("C", x, y)
            else:
                m = d.new_node()
                d.add("C", x, m)
                d.add("C", m, y)
    if ch.boolean(0.3):                       # a node with inductors only (cutset of L)
        m = d.new_node()
        d.add("L", ch.integer(0, n), m)
        d.add("L", m, ch.integer(0, n))
    if ch.boolean(0.3):                       # an inductor in series with a current source
        m = d.new_node()
        d.add("I", ch.integer(0, n), m)
        d.add("L", m, ch.integer(0, n))
    passive = [it for it in d.items if it["kind"] in ("R", "C", "L")]
    if passive and ch.boolean(0.3):           # parallel pair
        it = ch.choice(passive)
        d.add(it["kind"], it["a"], it["b"])
    if passive and ch.boolean(0.3):           # series pair through a node of its own
        it = ch.choice(passive + [i for i in d.items if i["kind"] == "V"])
        m = d.new_node()
        d.add(it["kind"], m, it["b"])
        it["b"] = m


def _repair_electrical(d: _Draft):
    """Resistors for voltage sources closing a V loop and current sources on an I
    cutset, and a source if there is none."""
    uf = _UnionFind()
    for it in d.items:
        if it["kind"] == "V" and not uf.union(it["a"], it["b"]):
            _make_resistor(d, it)
    while True:
        uf = _UnionFind()
        for it in d.items:
            if it["kind"] != "I":
                uf.union(it["a"], it["b"])
        cut = next((it for it in d.items if it["kind"] == "I"
                    and uf.find(it["a"]) != uf.find(it["b"])), None)
        if cut is None:
            break
        _make_resistor(d, cut)
    if not any(it["kind"] in ("V", "I") for it in d.items):
        it = d.items[0]
        it.update(kind="V", value=None, terms=sine_terms(d.ch, "V", 1), realize="library")


def _make_resistor(d: _Draft, it: dict):
    it.update(kind="R", value=e12(d.ch, *RANGES["electrical"]["R"]))
    it.pop("terms", None)
    it.pop("realize", None)


def _electrical_draft(ch: Chooser, max_nodes: int, motifs: bool) -> _Draft:
    n = ch.integer(1, max_nodes)
    d = _Draft(ch, "electrical", n)
    for k in range(1, n + 1):
        _electrical_branch(d, k, ch.integer(0, k - 1))
    for _ in range(ch.integer(0, 3)):
        a, b = ch.integer(0, n), ch.integer(0, n)
        if a != b:
            _electrical_branch(d, a, b)
    if motifs:
        _electrical_motifs(d, n)
    _repair_electrical(d)
    return d


def electrical_network(ch: Chooser) -> Netlist:
    return _electrical_draft(ch, 5, True).finalize()


# --------------------------------------------------------------------------- mechanical
def _rigid(d: _Draft, a: int, b: int):
    if d.domain == "rotational" and d.ch.boolean(0.6):
        return d.add("gear", a, b)
    return d.add("mass", a, b)


def _mechanical_branch(d: _Draft, a: int, b: int):
    kind = d.ch.weighted((("spring", 5), ("damper", 3), ("both", 2), ("rigid", 2)))
    if kind == "both":
        d.add("spring", a, b)
        d.add("damper", a, b)
    elif kind == "rigid":
        _rigid(d, a, b)
    else:
        d.add(kind, a, b)


def _mechanical_motifs(d: _Draft, n: int):
    ch = d.ch
    if ch.boolean(0.3):                       # massless node between two springs
        m = d.new_node()
        d.add("spring", ch.integer(1, n), m)
        d.add("spring", m, ch.integer(0, n))
    if ch.boolean(0.3):                       # spring in series with a damper
        m = d.new_node()
        d.add("spring", ch.integer(1, n), m)
        d.add("damper", m, ch.integer(0, n))
    if ch.boolean(0.3):                       # a rigid coupling to a second mass
        m = d.new_node()
        d.add("mass", m)
        _rigid(d, ch.integer(1, n), m)
    if d.domain == "rotational" and ch.boolean(0.1):   # locked: two ratios in parallel
        m = d.new_node()
        d.add("mass", m)
        x = ch.integer(1, n)
        d.add("gear", x, m, value="2")
        d.add("gear", x, m, value="3", locked=True)
    if ch.boolean(0.1):                       # a mass rigidly on the housing
        d.add("mass", ch.integer(1, n), 0)


def _repair_mechanical(d: _Draft):
    """A spring for each rigid coupling that closes a loop of rigid couplings; the
    locked gear pair counts as coupling its node to the housing."""
    uf = _UnionFind()
    for it in d.items:
        if it["kind"] in ("gear", "mass") and it["b"] is not None:
            # the second gear of a locked pair holds its nodes still, as the housing does
            ends = (it["a"], 0) if it.get("locked") else (it["a"], it["b"])
            if not uf.union(*ends):
                it.update(kind="spring", value=e12(d.ch, *RANGES[d.domain]["spring"]))
                it.pop("locked", None)
    if not any(it["kind"] == "force" for it in d.items):
        d.add("force", d.ch.integer(1, d.next_node - 1))


def _mechanical_draft(ch: Chooser, domain: str, max_nodes: int, motifs: bool) -> _Draft:
    n = ch.integer(1, max_nodes)
    d = _Draft(ch, domain, n)
    for k in range(1, n + 1):
        if ch.boolean(0.6):
            d.add("mass", k)
    for k in range(1, n + 1):
        _mechanical_branch(d, k, ch.integer(0, k - 1))
    for _ in range(ch.integer(0, 2)):
        a, b = ch.integer(0, n), ch.integer(0, n)
        if a != b:
            d.add(ch.choice(("spring", "damper")), a, b)
    for _ in range(ch.integer(1, 2)):
        d.add("force", ch.integer(1, n))
    if motifs:
        _mechanical_motifs(d, n)
    _repair_mechanical(d)
    return d


def mechanical_network(ch: Chooser, domain: str) -> Netlist:
    return _mechanical_draft(ch, domain, 4, True).finalize()


# --------------------------------------------------------------------------- ill-posed
def _island(d: _Draft, kinds) -> List[dict]:
    m1, m2 = d.new_node(), d.new_node()
    out = [d.add(d.ch.choice(kinds), m1, m2, culprit=True)]
    if d.ch.boolean(0.5):
        out.append(d.add(d.ch.choice(kinds), m1, m2, culprit=True))
    return out


def _electrical_defect(d: _Draft, defect: str):
    ch, n = d.ch, d.next_node - 1
    x = ch.integer(1, n)
    if defect == "floating":
        _island(d, ("R", "C", "L"))
    elif defect in ("V||V", "V loop", "V shorted"):
        m = d.new_node()
        d.add("R", m, 0)                      # so that m is not floating as well
        if defect == "V shorted":
            d.add("V", m, m, culprit=True)
        elif defect == "V||V":
            first = d.add("V", m, x, culprit=True)
            second = d.add("V", m, x, culprit=True)
            if ch.boolean(0.5):               # equal sources: consistent, still singular
                second.update(terms=first["terms"], realize=first["realize"])
        else:
            m2 = d.new_node()
            d.add("R", m2, 0)
            for p, q in ((x, m), (m, m2), (m2, x)):
                d.add("V", p, q, culprit=True)
    elif defect == "I in series":
        m = d.new_node()
        first = d.add("I", x, m, culprit=True)
        second = d.add("I", m, ch.integer(0, n), culprit=True)
        if ch.boolean(0.5):                   # equal currents: the potential of m is free
            second.update(terms=first["terms"], realize=first["realize"])
    elif defect == "I cutset":
        island = _island(d, ("R", "C", "L"))
        d.add("I", x, island[0]["a"], culprit=True)
        d.add("I", island[0]["b"], ch.integer(0, n), culprit=True)
    elif defect == "over-determined":
        return ch.choice([it for it in d.items]), "i"
    elif defect == "under-determined":
        src = d.add(ch.choice(("V", "I")), x, 0, culprit=True)
        src["realize"] = "open"
    return None


_EXTRA_VARIABLE = {"translational": {"spring": "f", "damper": "f", "mass": "v",
                                     "force": "flange.s"},
                   "rotational": {"spring": "tau", "damper": "tau", "mass": "w",
                                  "gear": "flange_a.tau", "force": "flange.phi"}}


def _mechanical_defect(d: _Draft, defect: str):
    ch, n = d.ch, d.next_node - 1
    x = ch.integer(1, n)
    if defect == "floating":
        _island(d, ("spring", "damper"))
    elif defect == "force on a massless node":
        m = d.new_node()
        d.add("force", m, culprit=True)
        if ch.boolean(0.5):
            d.add("force", m, culprit=True)
    elif defect == "rigid loop":
        m = d.new_node()
        d.add("mass", m)
        if d.domain == "rotational" and ch.boolean(0.5):
            ratio = ch.choice(GEAR_RATIOS)
            d.add("gear", x, m, value=ratio, culprit=True)
            d.add("gear", x, m, value=ratio, culprit=True)
        else:
            d.add("mass", x, m, culprit=True)
            d.add("mass", x, m, culprit=True)
    elif defect == "over-determined":
        it = ch.choice(d.items)
        it["culprit"] = True
        return it, _EXTRA_VARIABLE[d.domain][it["kind"]]
    elif defect == "under-determined":
        src = d.add("force", x, culprit=True)
        src["realize"] = "open"
    return None


def ill_posed_network(ch: Chooser, domain: str) -> Netlist:
    """A small well-posed network with one defect added (``Netlist.defect``)."""
    if domain == "electrical":
        d = _electrical_draft(ch, 2, False)
        defect = ch.choice(ELECTRICAL_DEFECTS)
        extra = _electrical_defect(d, defect)
    else:
        d = _mechanical_draft(ch, domain, 2, False)
        defect = ch.choice(MECHANICAL_DEFECTS)
        extra = _mechanical_defect(d, defect)
    if extra is not None:
        extra[0]["culprit"] = True
    net = d.finalize(expect="ill-posed", defect=defect, extra=extra)
    if extra is not None:     # whatever the extra equation over-determines may be named
        from .reference import overdetermined_elements
        net = replace(net, culprits=tuple(overdetermined_elements(net)))
    return net
