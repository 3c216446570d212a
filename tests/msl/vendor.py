"""Vendor the reference result of MSL examples from a clone of MAP-LIB_ReferenceResults.

    python tests/msl/vendor.py --repo PATH Modelica.Mechanics.Rotational.Examples.First ...

``PATH`` is a git clone of https://github.com/modelica/MAP-LIB_ReferenceResults; the files
are read at tag ``v4.0.0`` (the reference results of MSL v4.0.0).  Of each example, the
columns named in its ``comparisonSignals.txt`` are kept, on every k-th row of its grid (k
chosen so that about :data:`ROWS` rows remain) plus every row of an event instant (the
rows that repeat a time, the values before and after the event, and the rows just
before and after them), and the last row.  The header records the source (repository,
tag, commit, path), the experiment of ``creation.txt`` (StopTime, Tolerance, Interval)
and the tool that computed it.  Values are copied as written in the source.
"""
from __future__ import annotations

import argparse
import csv
import io
import re
import subprocess
from pathlib import Path

REPOSITORY = "https://github.com/modelica/MAP-LIB_ReferenceResults"
TAG = "v4.0.0"
ROWS = 500
HERE = Path(__file__).resolve().parent / "references"


def _show(repo: str, path: str) -> str:
    return subprocess.run(["git", "-C", repo, "show", f"{TAG}:{path}"], check=True,
                          capture_output=True, text=True).stdout


def _setting(text: str, key: str) -> str | None:
    m = re.search(rf'^{key}\s*=\s*("[^"]*"|[^\s/]+)', text, flags=re.M)
    return m.group(1).strip('"') if m else None


def vendor(repo: str, name: str, rows: int = ROWS) -> Path:
    """Write ``references/<name>.csv`` from the reference of the example ``name``."""
    folder = name.replace(".", "/")
    base = f"{folder}/{name.split('.')[-1]}"
    creation = _show(repo, f"{folder}/creation.txt")
    signals = [s.strip() for s in _show(repo, f"{folder}/comparisonSignals.txt").splitlines()
               if s.strip()]
    table = list(csv.reader(io.StringIO(_show(repo, f"{base}.csv"))))
    head, body = table[0], [r for r in table[1:] if r]
    missing = [s for s in signals if s not in head]
    if missing:
        raise ValueError(f"{name}: comparison signals not in the result: {missing}")
    cols = [head.index(s) for s in signals]
    times = [float(r[0]) for r in body]
    step = max(1, len(body) // rows)
    keep = set(range(0, len(body), step)) | {len(body) - 1}
    for k in range(1, len(body)):
        if times[k] == times[k - 1]:            # an event: before, after and neighbours
            keep |= {k - 2, k - 1, k, k + 1}
    keep = sorted(k for k in keep if 0 <= k < len(body))
    commit = subprocess.run(["git", "-C", repo, "rev-list", "-n", "1", TAG], check=True,
                            capture_output=True, text=True).stdout.strip()
    out = HERE / f"{name}.csv"
    HERE.mkdir(parents=True, exist_ok=True)
    with open(out, "w", newline="") as f:
        f.write(f"# source: {REPOSITORY} {TAG} ({commit}) {base}.csv\n")
        f.write(f"# tool: {_setting(creation, 'generationTool')}\n")
        for key in ("StopTime", "Tolerance", "Interval"):
            f.write(f"# {key}: {_setting(creation, key)}\n")
        f.write(f"# rows: {len(keep)} of {len(body)} (every {step}th, every event "
                "instant and its neighbours, the last)\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(signals)
        for k in keep:
            w.writerow([body[k][c] for c in cols])
    return out


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", required=True, help="a clone of MAP-LIB_ReferenceResults")
    parser.add_argument("--rows", type=int, default=ROWS)
    parser.add_argument("names", nargs="+", help="full MSL class names of examples")
    args = parser.parse_args(argv)
    for name in args.names:
        path = vendor(args.repo, name, args.rows)
        print(f"{name}: {path.stat().st_size / 1024:.0f} kB")


if __name__ == "__main__":
    main()
