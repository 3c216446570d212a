"""Faults injected into the compile cache, as a careful user's environment produces them,
each in a private cache: the table of what a later run does.

Each row starts from a cache that a first process filled (the motor drive of
``library/examples/motor_drive.py`` compiled, its C library built, the run to 1 s made with the compiled loop), damages it, and runs the same model
in a new process twice: the first of these must detect the damage (a ``CacheWarning``
line), rebuild, and give the reference result; the second must find the rebuilt entry
(a cache hit) with the same result.  A row passes when neither process crashed, both
results equal the reference (relative 1e-9: the same model and step loop), and the
damage was said.

    python benchmarks/cache_faults.py [--only TEXT]

Rows: a byte flipped in the model's library; the library truncated to half and to 0
bytes; a parameter value changed in the pickled entry (24 V -> 42 V); the entry truncated; with ``cache="tree"``: an index of
non-UTF-8 bytes, an index copied from another model's, a component library in a
site-packages directory edited after the first run; an entry owned by another user (as
root only); a group-writable cache directory; an uncreatable cache directory and a HOME
that cannot hold one (``/proc``); leftovers of killed builds (an hour old) pruned; a
malformed ``ACAUSAL_CACHE_SIZE``.
"""
from __future__ import annotations

import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import textwrap

__all__ = ["main", "ROWS"]

CHILD = textwrap.dedent("""
    import json, sys, warnings
    sys.path[:0] = {paths!r}
    import acausal as ac
    from {module} import {cls}
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        try:
            c = ac.compile({cls}(), cache={cache!r})
            r = ac.simulate(c, 1.0, step_loop={loop!r})
            out = {{"w": float(r["load.w"][-1]), "success": bool(r.success),
                    "hit": any("came from the compile cache" in n for n in c.report.notes),
                    "backend": c.backend, "loop": r.stats.get("step_loop")}}
        except Exception as exc:
            out = {{"error": f"{{type(exc).__name__}}: {{exc}}"}}
    out["said"] = [str(w.message) for w in seen if "Cache" in type(w.message).__name__]
    print(json.dumps(out))
""")

SITE_MODEL = textwrap.dedent("""
    import acausal as ac
    from acausal.library.electrical import Ground, StepVoltage
    from acausal.library.electromechanical import DCMotor
    from acausal.library.rotational import Fixed, Inertia, SpringDamper
    from acausal.library.rotational.interfaces import PartialCompliant

    class Drag(PartialCompliant):
        \"\"\"Viscous drag with its coefficient written in the equation.\"\"\"
        def equations(self):
            return [ac.Eq(self.tau, 0.01 * ac.der(self.phi_rel))]

    class Drive(ac.Component):
        source = StepVoltage(V=24.0, startTime=0.1)
        ground = Ground()
        motor = DCMotor(R=1.0, L=1e-3, k=0.05, J=1e-4)
        shaft = SpringDamper(c=100.0, d=0.01)
        load = Inertia(J=0.01)
        drag = Drag()
        housing = Fixed()

        def equations(self):
            return [ac.connect(self.source.p, self.motor.p),
                    ac.connect(self.source.n, self.motor.n, self.ground.p),
                    ac.connect(self.motor.flange, self.shaft.flange_a),
                    ac.connect(self.shaft.flange_b, self.load.flange_a),
                    ac.connect(self.load.flange_b, self.drag.flange_a),
                    ac.connect(self.drag.flange_b, self.housing.flange)]
""")
EDIT = ("0.01 * ac.der", "1.5 * ac.der")      # the drag coefficient, in the source only


def run(cache, env=None, module="acausal.library.examples.motor_drive", cls="MotorDrive",
        tree=False, loop="c", paths=(), python=None) -> dict:
    """One process: compile and simulate; its outcome as a dict (``exit`` its status)."""
    code = CHILD.format(paths=list(paths), module=module, cls=cls,
                        cache="tree" if tree else True, loop=loop)
    full = dict(os.environ, ACAUSAL_CACHE=str(cache))
    full.pop("ACAUSAL_COMPILE_CACHE", None)
    full.pop("ACAUSAL_CACHE_SIZE", None)
    full.update(env or {})
    proc = subprocess.run([python or sys.executable, "-c", code], capture_output=True,
                          text=True, env=full, timeout=600)
    out = {"exit": proc.returncode}
    try:
        out.update(json.loads(proc.stdout.strip().splitlines()[-1]))
    except (IndexError, ValueError):
        out["error"] = (proc.stderr.strip().splitlines() or ["no output"])[-1]
    return out


def _library(cache) -> str:
    """The model's library in the cache (the compiled step loop is built when acausal is
    installed, not kept in the cache)."""
    return [os.path.join(cache, n) for n in os.listdir(cache) if n.endswith(".so")][0]


def _entry(cache) -> str:
    models = os.path.join(cache, "models")
    return [os.path.join(models, n) for n in os.listdir(models)
            if n.endswith(".pkl") and not n.endswith(".programs.pkl")][0]


def _flip(path, where=0.5, n=16) -> None:
    with open(path, "r+b") as f:
        data = bytearray(f.read())
        k = int(len(data) * where)
        for i in range(k, min(k + n, len(data))):
            data[i] ^= 0xFF
        f.seek(0)
        f.write(data)


def _truncate(path, fraction) -> None:
    size = os.path.getsize(path)
    with open(path, "r+b") as f:
        f.truncate(int(size * fraction))


def _param_24_to_42(cache) -> None:
    path = _entry(cache)
    with open(path, "rb") as f:
        data = f.read()
    old, new = b"G" + struct.pack(">d", 24.0), b"G" + struct.pack(">d", 42.0)
    assert old in data, "the pickled entry holds no 24.0"
    with open(path, "wb") as f:
        f.write(data.replace(old, new, 1))


def _tree_index(cache) -> str:
    models = os.path.join(cache, "models")
    return [os.path.join(models, n) for n in os.listdir(models) if n.startswith("tree-")][0]


# -- the rows: (name, damage(cache, ctx), options of the runs) -----------------------------
def _lib_flip(c, ctx):
    _flip(_library(c), 0.45)


def _lib_half(c, ctx):
    _truncate(_library(c), 0.5)


def _lib_zero(c, ctx):
    _truncate(_library(c), 0.0)


def _entry_param(c, ctx):
    _param_24_to_42(c)


def _entry_half(c, ctx):
    _truncate(_entry(c), 0.5)


def _tree_bytes(c, ctx):
    with open(_tree_index(c), "wb") as f:
        f.write(b"\xff\xfe\xfa not an index \x80\x81")


def _tree_other(c, ctx):
    # a second model stored beside the first (another load inertia): its index's
    # content copied over the first model's index
    first = _tree_index(c)
    before = set(os.listdir(os.path.join(c, "models")))
    other = run(c, module="acausal_faults_other", cls="Other", tree=True,
                paths=[ctx["extra"]])
    assert "w" in other, other
    new = [n for n in set(os.listdir(os.path.join(c, "models"))) - before
           if n.startswith("tree-")]
    with open(os.path.join(c, "models", new[0]), "rb") as f:
        data = f.read()
    with open(first, "wb") as f:
        f.write(data)


def _site_python(work) -> tuple:
    """(interpreter, its site-packages): a virtual environment of its own whose
    site-packages also reads this one's, so that a package installed in it is installed
    code under the interpreter's prefix, as ``pip install`` puts it."""
    import site
    import sysconfig
    env = os.path.join(work, "venv")
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", env], check=True)
    python = os.path.join(env, "bin", "python")
    purelib = subprocess.run([python, "-c", "import sysconfig; print(sysconfig.get_paths()"
                              "['purelib'])"], capture_output=True, text=True,
                             check=True).stdout.strip()
    ours = [sysconfig.get_paths()["purelib"]] + site.getsitepackages()
    with open(os.path.join(purelib, "outer.pth"), "w") as f:
        f.write("import site; " + "; ".join(f"site.addsitedir({p!r})" for p in ours) + "\n")
    return python, purelib


def _site_edit(c, ctx):
    path = os.path.join(ctx["site"], "faultlib", "__init__.py")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace(*EDIT))
    ctx["reference"] = ctx["edited"]


def _foreign_owner(c, ctx):
    if os.getuid() != 0:
        ctx["skip"] = "needs root to give a file to another user"
        return
    os.chown(_entry(c), 54321, 54321)


def _group_writable(c, ctx):
    os.chmod(c, 0o770)


def _leftovers(c, ctx):
    old = 2 * 3600
    import time
    t = time.time() - old
    os.makedirs(os.path.join(c, "build_killed"))
    with open(os.path.join(c, "build_killed", "model0.o"), "wb") as f:
        f.write(b"\0" * 4_000_000)
    for d in (c, os.path.join(c, "models")):
        with open(os.path.join(d, ".tmp-killed"), "wb") as f:
            f.write(b"\0" * 3_000_000)
        os.utime(os.path.join(d, ".tmp-killed"), (t, t))
    os.utime(os.path.join(c, "build_killed"), (t, t))
    # a new model must be stored for the cache to be pruned
    shutil.rmtree(os.path.join(c, "models"))
    ctx["check"] = lambda: not any(n.startswith(("build_", ".tmp-")) for n in os.listdir(c))


ROWS = [
    ("byte flipped in the model's library", _lib_flip, {}),
    ("model's library truncated to half", _lib_half, {}),
    ("model's library truncated to 0 bytes", _lib_zero, {}),
    ("parameter in the entry 24 V -> 42 V", _entry_param, {}),
    ("entry truncated to half", _entry_half, {}),
    ("tree: index of non-UTF-8 bytes", _tree_bytes, {"tree": True}),
    ("tree: index copied from another model", _tree_other, {"tree": True}),
    ("tree: site-packages component library edited", _site_edit, {"tree": True,
                                                                   "site": True}),
    ("entry owned by another user", _foreign_owner, {}),
    ("cache directory group-writable", _group_writable, {"refused": True}),
    ("leftovers of killed builds (2 h old)", _leftovers, {}),
]


def _row(name, damage, opts, work) -> tuple:
    cache = os.path.join(work, "cache")
    shutil.rmtree(cache, ignore_errors=True)
    ctx = {"extra": work}
    kw = {"tree": opts.get("tree", False)}
    if opts.get("site"):
        python, ctx["site"] = _site_python(work)
        kw.update(module="faultlib", cls="Drive", python=python)
        os.makedirs(os.path.join(ctx["site"], "faultlib"), exist_ok=True)
        with open(os.path.join(ctx["site"], "faultlib", "__init__.py"), "w") as f:
            f.write(SITE_MODEL)
        edited = os.path.join(work, "edited-cache")
        shutil.rmtree(edited, ignore_errors=True)
        with open(os.path.join(ctx["site"], "faultlib", "__init__.py"), "w") as f:
            f.write(SITE_MODEL.replace(*EDIT))
        ctx["edited"] = run(edited, **kw)["w"]
        with open(os.path.join(ctx["site"], "faultlib", "__init__.py"), "w") as f:
            f.write(SITE_MODEL)
    first = run(cache, **kw)
    if "w" not in first:
        return name, "first run failed: " + first.get("error", "?"), False
    ctx["reference"] = first["w"]
    damage(cache, ctx)
    if "skip" in ctx:
        return name, "skipped: " + ctx["skip"], True
    second, third = run(cache, **kw), run(cache, **kw)
    ref = ctx["reference"]
    ok = all(r["exit"] == 0 and "w" in r and abs(r["w"] - ref) <= 1e-9 * abs(ref)
             and r["success"] for r in (second, third))
    said = second.get("said", [])
    if opts.get("refused"):
        what = "refused, ran without it" if said and not second.get("hit") else "used"
        ok = ok and bool(said) and not second.get("hit")
    elif "check" in ctx:
        what = "pruned" if ctx["check"]() else "left"
        ok = ok and ctx["check"]()
    else:
        what = ("detected, rebuilt" if said else "not said") + \
            (", then a hit" if third.get("hit") else ", then no hit")
        if name.startswith("tree: site"):
            what = ("seen" if not second.get("hit") else "stale hit") + \
                (", then a hit" if third.get("hit") else "")
            ok = ok and not second.get("hit") and third.get("hit")
        else:
            ok = ok and bool(said) and third.get("hit")
    detail = f"{what}; exit {second['exit']}/{third['exit']}; w = " + \
        (f"{second['w']:.6g}" if "w" in second else second.get("error", "?")) + \
        f" (reference {ref:.6g})"
    return name, detail, ok


def _environment_rows(work) -> list:
    rows = []
    for name, env, cache in [
            ("cache directory cannot be created", {}, "/proc/acausal-cache"),
            ("HOME cannot hold a cache", {"HOME": "/proc"}, None)]:
        full = dict(env)
        if cache is None:
            out = _run_without_cache_var(full)
        else:
            out = run(cache, env=full)
        ok = out["exit"] == 0 and "w" in out and bool(out.get("said"))
        rows.append((name, f"{'warned once' if len(out.get('said', [])) == 1 else out.get('said')}"
                           f", exit {out['exit']}, backend {out.get('backend')}, step loop "
                           f"{out.get('loop')}" + ("" if "w" in out else f": {out.get('error')}"),
                     ok))
    out = run(os.path.join(work, "cache-size"), env={"ACAUSAL_CACHE_SIZE": "10x"})
    ok = "CacheError" in out.get("error", "")
    rows.append(("ACAUSAL_CACHE_SIZE=10x", out.get("error", "accepted")[:90], ok))
    return rows


def _run_without_cache_var(env) -> dict:
    code = CHILD.format(paths=[], module="acausal.library.examples.motor_drive",
                        cls="MotorDrive", cache=True, loop="c")
    full = dict(os.environ)
    full.pop("ACAUSAL_CACHE", None)
    full.update(env)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=full, timeout=600)
    out = {"exit": proc.returncode}
    try:
        out.update(json.loads(proc.stdout.strip().splitlines()[-1]))
    except (IndexError, ValueError):
        out["error"] = (proc.stderr.strip().splitlines() or ["no output"])[-1]
    return out


def main(argv=None) -> int:
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", default="", help="the rows whose name has this text")
    only = parser.parse_args(argv).only
    work = tempfile.mkdtemp(prefix="acausal-cache-faults-")
    with open(os.path.join(work, "acausal_faults_other.py"), "w") as f:
        f.write("from acausal.library.examples.motor_drive import MotorDrive\n\n\n"
                "class Other(MotorDrive):\n    load = MotorDrive.load.__class__(J=0.05)\n")
    rows = []
    try:
        for name, damage, opts in ROWS:
            if only not in name:
                continue
            rows.append(_row(name, damage, opts, work))
            print(f"| {rows[-1][0]} | {rows[-1][1]} | {'ok' if rows[-1][2] else 'FAIL'} |",
                  flush=True)
        for row in _environment_rows(work) if not only else ():
            rows.append(row)
            print(f"| {row[0]} | {row[1]} | {'ok' if row[2] else 'FAIL'} |", flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"{sum(r[2] for r in rows)} of {len(rows)} rows hold")
    return 0 if all(r[2] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
