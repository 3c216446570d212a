"""Run every benchmark script in this directory, one after the other (``make bench``).

A script is a ``.py`` file here with a ``__main__`` block (the ``bench_*.py`` and
others such as ``fuzz_networks.py``), this one excepted.  Each runs in its own Python
process, in file-name order, with its default arguments, or with ``--quick`` when the
script accepts that option; its output is printed as it comes.  The closing summary
has one line per script: ok or failed (its exit status) and its wall time.
Benchmarks print numbers and ratios and assert nothing, so the exit status is non-zero
only when a script crashed (or ran past ``--timeout``).

Usage: ``python benchmarks/run_all.py [NAME ...] [--timeout SECONDS] [--list]``, where a
NAME selects the scripts whose file name contains it (``run_all.py structure``).
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

__all__ = ["scripts", "main"]

HERE = Path(__file__).resolve().parent
QUICK = "--quick"


def scripts(names: list | None = None) -> list:
    """The benchmark scripts, in file-name order; only those matching ``names`` if any."""
    found = [p for p in sorted(HERE.glob("*.py"))
             if p.name != Path(__file__).name and not p.name.startswith("_")
             and "__main__" in p.read_text()]
    if names:
        found = [p for p in found if any(n in p.name for n in names)]
    return found


def _arguments(path: Path) -> list:
    """``--quick`` if the script declares that option, else its defaults."""
    return [QUICK] if f'"{QUICK}"' in path.read_text() else []


def _run(path: Path, timeout: float | None) -> tuple:
    """Run one script with this interpreter; (status text, failed, seconds)."""
    command = [sys.executable, str(path), *_arguments(path)]
    print(f"=== {path.name} {' '.join(command[2:])}".rstrip(), flush=True)
    t0 = time.perf_counter()
    try:
        # the output goes straight to ours, unbuffered, so that a long benchmark shows
        # its progress (and what it printed survives a timeout)
        env = {**os.environ, "PYTHONUNBUFFERED": "1"}
        code = subprocess.run(command, cwd=HERE.parent, env=env, timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        return f"failed (no result after {timeout:g} s)", True, time.perf_counter() - t0
    elapsed = time.perf_counter() - t0
    return ("ok", False, elapsed) if code == 0 else (f"failed (exit {code})", True, elapsed)


def main(argv: list | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*", help="run only scripts whose name contains one")
    ap.add_argument("--timeout", type=float, default=None,
                    help="seconds after which a script counts as failed (default: none)")
    ap.add_argument("--list", action="store_true", help="list the scripts and stop")
    args = ap.parse_args(argv)
    selected = scripts(args.names)
    if not selected:
        print("no benchmark script matches " + " ".join(args.names))
        return 2                       # a usage error, as argparse's
    if args.list:
        print("\n".join(p.name for p in selected))
        return 0
    summary = []
    for path in selected:
        status, failed, elapsed = _run(path, args.timeout)
        summary.append((path.name, status, failed, elapsed))
        print(flush=True)
    print("=== summary")
    width = max(len(name) for name, *_ in summary)
    for name, status, _, elapsed in summary:
        print(f"{name:<{width}s}  {status:<28s} {elapsed:8.1f} s")
    return 1 if any(failed for _, _, failed, _ in summary) else 0


if __name__ == "__main__":
    sys.exit(main())
