"""mkdocs hooks: the tutorial and example pages are generated at build time.

* ``tutorial.md`` from ``docs/tutorial.ipynb`` (its markdown and code cells; the
  notebook itself is executed by the test suite, tests/notebook/test_tutorial.py).
* ``examples/<domain>-<module>.md`` for every module of ``acausal.library.*.examples``:
  the module's docstring and source, and for each model class in it (a Component with a
  ``stop_time``) its schematic (SVG) and a plot of its states (PNG), simulated here.

Nothing is written into the source tree: the pages and pictures are mkdocs generated
files, so the repository holds no binaries that can go stale.
"""
from __future__ import annotations

import importlib
import inspect
import json
import logging
import pathlib
import time

from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.acausal")

ROOT = pathlib.Path(__file__).resolve().parents[1]
_RTOL = 1e-6
_POINTS = 600


def _example_modules() -> list:
    """Dotted names of the example modules, in a fixed order (domain, then module)."""
    names = []
    for path in sorted(ROOT.glob("library/*/examples/*.py")) + sorted(
            ROOT.glob("library/examples/*.py")):
        if path.name.startswith("_"):
            continue
        rel = path.relative_to(ROOT).with_suffix("")
        names.append("acausal." + ".".join(rel.parts))
    return names


def _models(module) -> list:
    return [cls for _, cls in inspect.getmembers(module, inspect.isclass)
            if cls.__module__ == module.__name__ and hasattr(cls, "stop_time")
            and hasattr(cls, "equations")]


def _tutorial_markdown() -> str:
    nb = json.loads((ROOT / "docs" / "tutorial.ipynb").read_text())
    parts = []
    for cell in nb["cells"]:
        text = "".join(cell["source"])
        parts.append(text if cell["cell_type"] == "markdown" else f"```python\n{text}\n```")
    parts.append("The notebook: [tutorial.ipynb](tutorial.ipynb) (open it in Jupyter to "
                 "see the schematic, the report tables and the plots).")
    return "\n\n".join(parts) + "\n"


def _example_page(name: str, config, files) -> tuple[str, str]:
    """(page path, title) of one example module, adding its page and pictures."""
    import acausal as ac
    from acausal import display
    from acausal.components.declarations import own_docstring

    module = importlib.import_module(name)
    slug, title = _slug(name), _title(name)
    doc = inspect.getdoc(module) or ""
    lines = [f"# {title}", "", f"`{name}`", "", *doc.splitlines()[1:], ""]
    for cls in _models(module):
        model = cls()
        started = time.perf_counter()
        res = ac.simulate(ac.compile(model), t_end=float(cls.stop_time), rtol=_RTOL,
                          n_points=_POINTS)
        took = time.perf_counter() - started
        if not res.success:
            log.warning("example %s.%s failed: %s", name, cls.__name__, res.message)
        svg, png = f"examples/{slug}-{cls.__name__}.svg", f"examples/{slug}-{cls.__name__}.png"
        files.append(File.generated(config, svg, content=display.component_svg(model)))
        files.append(File.generated(config, png, content=display.result_png(
            res, units=display.units_of(res))))
        lines += [f"## {cls.__name__}", "", own_docstring(cls),
                  "", f"![schematic of {cls.__name__}]({svg.split('/')[1]})", "",
                  f"States over {cls.stop_time:g} s (rtol {_RTOL:g}, simulated in "
                  f"{took:.1f} s when these pages were built):", "",
                  f"![states of {cls.__name__}]({png.split('/')[1]})", ""]
    source = inspect.getsource(module)
    lines += ["## Source", "", "```python", source.rstrip(), "```", ""]
    page = f"examples/{slug}.md"
    files.append(File.generated(config, page, content="\n".join(lines)))
    return page, title


def _slug(name: str) -> str:
    return "-".join(name.split(".")[2:]).replace("-examples", "")


def _title(name: str) -> str:
    doc = inspect.getdoc(importlib.import_module(name)) or ""
    return doc.splitlines()[0].rstrip(".") if doc else name


def on_config(config):
    """List every example page under "Examples" in the navigation."""
    for k, entry in enumerate(config["nav"] or []):
        if isinstance(entry, dict) and entry.get("Examples") == "examples/index.md":
            pages = [{"Overview": "examples/index.md"}]
            pages += [{_title(n): f"examples/{_slug(n)}.md"} for n in _example_modules()]
            config["nav"][k] = {"Examples": pages}
    return config


def on_files(files, config):
    files.append(File.generated(config, "tutorial.md", content=_tutorial_markdown()))
    index = ["# Examples", "",
             "Each example of the component library is a runnable model with a fixed stop "
             "time; these pages show its schematic, the simulated states and its source.", ""]
    for name in _example_modules():
        page, title = _example_page(name, config, files)
        index.append(f"* [{title}]({page.split('/')[1]})")
    files.append(File.generated(config, "examples/index.md", content="\n".join(index) + "\n"))
    return files
