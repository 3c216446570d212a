"""HTML for Jupyter: a component, a compiled model, its index report, a result, a
linearization.

Each function returns one self-contained ``<div>`` (inline styles, pictures as inline
SVG or PNG) that the classes' ``_repr_html_`` hooks return, so a notebook shows the
same content after it is saved and rendered elsewhere.  Tables list what the text
forms print (``print(compiled.report)``, ``repr(result)``), in the user's dotted names.
"""
from __future__ import annotations

import html
import math

import numpy as np

from .plots import blt_svg, bode_png, png_img, result_png
from .schematic import component_svg

__all__ = ["component_html", "model_html", "report_html", "result_html", "statespace_html",
           "show", "units_of"]

_STYLE = ("<style>.acausal table{border-collapse:collapse;margin:4px 0 10px 0;"
          "font-size:12px}.acausal th,.acausal td{border:1px solid #ddd;padding:2px 6px;"
          "text-align:left}.acausal th{background:#f3f3f3}.acausal td.num{text-align:right;"
          "font-family:monospace}.acausal h4{margin:8px 0 4px 0}</style>")

_MAX_ROWS = 200


def _esc(x) -> str:
    return html.escape(str(x))


def _num(x) -> str:
    if isinstance(x, (float, np.floating)):
        return f"{float(x) + 0.0:.6g}"       # + 0.0: a pole at -0.0 reads 0
    return _esc(x)


def _table(header, rows, numeric=(), cls="") -> str:
    """An HTML table; columns whose index is in ``numeric`` are right-aligned."""
    rows = list(rows)
    more = len(rows) - _MAX_ROWS
    out = [f'<table class="{cls}"><tr>' + "".join(f"<th>{_esc(h)}</th>" for h in header)
           + "</tr>"]
    for row in rows[:_MAX_ROWS]:
        out.append("<tr>" + "".join(
            f'<td class="num">{_num(c)}</td>' if j in numeric else f"<td>{_esc(c)}</td>"
            for j, c in enumerate(row)) + "</tr>")
    if more > 0:
        out.append(f'<tr><td colspan="{len(header)}">... {more} more rows</td></tr>')
    return "\n".join(out + ["</table>"])


def _div(title: str, body: list) -> str:
    return "\n".join([_STYLE, '<div class="acausal">', f"<h3>{_esc(title)}</h3>", *body,
                      "</div>"])


def units_of(obj) -> dict:
    """Units by variable name where the object knows them (``units`` on a result or a
    compiled model, or ``meta["units"]``), else an empty dict."""
    for holder in (obj, getattr(obj, "compiled", None)):
        if holder is None:
            continue
        units = getattr(holder, "units", None)
        if callable(units):
            units = None
        if not units:
            units = (getattr(holder, "meta", None) or {}).get("units")
        if units:
            return dict(units)
    return {}


# -- component ------------------------------------------------------------------------
def _parameter_rows(comp):
    from ..components import Parameter
    from ..components.declarations import shown_value
    for name, decl in comp.declarations().items():
        if isinstance(decl, Parameter):
            value = comp._param_values.get(name, comp._mods.get(name, decl.value))
            yield name, shown_value(value), decl.unit, decl.description


def component_html(comp) -> str:
    """The schematic of a component and the parameters of it and of its sub-components
    (the values it was given, with units and descriptions)."""
    from ..components import Port
    from .schematic import _bound
    comp = _bound(comp)          # a parent's modifications reach its children when named
    body = [component_svg(comp)]
    own = list(_parameter_rows(comp))
    if own:
        body += ["<h4>Parameters</h4>",
                 _table(["name", "value", "unit", "description"], own, numeric=(1,))]
    rows = []
    for name, child in comp.children().items():
        if isinstance(child, Port):
            continue
        for p, value, unit, desc in _parameter_rows(child):
            rows.append((name, type(child).__name__, p, value, unit, desc))
    if rows:
        body += ["<h4>Sub-component parameters</h4>",
                 _table(["component", "class", "parameter", "value", "unit", "description"],
                        rows, numeric=(3,))]
    return _div(f"{type(comp).__name__}" + (f" ({comp.path})" if comp.path else ""), body)


# -- index report -----------------------------------------------------------------------
def _report_sections(r) -> list:
    names = getattr(r, "_names", [])
    eq_text = {e["index"]: e["text"] for e in r.equations}
    index = f"{r.differential_index}"
    if r.index_after_alias != r.differential_index:
        index += f" (after alias elimination: {r.index_after_alias})"
    body = [f"<p>Differential index: <b>{_esc(index)}</b></p>"]
    if r.counts:
        keys = list(dict.fromkeys(k for c in r.counts.values() for k in c))
        body += ["<h4>Equations and variables after each pass</h4>",
                 _table(["pass", *keys], ([stage, *(c.get(k, "") for k in keys)]
                                          for stage, c in r.counts.items()),
                        numeric=tuple(range(1, len(keys) + 1)))]
    body += ["<h4>States</h4>",
             _table(["state"], ([s] for s in r.states)) if r.states else "<p>(none)</p>"]
    if r.dummy_derivatives:
        body += ["<h4>Dummy derivatives</h4>",
                 _table(["dummy derivative"], ([d] for d in r.dummy_derivatives))]
    if r.state_sets:
        body += ["<h4>Dynamic state sets</h4>",
                 _table(["level", "dummies chosen at run time", "candidates"],
                        ([s["level"], s["n_dummies"], ", ".join(s["candidates"])]
                         for s in r.state_sets))]
    diffed = [e for e in r.equations if e["differentiated"] and e["order"] == 0]
    if diffed:
        body += ["<h4>Differentiated equations (Pantelides)</h4>",
                 _table(["times", "equation", "component"],
                        ([e["differentiated"], e["text"], e["component"]] for e in diffed),
                        numeric=(0,))]
    if r.blocks:
        rows = []
        for k, b in enumerate(r.blocks):
            tearing = ", ".join(names[v] for v in b.get("iteration_variables", []))
            how = b["solved"] + (" (torn)" if b.get("torn") else "")
            if b.get("not_torn"):
                how += f"; not torn: {b['not_torn']}"
            rows.append([k, b["size"], ", ".join(names[v] for v in b["variables"]),
                         "; ".join(eq_text.get(e, str(e)) for e in b["equations"]),
                         how, tearing])
        torn = sum(1 for b in r.blocks if b.get("torn"))
        body += [f"<h4>BLT blocks ({len(r.blocks)}, largest "
                 f"{max(b['size'] for b in r.blocks)}, {torn} torn)</h4>",
                 _table(["block", "size", "unknowns", "equations", "solved", "tearing variables"],
                        rows, numeric=(0, 1)),
                 "<h4>Incidence in BLT order</h4>", blt_svg(r)]
    sigma = r.sigma or {}
    if sigma.get("error"):
        body.append(f"<p>Cross-check failed: {_esc(sigma['error'])}</p>")
    elif "index_sigma" in sigma and not sigma.get("hidden"):
        verdict = "agrees with Pantelides" if sigma.get("agrees") else "DISAGREES with Pantelides"
        body.append(f"<p>Cross-check, Pryce's Sigma-method: index {sigma['index_sigma']}, "
                    f"{sigma.get('dof')} degrees of freedom; {verdict}</p>")
    if r.notes:
        body += ["<h4>Notes</h4>", "<ul>" + "".join(f"<li>{_esc(n)}</li>" for n in r.notes)
                 + "</ul>"]
    total = sum(r.timings.values()) if r.timings else 0.0
    body.append(f"<p>Compile time: {total:.3f} s</p>")
    return body


def report_html(report) -> str:
    """The index report as HTML tables, with the incidence matrix in BLT order."""
    return _div(f"Index report for {report.model_name}", _report_sections(report))


# -- compiled model ---------------------------------------------------------------------
def model_html(compiled) -> str:
    """A compiled model: its solver size and backend, states, parameters, and the index
    report (collapsed)."""
    r = compiled.report
    states = list(compiled.states)
    body = [f"<p>{len(compiled.names)} solver unknowns, {len(states)} states, "
            f"{len(compiled.outputs)} variables in results, backend "
            f"<code>{_esc(compiled.backend)}</code></p>",
            "<h4>Parameters</h4>",
            _table(["parameter", "value"], zip(compiled.param_names, compiled.p.tolist()),
                   numeric=(1,))]
    start = dict(zip(compiled.names, compiled.start.tolist()))
    units = units_of(compiled)
    body += ["<h4>States</h4>",
             _table(["state", "unit", "start"],
                    ([s, units.get(s, ""), start.get(s, "")] for s in states), numeric=(2,))]
    if r is not None:
        body.append("<details><summary>Index report</summary>"
                    + "\n".join(_report_sections(r)) + "</details>")
    name = r.model_name if r is not None else "model"
    return _div(f"Compiled model {name}", body)


# -- result -------------------------------------------------------------------------------
def result_html(res, names=None, plot: bool = True) -> str:
    """A result: status, solver statistics, a summary table (initial, final, minimum and
    maximum of each selected variable; the states by default) and a plot of them."""
    names = list(names) if names is not None else list(res.states)
    units = units_of(res)
    status = "ok" if res.success else f"FAILED: {res.message}"
    t0, t1 = (float(res.t[0]), float(res.t[-1])) if len(res.t) else (math.nan, math.nan)
    body = [f"<p>{len(res.t)} points, t = {t0:g} .. {t1:g} s, {len(res.names)} variables, "
            f"{len(res.events)} events, <b>{_esc(status)}</b></p>"]
    rows = []
    for n in names:
        x = np.asarray(res[n], dtype=float)
        rows.append([n, units.get(n, ""), x[0], x[-1], np.min(x), np.max(x)]
                    if x.size else [n, units.get(n, ""), "", "", "", ""])
    body += ["<h4>Summary</h4>",
             _table(["variable", "unit", "initial", "final", "min", "max"], rows,
                    numeric=(2, 3, 4, 5))]
    if res.stats:
        body += ["<h4>Solver statistics</h4>",
                 _table(["statistic", "value"], sorted(res.stats.items()), numeric=(1,))]
    if plot and names and len(res.t):
        try:
            body.append(png_img(result_png(res, names[:6], units), "states against time"))
        except ImportError:
            body.append("<p>(matplotlib is not installed: no plot)</p>")
    return _div("Simulation result", body)


# -- linearization ----------------------------------------------------------------------
def statespace_html(ss, plot: bool = True) -> str:
    """A StateSpace: its size, the poles with damping and natural frequency, and the Bode
    plot of its first channel."""
    poles = np.asarray(ss.poles())
    rows = []
    for p in sorted(poles, key=lambda z: (abs(z), z.imag)):
        wn = abs(p)
        zeta = -p.real / wn if wn > 0 else float("nan")
        rows.append([p.real, p.imag, wn, "" if math.isnan(zeta) else zeta])
    stable = "stable" if ss.is_stable() else "not asymptotically stable"
    body = [f"<p>{ss.n_states} states, {ss.n_inputs} inputs ({_esc(', '.join(ss.inputs))}), "
            f"{ss.n_outputs} outputs ({_esc(', '.join(ss.outputs))}); {stable}</p>",
            "<h4>States</h4>", _table(["state"], ([s] for s in ss.states)),
            "<h4>Poles</h4>",
            _table(["real", "imaginary", "natural frequency [rad/s]", "damping ratio"], rows,
                   numeric=(0, 1, 2, 3))]
    if plot and ss.n_inputs and ss.n_outputs and ss.n_states:
        try:
            body.append(png_img(bode_png(ss), "Bode plot"))
        except ImportError:
            body.append("<p>(matplotlib is not installed: no Bode plot)</p>")
    return _div("Linear model (state space)", body)


class Rich:
    """What ``show`` returns: an object Jupyter renders with its ``_repr_html_``."""

    def __init__(self, text: str):
        self.text = text

    def _repr_html_(self) -> str:
        return self.text

    def __str__(self):
        return self.text


def show(obj, **options) -> Rich:
    """An object a notebook displays as HTML, for any of a Component, CompiledModel,
    IndexReport, Result or StateSpace (``display.show(compiled.report)`` as the last
    line of a cell).  ``options`` go to the matching ``*_html`` function."""
    from ..components import Component
    kind = type(obj).__name__
    if isinstance(obj, Component):
        return Rich(component_html(obj, **options))
    dispatch = {"CompiledModel": model_html, "IndexReport": report_html,
                "Result": result_html, "StateSpace": statespace_html}
    if kind not in dispatch:
        raise TypeError(f"show() takes a Component, CompiledModel, IndexReport, Result or "
                        f"StateSpace, not a {kind}")
    return Rich(dispatch[kind](obj, **options))
