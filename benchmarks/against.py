"""This checkout against another commit of acausal, interleaved in one session.

The machine is shared and its speed drifts within an hour, so a change is measured
against the code before it by running both alternately: ``--rounds`` times, this
checkout's benchmark then the other's (``--base``: a checkout of the other commit, e.g.
``git worktree add ../base <commit>``; it is imported from there through a directory
that maps the name ``acausal`` to it, the interpreter being this one).

* ``peers``: ``peers.py`` (M1-M5, both backends), each run with a compile cache of its
  own (the build is a cold compile, its cache entry written); the step loop's library is
  the base's own where it builds one into its cache (copied there first, so that its
  runs do not start before it is built), this checkout's is installed.
* ``scale``: ``bench_scale.py --child`` for each family and size (no compile cache).

Printed: per model and backend the medians of the rounds (build s, simulate ms, and the
ratio to scipy's BDF), per family and size the medians of ``total`` and ``cpu``, each
with the ratio this/base (above 1: slower).

    python benchmarks/against.py --base ../base [--rounds 3] [--what peers,scale]
                                 [--models M1,M2,M3,M4,M5] [--sizes ladder:1000,...]
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
_ROW = re.compile(r"^\s+(acausal \[\w+\]|scipy BDF)\s+([\d.]+|-)\s+([\d.]+)\s")


def _env(tree: str | None, cache: str | None, link_dir: str) -> dict:
    env = dict(os.environ)
    env.pop("ACAUSAL_COMPILE_CACHE", None)
    if cache is not None:
        env["ACAUSAL_CACHE"] = cache
    if tree is not None:           # the other checkout, imported as acausal
        env["PYTHONPATH"] = link_dir + os.pathsep + env.get("PYTHONPATH", "")
    return env


def _base_loop_library(base: str, link_dir: str) -> str | None:
    """The path of the base's step loop library in its default cache, built now if
    the base builds it into its cache (None where the base installs it instead)."""
    code = ("import acausal.solvers.cbdf as c\n"
            "lib = c.library() if hasattr(c, 'library') else None\n"
            "print(getattr(lib, '_name', ''))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=_env(base, None, link_dir), cwd=tempfile.gettempdir())
    path = out.stdout.strip().splitlines()[-1] if out.stdout.strip() else ""
    return path if path.endswith(".so") and "_cbdf" not in os.path.basename(path) else None


def _peers_once(tree, script_dir, link_dir, models, library) -> dict:
    cache = tempfile.mkdtemp(prefix="acausal-against-")
    try:
        if library is not None:
            shutil.copy(library, cache)
        out = subprocess.run([sys.executable, os.path.join(script_dir, "peers.py"),
                              "--models", models], capture_output=True, text=True,
                             env=_env(tree, cache, link_dir), cwd=tempfile.gettempdir())
        if out.returncode != 0:
            raise RuntimeError(out.stderr[-3000:])
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    rows, model = {}, None
    for line in out.stdout.splitlines():
        m = re.match(r"^(M\d):", line)
        if m:
            model = m.group(1)
            continue
        m = _ROW.match(line)
        if m and model:
            build = float("nan") if m.group(2) == "-" else float(m.group(2))
            rows[(model, m.group(1))] = (build, float(m.group(3)))
    return rows


def _scale_once(tree, script_dir, link_dir, family, n) -> dict:
    out = subprocess.run([sys.executable, os.path.join(script_dir, "bench_scale.py"),
                          "--child", family, str(n)], capture_output=True, text=True,
                         env=_env(tree, None, link_dir), cwd=tempfile.gettempdir())
    if out.returncode != 0:
        raise RuntimeError(out.stderr[-3000:])
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", required=True, help="a checkout of the other commit")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--what", default="peers,scale")
    ap.add_argument("--models", default="M1,M2,M3,M4,M5")
    ap.add_argument("--sizes", default="ladder:1000,ladder:3000,chain:3000,network:3000")
    args = ap.parse_args(argv)
    base = os.path.abspath(args.base)
    link_dir = tempfile.mkdtemp(prefix="acausal-against-link-")
    os.symlink(base, os.path.join(link_dir, "acausal"))
    trees = {"base": (base, os.path.join(base, "benchmarks")), "this": (None, HERE)}
    what = args.what.split(",")
    peers = {k: [] for k in trees}
    scale = {k: {} for k in trees}
    library = _base_loop_library(base, link_dir) if "peers" in what else None
    for _ in range(args.rounds):
        for name, (tree, scripts) in trees.items():
            if "peers" in what:
                peers[name].append(_peers_once(tree, scripts, link_dir, args.models,
                                               library if name == "base" else None))
            if "scale" in what:
                for spec in args.sizes.split(","):
                    family, n = spec.split(":")
                    scale[name].setdefault(spec, []).append(
                        _scale_once(tree, scripts, link_dir, family, int(n)))
    shutil.rmtree(link_dir, ignore_errors=True)
    if "peers" in what:
        _print_peers(peers, args.rounds)
    if "scale" in what:
        _print_scale(scale, args.rounds)


def _median(values):
    values = [v for v in values if v == v]
    return statistics.median(values) if values else float("nan")


def _print_peers(peers, rounds) -> None:
    print(f"peers.py, medians of {rounds} interleaved rounds (each: medians of 3 runs)")
    print(f"  {'model':<6}{'solver':<17}{'build s':>9}{'base':>9}{'ratio':>7}"
          f"{'time ms':>10}{'base':>9}{'ratio':>7}{'/scipy':>8}{'base':>7}")
    keys = sorted({k for r in peers["this"] for k in r})
    for model, solver in keys:
        if not solver.startswith("acausal"):
            continue
        vals = {}
        for tree in ("this", "base"):
            rows = peers[tree]
            vals[tree] = (_median(r[(model, solver)][0] for r in rows if (model, solver) in r),
                          _median(r[(model, solver)][1] for r in rows if (model, solver) in r),
                          _median(r[(model, solver)][1] / r[(model, "scipy BDF")][1]
                                  for r in rows if (model, solver) in r
                                  and (model, "scipy BDF") in r))
        (b, t, s), (b0, t0, s0) = vals["this"], vals["base"]
        print(f"  {model:<6}{solver:<17}{b:9.2f}{b0:9.2f}{b / b0:7.2f}{t:10.1f}{t0:9.1f}"
              f"{t / t0:7.2f}{s:8.3f}{s0:7.3f}")


def _print_scale(scale, rounds) -> None:
    print(f"\nbench_scale.py (no compile cache), medians of {rounds} interleaved rounds")
    print(f"  {'family':<8}{'N':>6}{'flat':>7}{'total s':>9}{'base':>8}{'ratio':>7}"
          f"{'cpu s':>8}{'base':>8}{'ratio':>7}")
    for spec, runs in scale["this"].items():
        family, n = spec.split(":")
        base = scale["base"][spec]
        t, t0 = _median(r["total"] for r in runs), _median(r["total"] for r in base)
        c, c0 = _median(r["cpu"] for r in runs), _median(r["cpu"] for r in base)
        print(f"  {family:<8}{n:>6}{runs[0]['flat']:>7}{t:9.2f}{t0:8.2f}{t / t0:7.2f}"
              f"{c:8.2f}{c0:8.2f}{c / c0:7.2f}")
    print("  passes (this / base, medians, s):")
    for spec, runs in scale["this"].items():
        base = scale["base"][spec]
        names = [k for k in runs[0]["timings"]]
        names += [k for k in base[0]["timings"] if k not in names]
        cells = []
        for k in names:
            a = _median(r["timings"].get(k, 0.0) for r in runs)
            b = _median(r["timings"].get(k, 0.0) for r in base)
            if max(a, b) >= 0.02:
                cells.append(f"{k} {a:.2f}/{b:.2f}")
        print(f"    {spec}: " + ", ".join(cells))


if __name__ == "__main__":
    main()
