"""A component's schematic: its sub-components as boxes, its connections as edges.

The picture is the top level of the instance tree, as a Modelica tool's diagram layer
shows it: one box per sub-component (its name and class), one edge per ``connect`` of
two ports, a junction dot for a node of three or more, and the component's own ports as
small squares on the border.  Boxes and edges are coloured by physical domain (the port
classes of ``acausal.ports``).  With Graphviz's ``dot`` on the PATH the layout is dot's;
otherwise networkx's Kamada-Kawai layout (Kamada & Kawai 1989, a spring model whose
lengths are graph distances; deterministic, unlike a random-start spring layout) placed
on a fixed canvas and drawn as SVG here.
"""
from __future__ import annotations

import copy
import html
import shutil
import subprocess
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Schematic", "diagram", "component_svg", "component_dot", "DOMAIN_COLOURS"]

# port class (or a base of it) -> domain; the first match along the MRO decides
_PORT_DOMAINS = {"Pin": "electrical", "RotationalFlange": "rotational",
                 "TranslationalFlange": "translational", "FluidPort": "hydraulic",
                 "HeatPort": "thermal", "Frame": "multibody", "SignalPort": "signal"}

DOMAIN_COLOURS = {"electrical": "#1f63b4", "rotational": "#555555",
                  "translational": "#2c8a3c", "hydraulic": "#c46a00", "thermal": "#c0282d",
                  "multibody": "#7b3fa0", "signal": "#00838f", "mixed": "#8a7d5a",
                  "": "#9e9e9e"}

_BOX_H = 40
_CHAR_W = 7.0      # width of one character of the 12 px label font, roughly


@dataclass
class Schematic:
    """The diagram as data: ``boxes`` (name, class, domain), ``ports`` (the component's
    own ports), ``edges`` (two endpoints, domain, the connect text) and ``junctions``
    (nodes of three or more ports).  Endpoints are box, port or junction names."""

    name: str
    boxes: dict = field(default_factory=dict)       # name -> (class name, domain)
    ports: dict = field(default_factory=dict)       # name -> domain
    junctions: dict = field(default_factory=dict)   # name -> domain
    edges: list = field(default_factory=list)       # (a, b, domain, text)
    note: str = ""                                  # why connections are missing


def port_domain(port) -> str:
    """The physical domain of a port, from its class."""
    for klass in type(port).__mro__:
        if klass.__name__ in _PORT_DOMAINS:
            return _PORT_DOMAINS[klass.__name__]
    return ""


def _component_domain(comp) -> str:
    """A library component's domain is its package's; otherwise its ports' (``mixed``
    when they belong to several domains, as a motor's pins and flange do)."""
    from ..components import Port
    module = type(comp).__module__
    for name in ("electrical", "rotational", "translational", "hydraulics", "thermal",
                 "multibody", "blocks", "electromechanical", "friction"):
        if f".library.{name}" in module:
            return {"hydraulics": "hydraulic", "blocks": "signal",
                    "electromechanical": "mixed", "friction": "translational"}.get(name, name)
    domains = {port_domain(c) for c in comp.children().values() if isinstance(c, Port)}
    domains.discard("")
    return domains.pop() if len(domains) == 1 else ("mixed" if domains else "")


def _bound(comp):
    """``comp`` with its names: an unbound model is named on a copy, as compile would
    name it, so showing a model never changes it."""
    if comp._path is not None:
        return comp
    try:
        named = copy.deepcopy(comp)
    except Exception:       # an unusual attribute that does not copy: name the model itself
        named = comp
    named._bind()
    return named


def diagram(comp) -> Schematic:
    """The top level of ``comp`` as a :class:`Schematic`."""
    from ..components import Port
    from ..components.component import Connection
    from ..components.inheritance import all_items
    comp = _bound(comp)
    prefix = f"{comp.path}." if comp.path else ""
    sch = Schematic(type(comp).__name__)
    for name, child in comp.children().items():
        if isinstance(child, Port):
            sch.ports[name] = port_domain(child)
        else:
            sch.boxes[name] = (type(child).__name__, _component_domain(child))
    try:
        items = [i for i in all_items(comp, "equations")
                 if isinstance(i, Connection)]
    except Exception as err:     # the equations fail: compile will say why; draw the boxes
        sch.note = f"connections not shown: equations() raised {type(err).__name__}: {err}"
        items = []
    for k, conn in enumerate(items):
        ends = []
        for p in conn.ports:
            rel = p.path[len(prefix):] if p.path.startswith(prefix) else p.path
            head = rel.split(".", 1)[0]
            ends.append(head if (head in sch.boxes or head in sch.ports) else rel)
        domain = port_domain(conn.ports[0])
        text = "connect(" + ", ".join(p.path[len(prefix):] for p in conn.ports) + ")"
        if len(ends) == 2:
            if ends[0] != ends[1]:
                sch.edges.append((ends[0], ends[1], domain, text))
            continue
        node = f"node{k}"
        sch.junctions[node] = domain
        sch.edges += [(node, e, domain, text) for e in dict.fromkeys(ends)]
    return sch


def component_dot(comp) -> str:
    """Graphviz DOT text of the schematic (boxes, junction points, coloured edges)."""
    sch = comp if isinstance(comp, Schematic) else diagram(comp)
    q = lambda s: '"' + s.replace('"', r'\"') + '"'          # noqa: E731
    lines = [f"graph {q(sch.name)} {{", "  layout=dot; rankdir=LR; splines=true;",
             '  node [shape=box, style="rounded,filled", fontname="Helvetica", fontsize=11];']
    for name, (cls, dom) in sch.boxes.items():
        colour = DOMAIN_COLOURS.get(dom, DOMAIN_COLOURS[""])
        lines.append(f'  {q(name)} [label="{name}\\n{cls}", color="{colour}", '
                     f'fillcolor="{colour}22"];')
    for name, dom in sch.ports.items():
        lines.append(f'  {q(name)} [shape=square, label={q(name)}, width=0.3, '
                     f'color="{DOMAIN_COLOURS.get(dom, "#999")}"];')
    for name, dom in sch.junctions.items():
        lines.append(f'  {q(name)} [shape=point, width=0.08, '
                     f'color="{DOMAIN_COLOURS.get(dom, "#999")}"];')
    for a, b, dom, text in sch.edges:
        lines.append(f'  {q(a)} -- {q(b)} [color="{DOMAIN_COLOURS.get(dom, "#999")}", '
                     f'penwidth=2, tooltip={q(text)}];')
    return "\n".join(lines + ["}"])


def _layout(sch: Schematic) -> dict:
    """Node positions (Kamada-Kawai; nodes in declaration order), turned so that the
    principal axis of the drawing is horizontal (a chain reads left to right), with the
    x-extent scaled to 1."""
    import networkx as nx
    g = nx.Graph()
    g.add_nodes_from([*sch.boxes, *sch.ports, *sch.junctions])
    g.add_edges_from((a, b) for a, b, _, _ in sch.edges)
    if len(g) == 0:
        return {}
    if len(g) == 1:
        return {n: (0.5, 0.0) for n in g}
    pos = nx.kamada_kawai_layout(g)
    nodes = list(pos)
    xy = np.array([pos[n] for n in nodes], dtype=float)
    xy -= xy.mean(axis=0)
    _, _, vt = np.linalg.svd(xy, full_matrices=False)
    if vt[0, 0] < 0:                    # a fixed orientation: deterministic output
        vt[0] = -vt[0]
    xy = xy @ np.array([vt[0], [-vt[0, 1], vt[0, 0]]]).T
    span = np.ptp(xy[:, 0]) or 1.0
    xy = (xy - xy.min(axis=0)) / span
    return {n: (float(x), float(y)) for n, (x, y) in zip(nodes, xy)}


def _clip(x0, y0, x1, y1, half_w, half_h):
    """Where the segment from a box's centre (x0, y0) to (x1, y1) leaves the box."""
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return x0, y0
    s = min(half_w / abs(dx) if dx else float("inf"), half_h / abs(dy) if dy else float("inf"))
    s = min(s, 1.0)
    return x0 + s * dx, y0 + s * dy


def _svg_networkx(sch: Schematic) -> str:
    pos = _layout(sch)
    n = max(len(pos), 1)
    widths = {name: max(len(name), len(cls)) * _CHAR_W + 20
              for name, (cls, _) in sch.boxes.items()}
    scale = 110.0 * n ** 0.75 + 60.0
    margin = max(widths.values(), default=40) / 2 + 20
    xy = {k: (margin + p[0] * scale, margin + p[1] * scale) for k, p in pos.items()}
    width = 2 * margin + scale
    height = 2 * margin + max((p[1] for p in pos.values()), default=0.0) * scale + 20
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" '
           f'height="{height:.0f}" viewBox="0 0 {width:.0f} {height:.0f}" '
           'font-family="Helvetica, Arial, sans-serif" class="acausal-schematic">',
           f"<title>{html.escape(sch.name)}</title>"]

    def half(node):
        if node in sch.boxes:
            return widths[node] / 2, _BOX_H / 2
        return (6.0, 6.0) if node in sch.ports else (0.0, 0.0)

    for a, b, dom, text in sch.edges:
        if a not in xy or b not in xy:
            continue
        (xa, ya), (xb, yb) = xy[a], xy[b]
        x0, y0 = _clip(xa, ya, xb, yb, *half(a))
        x1, y1 = _clip(xb, yb, xa, ya, *half(b))
        colour = DOMAIN_COLOURS.get(dom, DOMAIN_COLOURS[""])
        out.append(f'<line class="edge" x1="{x0:.1f}" y1="{y0:.1f}" x2="{x1:.1f}" '
                   f'y2="{y1:.1f}" stroke="{colour}" stroke-width="2.5">'
                   f"<title>{html.escape(text)}</title></line>")
    for name, (cls, dom) in sch.boxes.items():
        x, y = xy[name]
        w = widths[name]
        colour = DOMAIN_COLOURS.get(dom, DOMAIN_COLOURS[""])
        out.append(f'<g class="component"><rect x="{x - w / 2:.1f}" y="{y - _BOX_H / 2:.1f}" '
                   f'width="{w:.1f}" height="{_BOX_H}" rx="6" fill="{colour}1f" '
                   f'stroke="{colour}" stroke-width="1.5"/>'
                   f'<text x="{x:.1f}" y="{y - 3:.1f}" text-anchor="middle" font-size="12" '
                   f'font-weight="bold">{html.escape(name)}</text>'
                   f'<text x="{x:.1f}" y="{y + 12:.1f}" text-anchor="middle" '
                   f'font-size="10" fill="#444">{html.escape(cls)}</text></g>')
    for name, dom in sch.ports.items():
        x, y = xy[name]
        colour = DOMAIN_COLOURS.get(dom, DOMAIN_COLOURS[""])
        out.append(f'<g class="port"><rect x="{x - 6:.1f}" y="{y - 6:.1f}" width="12" '
                   f'height="12" fill="{colour}"/><text x="{x:.1f}" y="{y - 10:.1f}" '
                   f'text-anchor="middle" font-size="10">{html.escape(name)}</text></g>')
    for name, dom in sch.junctions.items():
        x, y = xy[name]
        colour = DOMAIN_COLOURS.get(dom, DOMAIN_COLOURS[""])
        out.append(f'<circle class="junction" cx="{x:.1f}" cy="{y:.1f}" r="4" '
                   f'fill="{colour}"/>')
    if sch.note:
        out.append(f'<text x="10" y="16" font-size="11" fill="#c0282d">'
                   f"{html.escape(sch.note)}</text>")
    out += _legend(sch, 10, height - 14) + ["</svg>"]
    return "\n".join(out)


def _legend(sch: Schematic, x0: float, y: float) -> list:
    used = sorted(({d for _, d in sch.boxes.values()} | {e[2] for e in sch.edges}) - {""})
    out, x = [], x0
    for dom in used:
        out.append(f'<rect x="{x:.0f}" y="{y - 8:.0f}" width="10" height="10" '
                   f'fill="{DOMAIN_COLOURS[dom]}"/><text x="{x + 14:.0f}" y="{y + 1:.0f}" '
                   f'font-size="10">{dom}</text>')
        x += 24 + len(dom) * 6
    return out


def component_svg(comp, engine: str = "auto") -> str:
    """The schematic of ``comp`` as SVG text.

    ``engine``: ``"dot"`` (Graphviz, must be on the PATH), ``"networkx"`` (always
    available) or ``"auto"`` (dot when found).
    """
    sch = comp if isinstance(comp, Schematic) else diagram(comp)
    if engine not in ("auto", "dot", "networkx"):
        raise ValueError(f"engine must be 'auto', 'dot' or 'networkx', not {engine!r}")
    dot = shutil.which("dot") if engine != "networkx" else None
    if engine == "dot" and dot is None:
        raise RuntimeError("engine='dot' needs Graphviz's dot on the PATH")
    if dot is not None:
        done = subprocess.run([dot, "-Tsvg"], input=component_dot(sch), capture_output=True,
                              text=True, timeout=30)
        if done.returncode == 0:
            text = done.stdout
            return text[text.find("<svg"):]
        if engine == "dot":
            raise RuntimeError(f"dot failed: {done.stderr.strip()}")
    return _svg_networkx(sch)
