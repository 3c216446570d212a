"""A 3-D animation of the spatial frames of a multibody result (matplotlib).

Every frame of the result (a name with ``.x``, ``.y``, ``.z`` and ``.R11`` ... ``.R33``)
whose motion differs from the others' is drawn as a dot with its three axes
(x red, y green, z blue; R's rows are the frame's axes in the world), and the
``links`` given as pairs of frame names as lines between their origins.  The file is a
GIF (matplotlib's Pillow writer) when Pillow is installed and the path ends in .gif,
otherwise an HTML page with the animation as JavaScript (``to_jshtml``).

The world's y is drawn upwards (the World's default gravity is along -y): the picture's
axes are (x, -z, y), a rotation of the world's, so the drawing stays right-handed.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["animate", "spatial_frames"]

_AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")


def spatial_frames(res) -> list:
    """The paths of the spatial frames in the result, one per distinct motion (frames
    joined rigidly at one point, such as a joint's frame_b and the body on it, appear
    once)."""
    names = set(res.names)
    paths = [n[:-4] for n in res.names if n.endswith(".R11")
             and all(f"{n[:-4]}.{c}" in names for c in "xyz")]
    distinct, seen = [], []
    for p in paths:
        motion = np.concatenate([res[f"{p}.{c}"] for c in ("x", "y", "z", "R11", "R22",
                                                          "R33", "R12")])
        if not any(np.allclose(motion, m, rtol=0, atol=1e-9) for m in seen):
            seen.append(motion)
            distinct.append(p)
    return distinct


# world (x, y, z) -> picture (x, -z, y): the world's y up
_TO_PICTURE = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def _point(res, path, k):
    return _TO_PICTURE @ np.array([res[f"{path}.{c}"][k] for c in "xyz"])


def _axes_of(res, path, k):
    R = np.array([[res[f"{path}.R{i}{j}"][k] for j in (1, 2, 3)] for i in (1, 2, 3)])
    return _point(res, path, k), R @ _TO_PICTURE.T      # rows: the axes, in the picture


def animate(res, path, frames=None, links=(), n_frames: int = 60, fps: int = 20,
            axis_length: float | None = None) -> Path:
    """Write an animation of the result's spatial frames to ``path`` and return it.

    Parameters
    ----------
    res : Result
        A simulation result of a model with spatial frames.
    path : str or Path
        ``.gif`` (needs Pillow; else an ``.html`` next to it is written) or ``.html``.
    frames : list of str, optional
        Frame paths to draw (default ``spatial_frames(res)``).
    links : sequence of (str, str)
        Pairs of frame paths to join with a line (bars, rods).
    n_frames, fps : int
        Number of pictures (evenly spaced in time) and their rate.
    axis_length : float, optional
        Length of the drawn frame axes [m] (default a tenth of the motion's extent).
    """
    from matplotlib.animation import FuncAnimation, PillowWriter
    from matplotlib.figure import Figure

    frames = list(frames) if frames is not None else spatial_frames(res)
    if not frames:
        raise ValueError("animate: the result has no spatial frames "
                         "(names with .x, .y, .z and .R11 ... .R33)")
    for name in [f for pair in links for f in pair] + frames:
        if f"{name}.R11" not in res and f"{name}.x" not in res:
            raise KeyError(f"animate: no frame '{name}' in the result")
    idx = np.linspace(0, len(res.t) - 1, max(int(n_frames), 2)).round().astype(int)
    pts = np.einsum("ij,fjn->fin", _TO_PICTURE,
                    np.array([[res[f"{p}.{c}"][idx] for c in "xyz"] for p in frames]))
    lo, hi = pts.min(axis=(0, 2)), pts.max(axis=(0, 2))
    span = max(float(np.max(hi - lo)), 1e-3)
    L = axis_length if axis_length is not None else span / 10
    centre = (lo + hi) / 2

    fig = Figure(figsize=(5, 5))
    ax = fig.add_subplot(projection="3d")
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - 0.6 * span, c + 0.6 * span)
    ax.set_xlabel("x [m]"), ax.set_ylabel("-z [m]"), ax.set_zlabel("y [m]")
    dots = ax.plot([], [], [], "ko", ms=4)[0]
    triads = [[ax.plot([], [], [], color=col, lw=1.5)[0] for col in _AXIS_COLOURS]
              for _ in frames]
    bars = [ax.plot([], [], [], color="0.3", lw=2)[0] for _ in links]
    title = ax.set_title("")

    def draw(n):
        k = idx[n]
        origins = []
        for lines, p in zip(triads, frames):
            o, R = _axes_of(res, p, k)
            origins.append(o)
            for line, axis in zip(lines, R):        # R's rows: the frame's axes in the world
                end = o + L * axis
                line.set_data_3d([o[0], end[0]], [o[1], end[1]], [o[2], end[2]])
        o = np.array(origins)
        dots.set_data_3d(o[:, 0], o[:, 1], o[:, 2])
        for line, (a, b) in zip(bars, links):
            line.set_data_3d(*zip(_point(res, a, k), _point(res, b, k)))
        title.set_text(f"t = {res.t[k]:.2f} s")
        return [dots, title, *bars, *(l for ls in triads for l in ls)]

    anim = FuncAnimation(fig, draw, frames=len(idx), interval=1000 / fps, blit=False)
    path = Path(path)
    if path.suffix.lower() == ".gif":
        try:
            import PIL  # noqa: F401
            anim.save(path, writer=PillowWriter(fps=fps))
            return path
        except ImportError:
            path = path.with_suffix(".html")
    path.write_text(anim.to_jshtml(fps=fps))
    return path
