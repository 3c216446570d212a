"""The documentation's sources stay consistent with the code (the full build,
``mkdocs build --strict``, simulates every example and runs in ``make docs``)."""
import importlib
import importlib.util
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
yaml = pytest.importorskip("yaml")


def _hooks():
    spec = importlib.util.spec_from_file_location("docs_hooks", ROOT / "docs" / "hooks.py")
    module = importlib.util.module_from_spec(spec)
    pytest.importorskip("mkdocs")
    spec.loader.exec_module(module)
    return module


def _nav_pages(entries):
    for entry in entries:
        for value in (entry.values() if isinstance(entry, dict) else [entry]):
            if isinstance(value, list):
                yield from _nav_pages(value)
            else:
                yield value


def test_every_api_reference_module_imports():
    modules = [m for page in sorted((ROOT / "docs" / "api").glob("*.md"))
               for m in re.findall(r"^::: (\S+)$", page.read_text(), re.M)]
    assert len(modules) > 30
    for name in modules:
        importlib.import_module(name)


def test_every_library_module_has_a_reference_page():
    listed = "".join(p.read_text() for p in (ROOT / "docs" / "api").glob("library-*.md"))
    for path in sorted(ROOT.glob("library/*/*.py")):
        if path.name.startswith("_") or path.parent.name == "examples":
            continue          # the examples have their own generated pages
        name = "acausal." + ".".join(path.relative_to(ROOT).with_suffix("").parts)
        assert f"::: {name}\n" in listed, name


def test_nav_pages_exist_or_are_generated():
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text())
    generated = {"tutorial.md", "examples/index.md"}
    for page in _nav_pages(config["nav"]):
        assert page in generated or (ROOT / "docs" / page).is_file(), page


def test_generated_pages_cover_the_tutorial_and_every_example():
    hooks = _hooks()
    text = hooks._tutorial_markdown()
    assert "class MotorDrive(ac.Component):" in text and "ac.linearize(" in text
    names = hooks._example_modules()
    files = sorted(ROOT.glob("library/*/examples/[!_]*.py")) + sorted(
        ROOT.glob("library/examples/[!_]*.py"))
    assert len(names) == len(files) > 10
    assert "acausal.library.translational.examples.mass_spring_damper" in names
