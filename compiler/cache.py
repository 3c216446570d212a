"""Compiled models that outlive their process: a picklable form, and the compile cache.

**Picklable form.**  :func:`portable` gives a ModelCode whose generated codes are
:class:`LoadedCode`: they pickle as their Python source (with its bytecode) and, for the
C backend, the C source, the library's path and the wrappers' layout, and are executed
again when unpickled; the library is loaded again, or rebuilt from its source when the
file is gone.  The index report pickles as plain data
(:meth:`acausal.compiler.report.IndexReport.__getstate__`).  Nothing in the pickle
refers to sympy or the code generator: loading and running a model imports neither.

**Compile cache** (:func:`lookup`, :func:`store`; ``ac.compile(..., cache=True)``, the
default, and ``cache="tree"``).
An entry is a pickled portable ModelCode in ``<cache>/models/<key>.pkl``, ``<cache>``
being ``$ACAUSAL_CACHE`` or ``~/.cache/acausal``.  Two keys lead to it, both SHA-256
over the backend (and C compiler) and the :func:`fingerprint` of the compiler:

* the **flat key** (:func:`flat_key`): everything of the flat model the compiler reads
  -- variables and all their attributes, parameters and values, every residual printed
  exactly (:class:`~acausal.compiler.symbolic.ExactText`) and the source of its text,
  initial equations, when-clauses, derivatives, structural zeros, ports, components.
  Needs flattening, hence sympy.
* the **tree key** (:func:`tree_key`, only with ``cache="tree"``), from the instance
  tree before flattening, without sympy: each instance's path, class, modifications,
  constructor arguments and plain attributes (structural parameters); every class's
  plain attributes; the source files of the model's own modules and, transitively, of
  the project modules they reference (with their plain constants).  ``<cache>/models/tree-<key>`` names the flat key it led
  to.  No tree key (only the flat one) when a part has no description that is the same
  in every process: a class without a source file (a notebook, ``python -c``), a local
  class, a value whose repr is an address.  Not seen by a tree key: equations reading
  mutable state elsewhere (a dict filled at run time, a file, the environment): that is
  why the default is the flat key, which is exact.

The fingerprint hashes the sources that determine a ModelCode (compiler, components,
ports, the model library, the model functions) and the versions of Python, numpy and
sympy (sympy's release file, found without importing it).

Writes are atomic (temporary file, then ``os.replace``): processes compiling at once each
find a whole entry or none.  An unreadable entry is removed and compiled again.  The
cache is pruned to ``$ACAUSAL_CACHE_SIZE`` bytes (default 512 MiB), least recently used
entries and C libraries first; ``$ACAUSAL_COMPILE_CACHE=0`` switches it off.
"""
from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import marshal
import math
import os
import pickle
import sys
import tempfile
import time as _time
import types
from dataclasses import fields, is_dataclass, replace

import numpy as np

from ..components.component import Component

__all__ = ["LoadedCode", "ParameterFunction", "portable", "load_notes", "flat_key",
           "tree_key", "fingerprint", "lookup", "store", "store_index", "enabled",
           "models_dir"]

DEFAULT_SIZE = 512 * 2**20
_MAGIC = importlib.util.MAGIC_NUMBER
_FORMAT = 1                  # of the entries: a new layout changes every key


# -- the picklable form --------------------------------------------------------------------
def _list(a):
    return a.tolist() if hasattr(a, "tolist") else list(a)


def _run(source: str, what: str, bytecode: bytes | None = None) -> dict:
    """Execute generated source (its bytecode when it was compiled by this Python: the
    compiling of a large model's source is most of its loading time)."""
    code = None
    if bytecode is not None and bytecode[:len(_MAGIC)] == _MAGIC:
        try:
            code = marshal.loads(bytecode[len(_MAGIC):])
        except (ValueError, EOFError, TypeError):
            code = None
    if code is None:
        code = compile(source, what, "exec")
    # the namespace the generated Python expects (acausal.compiler.codegen.python_code)
    namespace = {"math": math, "_list": _list}
    exec(code, namespace)
    return namespace


class LoadedCode:
    """A generated code without its Program: the functions executed from ``source``
    (and the C library behind them when ``c`` is given).  Reads like a
    :class:`~acausal.compiler.codegen.GeneratedCode` (``program`` is None) and pickles
    as its sources (with the bytecode of the Python source, used when the receiving
    Python has the same bytecode version), so it is rebuilt, not unpickled, in the
    receiving process.  A code loaded from the compile cache finds its Program in the
    entry's side file when something asks for it (an FMU export prints its C from it):
    only then are the Program and sympy loaded."""

    _program = None
    _program_file = None        # (path of the side file, which code), set by lookup()

    @property
    def program(self):
        if self._program is None and self._program_file is not None:
            self._program = _load_program(*self._program_file)
            self._program_file = None
        return self._program

    @program.setter
    def program(self, value) -> None:
        self._program = value

    def __init__(self, source, jac_rows, jac_cols, n_rows, n_roots, digest, c=None,
                 bytecode=None):
        ns = _run(source, "<acausal generated>", bytecode)
        self.bytecode = bytecode if bytecode and bytecode[:len(_MAGIC)] == _MAGIC else None
        self.source = source
        self.residual, self.jacobian, self.roots = ns["residual"], ns["jacobian"], ns["roots"]
        self.scales, self.expand = ns.get("scales"), ns.get("expand")
        self.jac_rows = np.asarray(jac_rows, dtype=np.int64)
        self.jac_cols = np.asarray(jac_cols, dtype=np.int64)
        self.n_rows, self.n_roots, self.digest = int(n_rows), int(n_roots), digest
        self.program = None
        self.backend = "numpy"
        self.load_note = None
        if c is not None:
            from ..errors import BackendError
            from .cbackend import reattach
            try:
                reattach(self, c["library"], c["source"], c["layout"])
            except (BackendError, OSError) as exc:
                # no library and no compiler here: the Python functions run the model
                self.load_note = (f"the C library of this model could not be loaded or "
                                  f"built ({str(exc).splitlines()[0]}); the numpy backend "
                                  "runs it")

    @classmethod
    def of(cls, code) -> "LoadedCode":
        """The same functions as ``code`` (a GeneratedCode), as a LoadedCode, sharing
        them: nothing is executed again until it is unpickled."""
        if isinstance(code, cls):
            return code
        out = cls.__new__(cls)
        out.__dict__.update({k: v for k, v in vars(code).items()
                             if k not in ("program", "_program", "_program_file")})
        out.program = None
        out.load_note = None
        out.bytecode = None
        return out

    def __reduce__(self):
        c = None
        if self.backend == "c":
            c = {"library": self.library, "source": self.c_source, "layout": self.c_layout}
        return (LoadedCode, (self.source, self.jac_rows, self.jac_cols, self.n_rows,
                             self.n_roots, self.digest, c, self._bytes()))

    def _bytes(self) -> bytes:
        if getattr(self, "bytecode", None) is None:      # compiled once, then kept
            self.bytecode = _MAGIC + marshal.dumps(compile(self.source,
                                                           "<acausal generated>", "exec"))
        return self.bytecode


class ParameterFunction:
    """f(p): a variable's value as a function of the parameters, from generated Python
    (``source`` defines ``name``); pickles as its source."""

    def __init__(self, source: str, name: str):
        self.source, self.name = source, name
        self._f = _run(source, "<acausal constants>")[name]

    def __call__(self, p):
        return self._f(p)

    def __reduce__(self):
        return (ParameterFunction, (self.source, self.name))


def _codes(mc) -> dict:
    return {"code": mc.code, "initial": mc.initial.code,
            **({"whens": mc.whens.code} if mc.whens is not None else {})}


def _load_program(path: str, which: str):
    """The Program of one code from an entry's side file, or None (pruned, unreadable)."""
    try:
        with open(path, "rb") as f:
            return pickle.load(f).get(which)
    except Exception:      # noqa: BLE001 - without it only what needs a Program fails
        return None


def portable(mc):
    """``mc`` with every generated code as a :class:`LoadedCode`: picklable, and loadable
    without sympy.  The functions themselves are shared, not rebuilt."""
    out = replace(mc, code=LoadedCode.of(mc.code),
                  initial=replace(mc.initial, code=LoadedCode.of(mc.initial.code)),
                  meta=dict(mc.meta))
    if mc.whens is not None:
        out.whens = replace(mc.whens, code=LoadedCode.of(mc.whens.code))
    return out


def load_notes(mc) -> list:
    """What went differently when the codes of ``mc`` were loaded: a C library that could
    be neither loaded nor rebuilt makes the numpy backend run the whole model."""
    codes = [mc.code, mc.initial.code] + ([mc.whens.code] if mc.whens is not None else [])
    notes = [c.load_note for c in codes if getattr(c, "load_note", None)]
    if notes:
        for c in codes:           # one backend for all: the Python functions
            for name in ("residual", "jacobian", "roots", "scales", "expand"):
                f = getattr(c, name, None)
                if f is not None and hasattr(f, "fallback"):
                    setattr(c, name, f.fallback)
            c.backend = "numpy"
        mc.meta["backend"] = "numpy"
    return notes[:1]


# -- keys -------------------------------------------------------------------------------------
class _Hasher:
    def __init__(self, *head):
        self.h = hashlib.sha256()
        self(*head)

    def __call__(self, *items) -> None:
        for x in items:
            self.h.update(str(x).encode("utf-8", "surrogatepass"))
            self.h.update(b"\x1f")
        self.h.update(b"\x1e")

    def hexdigest(self) -> str:
        return self.h.hexdigest()[:40]


_NOT_COMPILER = {"tests", "benchmarks", "docs", "__pycache__"}
# what determines a ModelCode: the passes, the component classes and their library, the
# functions models call; not the runtime, which reads a ModelCode afresh on every load
_COMPILER_PACKAGES = ("compiler", "components", "ports", "library")
_COMPILER_FILES = ("__init__.py", "errors.py", "functions.py")


def fingerprint() -> str:
    """The compiler's identity: the sources that determine a ModelCode (the compiler,
    the components, ports and model library, the model functions) and the versions of
    what it runs on.  Each call looks at the files again (a stat each; a changed file is
    read again), so an edit made while a process runs is seen too."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    h = _Hasher("acausal", _FORMAT, sys.version, np.__version__, _sympy_version())
    files = [os.path.join(root, f) for f in _COMPILER_FILES
             if os.path.exists(os.path.join(root, f))]
    for sub in _COMPILER_PACKAGES:
        for dirpath, dirnames, names in os.walk(os.path.join(root, sub)):
            dirnames[:] = sorted(d for d in dirnames if d not in _NOT_COMPILER)
            files += [os.path.join(dirpath, f) for f in names if f.endswith(".py")]
    for path in sorted(files):
        h(os.path.relpath(path, root), _file_hash(path))
    return h.hexdigest()


def _sympy_version() -> str:
    """sympy's version from its release file: found, not imported (importing sympy is
    what a cached model saves; reading the installed metadata is slower still)."""
    from importlib.util import find_spec
    spec = find_spec("sympy")
    if spec is None or not spec.submodule_search_locations:
        return "none"
    path = os.path.join(list(spec.submodule_search_locations)[0], "release.py")
    try:
        return _file_hash(path)
    except OSError:
        return "unknown"


def _backend_id(backend: str) -> tuple:
    if backend == "numpy":
        return (backend,)
    from .cbackend import compiler_available
    return (backend, compiler_available())


def flat_key(flat, backend: str) -> str | None:
    """The SHA-256 of everything of the flat model the compiler reads (see the module
    docstring), the backend and the compiler's :func:`fingerprint`; None when a value
    in it has no description that is the same in every process."""
    try:
        return _flat_key(flat, backend)
    except _Unstable:
        return None


def _flat_key(flat, backend: str) -> str:
    from ..components.symbols import Equation
    from .symbolic import ExactText
    ex = ExactText(_plain)

    def source(e):
        src = e.source
        if isinstance(src, str):
            return src
        if isinstance(src, Equation):
            return f"{ex(src.lhs)} = {ex(src.rhs)}"
        return ex(src)

    h = _Hasher("flat", fingerprint(), *_backend_id(backend), flat.name)
    for v in flat.variables:
        h("v", v.name, ex(v.symbol), repr(v.attrs), v.component, v.component_class,
          v.kind, v.hint)
    for p in flat.parameters:
        h("p", p.name, ex(p.symbol), ex(p.value), p.unit, p.description, p.component,
          p.component_class, ex(p.min), ex(p.max))
    for eqs, tag in ((flat.equations, "e"), (flat.initial_equations, "i")):
        for e in eqs:
            h(tag, e.kind, ex(e.residual), source(e), e.component, e.component_class,
              e.label)
    for x, d in flat.derivatives.items():
        h("d", ex(x), ex(d))
    for w in flat.whens:
        h("w", ex(w.condition), w.origin, w.origin_class,
          *[f"{ex(a.variable)}:={ex(a.value)}" for a in w.actions])
    h("z", *flat.structural_zeros)
    h("ports", *map(repr, flat.ports))
    h("components", *map(repr, flat.components.items()))
    return h.hexdigest()


class _Unstable(Exception):
    """A part of the instance tree has no description that is the same in every process."""


_PACKAGE = __name__.split(".")[0]
_PLAIN = (int, float, complex, str, bytes, bool, type(None))
_SOURCES: dict = {}          # path -> (mtime, size, sha256), once per process and change


def _file_hash(path: str) -> str:
    st = os.stat(path)
    known = _SOURCES.get(path)
    if known is None or known[:2] != (st.st_mtime_ns, st.st_size):
        with open(path, "rb") as f:
            known = (st.st_mtime_ns, st.st_size, hashlib.sha256(f.read()).hexdigest())
        # a file changed within the file system's timestamp resolution could change
        # again with the same size and time: such a hash is not remembered
        if _time.time() - st.st_mtime > 2.0:
            _SOURCES[path] = known
    return known[2]


def _outside_project(path: str) -> bool:
    """Installed code (the standard library, site-packages): versioned elsewhere."""
    path = os.path.abspath(path)
    prefixes = {sys.prefix, sys.base_prefix, sys.exec_prefix}
    return any(path.startswith(os.path.abspath(p) + os.sep) for p in prefixes)


def _plain(x, depth=0) -> str:
    """A description of a value that is the same in every process, or _Unstable."""
    if isinstance(x, float):
        return repr(x) if math.isfinite(x) else str(x)
    if isinstance(x, _PLAIN):
        return repr(x)
    if isinstance(x, np.generic):
        return f"{type(x).__name__}({x!r})"
    if depth > 6:
        raise _Unstable("nested too deep")
    if isinstance(x, np.ndarray):
        return f"array({x.dtype},{x.shape},{hashlib.sha256(x.tobytes()).hexdigest()})"
    if isinstance(x, (list, tuple)):
        return type(x).__name__ + "(" + ",".join(_plain(v, depth + 1) for v in x) + ")"
    if isinstance(x, dict):
        return "{" + ",".join(f"{_plain(k, depth + 1)}:{_plain(v, depth + 1)}"
                              for k, v in x.items()) + "}"
    if isinstance(x, (set, frozenset)):
        return "set(" + ",".join(sorted(_plain(v, depth + 1) for v in x)) + ")"
    if isinstance(x, (types.FunctionType, type)):
        # a function or class: named, and its module's source is part of the key
        if "<locals>" in x.__qualname__:
            raise _Unstable(f"local {x.__qualname__}")
        return f"<{x.__module__}.{x.__qualname__}>"
    if isinstance(x, Component):      # an instance given as an argument, not a child
        return (f"<{type(x).__module__}.{type(x).__qualname__} {_plain(x._mods, depth + 1)}"
                f" {_plain(getattr(x, '_init_call', None), depth + 1)}>")
    if isinstance(x, types.ModuleType):
        return f"<module {x.__name__}>"
    text = repr(x)
    if " at 0x" in text or " object at " in text:
        raise _Unstable(text)
    return f"{type(x).__module__}.{type(x).__qualname__}:{text}"


def _fingerprinted(name: str) -> bool:
    parts = name.split(".")
    return parts[0] == _PACKAGE and (len(parts) == 1 or parts[1] in _COMPILER_PACKAGES
                                     or f"{parts[1]}.py" in _COMPILER_FILES)


def _module_closure(modules: list) -> list:
    """The project modules (not installed ones) that ``modules`` reference through their
    globals, transitively: the code an ``equations()`` can call."""
    seen, order, stack = set(), [], list(modules)
    while stack:
        name = stack.pop()
        if name in seen:
            continue
        seen.add(name)
        mod = sys.modules.get(name)
        path = getattr(mod, "__file__", None)
        if mod is None or path is None:
            spec = getattr(mod, "__spec__", None)
            if name in sys.builtin_module_names or getattr(spec, "origin", None) in (
                    "built-in", "frozen"):
                continue
            raise _Unstable(f"module {name} has no source file")
        if _outside_project(path) or _fingerprinted(name):
            continue          # installed code has versions; the package, a fingerprint
        order.append(name)
        for v in vars(mod).values():
            if isinstance(v, types.ModuleType):
                # a package's submodules are its attributes once imported anywhere:
                # which are is no property of the model
                if not v.__name__.startswith(name + "."):
                    stack.append(v.__name__)
            elif isinstance(v, (types.FunctionType, type)) and isinstance(
                    getattr(v, "__module__", None), str):
                stack.append(v.__module__)
    return sorted(order)


def _describe_module(name: str, h) -> None:
    mod = sys.modules[name]
    h("module", name, _file_hash(mod.__file__))
    for k, v in vars(mod).items():      # module constants may be changed at run time
        if not k.startswith("__") and isinstance(v, _PLAIN + (tuple,)):
            try:
                h(k, _plain(v))
            except _Unstable:
                pass


def _class_attributes(cls) -> list:
    out = []
    for k, v in vars(cls).items():
        if k.startswith("__") or isinstance(v, (types.FunctionType, classmethod,
                                                staticmethod, property)):
            continue
        out.append((k, _plain(v)))
    return out


def tree_key(model, backend: str) -> str | None:
    """The key of the instance tree (see the module docstring), or None when some part of
    it has no description that is the same in every process.  Imports no sympy."""
    try:
        h = _Hasher("tree", fingerprint(), *_backend_id(backend))
        classes, modules = {}, set()
        stack = [("", model)]
        seen_types = set()
        while stack:
            path, comp = stack.pop()
            cls = type(comp)
            if cls not in seen_types:
                seen_types.add(cls)
                if "<locals>" in cls.__qualname__:
                    raise _Unstable(f"local class {cls.__qualname__}")
                for c in cls.__mro__:
                    if c is not object and c not in classes:
                        classes[c] = None
                        modules.add(c.__module__)
            mods, init = comp._mods, getattr(comp, "_init_call", ((), {}))
            # most instances carry no modification and no argument: no printing for them
            parts = [path, cls.__module__, cls.__qualname__, _plain(mods) if mods else "",
                     _plain(init) if init[0] or init[1] else ""]
            children = {id(c) for c in comp._children.values()}
            for k, v in vars(comp).items():
                # children are described as nodes; anything else, components too, here
                if k.startswith("_") or id(v) in children or (
                        isinstance(v, (list, tuple)) and v
                        and all(id(c) in children for c in v)):
                    continue
                parts.append(f"{k}={_plain(v)}")
            h("node", *parts)
            for name, child in reversed(list(comp._children.items())):
                stack.append((f"{path}.{name}" if path else name, child))
        for c in classes:
            h("class", c.__module__, c.__qualname__, *_class_attributes(c))
        for name in _module_closure(sorted(modules)):
            _describe_module(name, h)
        return h.hexdigest()
    except (_Unstable, OSError, AttributeError):
        return None


# -- the store ----------------------------------------------------------------------------------
def enabled() -> bool:
    return os.environ.get("ACAUSAL_COMPILE_CACHE", "1").strip().lower() not in (
        "0", "no", "off", "false")


def models_dir() -> str:
    from .cbackend import cache_dir
    path = os.path.join(cache_dir(), "models")
    os.makedirs(path, exist_ok=True)
    return path


def _read_index(tree: str) -> str | None:
    try:
        with open(os.path.join(models_dir(), f"tree-{tree}")) as f:
            key = f.read().strip()
    except OSError:
        return None
    return key if key.isalnum() else None


def lookup(key: str | None = None, tree: str | None = None):
    """The cached ModelCode for a flat key or a tree key (tried in that order), or None.
    Returns (ModelCode, seconds spent loading).  An unreadable entry is removed."""
    if key is None and tree is not None:
        key = _read_index(tree)
    if key is None:
        return None
    path = os.path.join(models_dir(), f"{key}.pkl")
    t0 = _time.perf_counter()
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None
    try:
        mc = pickle.loads(data)
        if not (is_dataclass(mc) and {f.name for f in fields(mc)} >= {"code", "report"}):
            raise ValueError("not a compiled model")
    except Exception:       # noqa: BLE001 - a corrupt or foreign entry: compile again
        _remove(path)
        return None
    with contextlib.suppress(OSError):
        os.utime(path)      # recently used: pruned last
    side = os.path.join(models_dir(), f"{key}.programs.pkl")
    for which, code in _codes(mc).items():
        if isinstance(code, LoadedCode):
            code._program_file = (side, which)
    return mc, _time.perf_counter() - t0


def store(key: str, mc, tree: str | None = None) -> None:
    """Write the portable form of ``mc`` under ``key`` (and the index for ``tree``),
    atomically; a cache that cannot be written is skipped, never an error."""
    try:
        root = models_dir()
        _atomic_write(os.path.join(root, f"{key}.pkl"),
                      pickle.dumps(portable(mc), protocol=pickle.HIGHEST_PROTOCOL))
        with contextlib.suppress(Exception):     # the Programs only serve FMU export
            programs = {w: getattr(c, "program", None) for w, c in _codes(mc).items()}
            _atomic_write(os.path.join(root, f"{key}.programs.pkl"),
                          pickle.dumps(programs, protocol=pickle.HIGHEST_PROTOCOL))
        if tree is not None:
            store_index(tree, key)
        _prune(os.path.dirname(root))
    except Exception:      # noqa: BLE001 - the cache saves time; it never fails a compile
        return


def store_index(tree: str, key: str) -> None:
    """Record that the tree key ``tree`` leads to the flat key ``key``."""
    try:
        _atomic_write(os.path.join(models_dir(), f"tree-{tree}"), key.encode())
    except OSError:
        return


def _atomic_write(path: str, data: bytes) -> None:
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".tmp-")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        _remove(tmp)
        raise


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.remove(path)


def _prune(root: str) -> None:
    """Remove least recently used entries and libraries until the cache fits its size."""
    limit = int(os.environ.get("ACAUSAL_CACHE_SIZE", DEFAULT_SIZE))
    items = []
    for d in (root, os.path.join(root, "models")):
        for entry in os.scandir(d):
            if entry.name.endswith((".so", ".pkl")) or entry.name.startswith("tree-"):
                try:
                    st = entry.stat()
                except OSError:
                    continue
                items.append((st.st_mtime, entry.path, st.st_size))
    total = sum(s for _, _, s in items)
    for _, p, size in sorted(items):
        if total <= limit:
            break
        _remove(p)          # a library still named by an entry is rebuilt on load
        total -= size
