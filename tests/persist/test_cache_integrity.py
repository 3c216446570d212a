"""The compile cache verifies before it trusts, and can be absent.

Each test damages a private cache as a user's environment does (a flipped byte, a
truncated file, a value changed in an entry, an index copied from another model, a
directory that cannot be made or that others may write) and checks that the later run
detects it (one ``CacheWarning`` line), rebuilds, and gives the closed-form result of the
RC discharge v(t) = v0 exp(-t / (R C)) -- never a wrong number, never a crash.
"""
import os
import stat
import struct
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import acausal as ac
from acausal.native import cachefiles
from acausal.compiler.cache import keys as cachekeys
from acausal.compiler.pipeline import compile_model
from acausal.runtime import CompiledModel

from .circuits import RC
from .helpers import run_python

HIT = "came from the compile cache"


@pytest.fixture(autouse=True)
def cache_dir(fresh_cache):
    return fresh_cache


def _needs_cc():
    from acausal.native import find_compiler
    if find_compiler() is None:
        pytest.skip("no C compiler")


def _compile(model, backend="numpy", cache=True):
    return CompiledModel(compile_model(model, backend, cache=cache))


def _hit(compiled) -> bool:
    return any(HIT in n for n in compiled.report.notes)


def _v1(compiled, **kw) -> float:
    """v(1 s) of the discharge; the closed form with R = 2, C = 0.5 is exp(-1)."""
    return float(ac.simulate(compiled, t_end=1.0, rtol=1e-9, atol=1e-12, **kw)["C1.v"][-1])


def _entry(cache_dir):
    return next(p for p in (cache_dir / "models").glob("*.pkl")
                if not p.name.endswith(".programs.pkl"))


def _replace(path, data: bytes) -> None:
    """Write ``data`` as a new file in place of ``path``: a library this process has
    loaded stays mapped from the old file (rewriting that file in place would change
    the code under the running process, which no check can prevent)."""
    tmp = path.with_name(path.name + ".damaged")
    tmp.write_bytes(data)
    os.replace(tmp, path)


def _flip(path, where=0.5, n=8):
    data = bytearray(path.read_bytes())
    k = int(len(data) * where)
    for i in range(k, min(k + n, len(data))):
        data[i] ^= 0xFF
    _replace(path, bytes(data))


@pytest.mark.parametrize("damage", ["flip", "half", "empty"])
def test_a_damaged_library_is_detected_and_built_again(cache_dir, damage):
    _needs_cc()
    first = _compile(RC(), "c")
    lib = first.code.library
    assert os.path.exists(lib + ".sha256")
    path = type(cache_dir)(lib)
    if damage == "flip":
        _flip(path, 0.45)
    else:
        _replace(path, path.read_bytes()[:path.stat().st_size // 2 if damage == "half" else 0])
    with pytest.warns(ac.CacheWarning, match=f"C library {lib}.*(failed its checksum)"):
        again = _compile(RC(), "c")
    assert _hit(again) and again.backend == "c"
    assert not any("does not load" in n for n in again.report.notes)
    assert abs(_v1(again) - np.exp(-1.0)) <= 1e-6
    assert cachefiles.library_ok(lib)          # rebuilt whole, with its checksum


def test_a_value_changed_in_an_entry_is_never_unpickled(cache_dir):
    _compile(RC())
    entry = _entry(cache_dir)
    data = entry.read_bytes()
    # R = 2 Ohm in the pickled model (a float pickles as 'G' and 8 bytes): 2 -> 5
    old, new = b"G" + struct.pack(">d", 2.0), b"G" + struct.pack(">d", 5.0)
    assert old in data
    entry.write_bytes(data.replace(old, new, 1))
    with pytest.warns(ac.CacheWarning, match="failed its checksum; removed"):
        again = _compile(RC())
    assert not _hit(again)
    assert abs(_v1(again) - np.exp(-1.0)) <= 1e-6     # tau = 1 s, not 2.5 s
    assert _hit(_compile(RC()))                         # written again, whole


def test_a_damaged_tree_index_compiles_again(cache_dir):
    _compile(RC(), cache="tree")
    index = next((cache_dir / "models").glob("tree-*"))
    index.write_bytes(b"\xff\xfe\x80 not an index")
    with pytest.warns(ac.CacheWarning, match="index"):
        again = _compile(RC(), cache="tree")
    assert abs(_v1(again) - np.exp(-1.0)) <= 1e-6
    assert _hit(_compile(RC(), cache="tree"))


class Slower(RC):
    """R = 4 Ohm: time constant 2 s, v(1) = exp(-1/2)."""

    R1 = RC.R1.__class__(R=4.0)


def test_an_index_copied_from_another_model_is_refused(cache_dir):
    _compile(RC(), cache="tree")
    ours = set((cache_dir / "models").glob("tree-*"))
    _compile(Slower(), cache="tree")
    theirs = (set((cache_dir / "models").glob("tree-*")) - ours).pop()
    ours = ours.pop()
    ours.write_bytes(theirs.read_bytes())       # RC's tree key now names Slower's entry
    with pytest.warns(ac.CacheWarning, match="names another tree key"):
        again = _compile(RC(), cache="tree")
    assert abs(_v1(again) - np.exp(-1.0)) <= 1e-6


INSTALLED = '''
import acausal as ac


class Discharge(ac.Component):
    """der(x) = -k x, x(0) = 1, with k written in the equation: x(1) = exp(-k)."""

    x = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -1.0 * self.x)]
'''


def test_the_tree_key_sees_a_component_library_installed_in_site_packages(tmp_path,
                                                                          monkeypatch):
    site = tmp_path / "lib" / "site-packages"
    (site / "rclib").mkdir(parents=True)
    source = site / "rclib" / "__init__.py"
    source.write_text(INSTALLED)
    old = time.time() - 10
    os.utime(source, (old, old))
    monkeypatch.syspath_prepend(str(site))
    import importlib
    module = importlib.import_module("rclib")
    try:
        assert cachekeys._where(module.__file__) == "installed"
        first = _compile(module.Discharge(), cache="tree")
        x1 = ac.simulate(first, 1.0, rtol=1e-9, atol=1e-12)["x"][-1]
        assert abs(x1 - np.exp(-1.0)) <= 1e-6
        # the equation edited where the package is installed: k = 2
        source.write_text(INSTALLED.replace("-1.0 * self.x", "-2.0 * self.x"))
        module = importlib.reload(module)
        again = _compile(module.Discharge(), cache="tree")
        assert not _hit(again)
        x1 = ac.simulate(again, 1.0, rtol=1e-9, atol=1e-12)["x"][-1]
        assert abs(x1 - np.exp(-2.0)) <= 1e-6
    finally:
        sys.modules.pop("rclib", None)


def test_other_installed_packages_enter_the_tree_key_by_their_version(tmp_path,
                                                                     monkeypatch):
    (tmp_path / "usesnumpy.py").write_text("import numpy as np\nK = np.pi\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import importlib
    importlib.import_module("usesnumpy")
    try:
        described, packages = cachekeys._module_closure(["usesnumpy"])
    finally:
        sys.modules.pop("usesnumpy", None)
    assert described == ["usesnumpy"] and packages == ["numpy"]


UNUSABLE = """
import warnings, sys
import acausal as ac
from acausal.tests.persist.circuits import RC
with warnings.catch_warnings(record=True) as seen:
    warnings.simplefilter("always")
    c = ac.compile(RC(), backend={backend!r})
    r = ac.simulate(c, 1.0, rtol=1e-9, atol=1e-12, step_loop={loop!r})
said = [str(w.message) for w in seen if issubclass(w.category, ac.CacheWarning)]
print(repr((float(r["C1.v"][-1]), c.backend, r.stats.get("step_loop"), said)))
"""


@pytest.mark.parametrize("where", ["under a file", "HOME under a file"])
def test_a_cache_that_cannot_be_created_is_skipped_with_one_warning(tmp_path, where):
    _needs_cc()
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    env = dict(os.environ)
    env.pop("ACAUSAL_COMPILE_CACHE", None)
    if where == "under a file":
        env["ACAUSAL_CACHE"] = str(blocker / "cache")
        named = str(blocker / "cache")
    else:
        env.pop("ACAUSAL_CACHE", None)
        env["HOME"] = str(blocker)
        named = str(blocker / ".cache" / "acausal")
    proc = subprocess.run([sys.executable, "-c", UNUSABLE.format(backend="c", loop="c")],
                          capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    v, backend, loop, said = eval(proc.stdout.strip().splitlines()[-1])  # noqa: S307
    assert abs(v - np.exp(-1.0)) <= 1e-6
    assert backend == "c" and loop == "c"     # built aside, without the cache
    assert len(said) == 1 and named in said[0] and "without it" in said[0]
    assert not list(tmp_path.glob("**/acausal-build-*"))


def test_the_switch_off_and_an_unwritable_cache_still_run(tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    monkeypatch.setenv("ACAUSAL_CACHE", str(blocker / "cache"))
    monkeypatch.setenv("ACAUSAL_COMPILE_CACHE", "0")
    with pytest.warns(ac.CacheWarning, match=str(blocker / "cache")):
        compiled = ac.compile(RC(), backend="auto")
        v = _v1(compiled)
    assert abs(v - np.exp(-1.0)) <= 1e-6


def test_the_cache_is_created_private_and_one_others_may_write_is_not_used(cache_dir):
    _compile(RC())
    assert stat.S_IMODE(os.stat(cache_dir).st_mode) == 0o700
    assert stat.S_IMODE(os.stat(cache_dir / "models").st_mode) == 0o700
    os.chmod(cache_dir, 0o770)
    with pytest.warns(ac.CacheWarning, match=f"{cache_dir}.*others may write"):
        again = _compile(RC())
    assert not _hit(again)
    assert abs(_v1(again) - np.exp(-1.0)) <= 1e-6


@pytest.mark.skipif(not hasattr(os, "getuid") or os.getuid() != 0,
                    reason="giving a file to another user needs root")
def test_an_entry_of_another_user_is_not_loaded(cache_dir):
    _compile(RC())
    os.chown(_entry(cache_dir), 54321, 54321)
    with pytest.warns(ac.CacheWarning, match="belongs to user 54321"):
        again = _compile(RC())
    assert not _hit(again)
    assert abs(_v1(again) - np.exp(-1.0)) <= 1e-6


def test_leftovers_older_than_an_hour_are_pruned(cache_dir):
    _compile(RC())
    old = time.time() - 2 * cachefiles.LEFTOVER_AGE
    (cache_dir / "build_killed").mkdir()
    (cache_dir / "build_killed" / "model0.o").write_bytes(b"\0" * 1000)
    (cache_dir / "build_running").mkdir()            # a build going on now: kept
    for d in (cache_dir, cache_dir / "models"):
        (d / ".tmp-killed").write_bytes(b"\0" * 1000)
        os.utime(d / ".tmp-killed", (old, old))
    os.utime(cache_dir / "build_killed", (old, old))
    cachefiles.prune(str(cache_dir))
    left = sorted(p.name for p in cache_dir.iterdir()) + \
        sorted(p.name for p in (cache_dir / "models").iterdir())
    assert "build_killed" not in left and ".tmp-killed" not in left
    assert "build_running" in left and any(n.endswith(".pkl") for n in left)


@pytest.mark.parametrize("text, size", [("1000", 1000), ("10k", 10240), ("512M", 512 << 20),
                                        ("2 GiB", 2 << 30), (" 3MB ", 3 << 20)])
def test_the_cache_size_reads_bytes_and_binary_multiples(monkeypatch, text, size):
    monkeypatch.setenv("ACAUSAL_CACHE_SIZE", text)
    assert cachefiles.size_limit() == size


@pytest.mark.parametrize("text", ["ten", "-5", "1.5G", "10x", "5 5"])
def test_a_malformed_cache_size_is_an_error(monkeypatch, text):
    monkeypatch.setenv("ACAUSAL_CACHE_SIZE", text)
    with pytest.raises(ac.CacheError, match="ACAUSAL_CACHE_SIZE"):
        ac.compile(RC())


def test_the_compiler_fingerprint_names_the_code_this_process_runs(monkeypatch):
    # a source of the compiler edited while a process runs does not change what that
    # process compiles with, so it must not change the name its entries are stored under
    # (a fresh process, running the edited code, would load the old code's entries)
    taken = cachekeys.fingerprint()
    monkeypatch.setattr(cachekeys, "_file_hash", lambda path: "edited")
    assert cachekeys.fingerprint() == taken
    # what an edited source gives a fresh process is another name
    assert cachekeys._sources_fingerprint() != taken
