"""Pictures for the notebook: the states of a result, a Bode plot, the BLT incidence.

The result and Bode plots are drawn with matplotlib (Agg, no window) into PNG bytes; the
incidence matrix in BLT order is drawn directly as SVG (one square per non-zero, each
block outlined, torn blocks in red), so the report's picture needs no plotting library.
"""
from __future__ import annotations

import base64
import html
import io

import numpy as np

__all__ = ["result_png", "bode_png", "blt_svg", "png_img"]

_MAX_PANELS = 6


def _figure():
    import matplotlib
    from matplotlib.figure import Figure     # no pyplot: never opens a window
    matplotlib.rcParams.setdefault("svg.fonttype", "none")
    return Figure


def _png(fig) -> bytes:
    buf = io.BytesIO()
    # the figures are laid out when made (layout="constrained"): bbox_inches="tight" would
    # draw them twice
    fig.savefig(buf, format="png", dpi=96)
    return buf.getvalue()


def png_img(data: bytes, alt: str) -> str:
    """An ``<img>`` element holding PNG bytes inline (a notebook keeps it in its HTML)."""
    return (f'<img alt="{html.escape(alt)}" src="data:image/png;base64,'
            f'{base64.b64encode(data).decode("ascii")}"/>')


def result_png(res, names=None, units=None) -> bytes:
    """The selected variables (default: the states, at most six) against time, one panel
    each, labelled with their units where known; events as dotted lines."""
    Figure = _figure()
    names = list(names) if names is not None else list(res.states)[:_MAX_PANELS]
    units = units or {}
    fig = Figure(figsize=(7.0, 1.6 * max(len(names), 1) + 0.6), layout="constrained")
    axes = fig.subplots(max(len(names), 1), 1, sharex=True, squeeze=False)[:, 0]
    events = [getattr(e, "time", e) for e in res.events]
    for ax, name in zip(axes, names):
        ax.plot(res.t, res[name], lw=1.4)
        unit = units.get(name, "")
        ax.set_ylabel(f"{name}\n[{unit}]" if unit else name, fontsize=8)
        for te in events:
            if isinstance(te, (int, float, np.floating)):
                ax.axvline(float(te), color="0.6", ls=":", lw=0.8)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time [s]")
    return _png(fig)


def bode_png(ss, output=None, input=None) -> bytes:  # noqa: A002 (control naming)
    """Magnitude and phase of one channel of a StateSpace against frequency."""
    Figure = _figure()
    w, mag, phase = ss.bode(output=output, input=input)
    out = output if output is not None else ss.outputs[0]
    inp = input if input is not None else ss.inputs[0]
    fig = Figure(figsize=(6.5, 4.2), layout="constrained")
    a1, a2 = fig.subplots(2, 1, sharex=True)
    if not np.any(np.isfinite(mag)):
        # an input without effect at this operating point (a source switched off)
        a1.text(0.5, 0.5, "the transfer function is identically zero here",
                ha="center", va="center", transform=a1.transAxes)
    a1.semilogx(w, mag)
    a1.set_ylabel("magnitude [dB]")
    a2.semilogx(w, phase)
    a2.set_ylabel("phase [deg]")
    a2.set_xlabel("frequency [rad/s]")
    for ax in (a1, a2):
        ax.grid(True, alpha=0.3)
    a1.set_title(f"Bode: {out} / {inp}", fontsize=10)
    return _png(fig)


def blt_svg(report, max_size: int = 600) -> str:
    """The incidence matrix in BLT order as SVG: rows are equations, columns variables,
    blocks outlined on the diagonal (red: torn).  Above ``max_size`` unknowns a note."""
    eqs, vars_ = report.blt_order()
    n = len(vars_)
    if n == 0:
        return "<p>(no algebraic blocks)</p>"
    if n > max_size:
        return f"<p>(incidence of {n} unknowns not drawn; above {max_size})</p>"
    graph = report._graph
    names = report._names
    cell = float(min(14, max(3, 420 // n)))
    label_w = 0 if cell < 8 else 9 + 6 * max(len(names[v]) for v in vars_)
    size = n * cell
    col = {v: j for j, v in enumerate(vars_)}
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" class="acausal-blt" '
           f'width="{size + 4:.0f}" height="{size + label_w + 4:.0f}">',
           f"<title>{html.escape(report.model_name)}: incidence in BLT order</title>",
           f'<g transform="translate(2,{label_w + 2})">',
           f'<rect width="{size}" height="{size}" fill="white" stroke="#ccc"/>']
    for i, e in enumerate(eqs):
        for v in graph[e]:
            if v in col:
                out.append(f'<rect class="nz" x="{col[v] * cell + 0.5:.1f}" '
                           f'y="{i * cell + 0.5:.1f}" width="{cell - 1:.1f}" '
                           f'height="{cell - 1:.1f}" fill="#222"/>')
    k = 0
    for b in report.blocks:
        s = b["size"]
        colour = "#d62728" if b.get("torn") else "#1f77b4"
        out.append(f'<rect class="block" x="{k * cell}" y="{k * cell}" width="{s * cell}" '
                   f'height="{s * cell}" fill="none" stroke="{colour}" stroke-width="1.5"/>')
        k += s
    if label_w:
        fs = min(10, cell - 2)
        for j, v in enumerate(vars_):
            x = j * cell + cell * 0.75
            out.append(f'<text x="{x:.1f}" y="-4" font-size="{fs}" '
                       f'transform="rotate(-90 {x:.1f} -4)" font-family="monospace">'
                       f"{html.escape(names[v])}</text>")
    out += ["</g>", "</svg>"]
    return "\n".join(out)
