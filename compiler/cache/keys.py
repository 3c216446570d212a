"""The keys of the compile cache (:mod:`acausal.compiler.cache.entries`): the exact key of a flat
model, the key of an instance tree taken before flattening, and the fingerprint of the
compiler's own sources.  What each key covers, and why the flat key is the default, is in
the docstring of :mod:`acausal.compiler.cache.entries`.
"""
from __future__ import annotations

import hashlib
import math
import os
import sys
import time as _time
import types
from importlib.util import find_spec

import numpy as np

from ... import native
from ...components.component import Component

__all__ = ["fingerprint", "flat_key", "tree_key"]

_FORMAT = 1                  # of the cache entries: a new layout changes every key


# -- keys -------------------------------------------------------------------------------------
class _Hasher:
    """The SHA-256 of records of items: each item followed by \x1f, each record by
    \x1e.  The records are joined and hashed once, at :meth:`hexdigest` (a record is
    short, and encoding and hashing each one cost more than the text itself)."""

    def __init__(self, *head):
        self.parts = []
        self(*head)

    def __call__(self, *items) -> None:
        # one string a record: a model's key has some 40 000 records
        self.parts.append("\x1f".join([x if type(x) is str else str(x) for x in items])
                          + "\x1f\x1e" if items else "\x1e")

    def hexdigest(self) -> str:
        text = "".join(self.parts)
        return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()[:40]


_NOT_COMPILER = {"tests", "benchmarks", "docs", "__pycache__"}
# what determines a ModelCode: the passes, the component classes and their library, the
# functions models call; not the runtime, which reads a ModelCode afresh on every load
_COMPILER_PACKAGES = ("compiler", "components", "ports", "library", "native")
_COMPILER_FILES = ("__init__.py", "errors.py", "functions.py")


_TAKEN = []        # the fingerprint, once taken in this process


def fingerprint() -> str:
    """The compiler's identity: the sources that determine a ModelCode (the compiler,
    the components, ports and model library, the model functions) and the versions of
    what it runs on.  Taken once a process, at its first compile: it names the code this
    process runs, which an edit of the sources made while it runs does not change (with
    the files read again, such a process stored what its old code compiled under the
    new code's name, and a fresh process then loaded it)."""
    if not _TAKEN:
        _TAKEN.append(_sources_fingerprint())
    return _TAKEN[0]


def _sources_fingerprint() -> str:
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
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
    return (backend, native.find_compiler())


def flat_key(flat, backend: str) -> str | None:
    """The SHA-256 of everything of the flat model the compiler reads (see the module
    docstring), the backend and the compiler's :func:`fingerprint`; None when a value
    in it has no description that is the same in every process."""
    try:
        return _flat_key(flat, backend)
    except _Unstable:
        return None


def _flat_key(flat, backend: str) -> str:
    # sympy and what needs it are imported in the flat key's functions only: the tree
    # key is taken without sympy (0.3 s to import), which a model found so never loads
    from ...components.symbols import Equation
    ex = _key_text()

    def source(e):
        src = e.source
        if isinstance(src, str):
            return src
        if isinstance(src, dict):   # a sum's terms: hashed below, as made
            return ""
        if isinstance(src, Equation):
            return f"{ex(src.lhs)} = {ex(src.rhs)}"
        return ex(src)

    h = _Hasher("flat", fingerprint(), *_backend_id(backend), flat.name)
    attrs = {}     # id -> reference: instances of a class share their declared attributes
    # after its own record, a variable's or parameter's symbol is written as \x1c and
    # its number in these records (which the key holds in order, with the symbol's whole
    # text): the equations name each symbol some three times
    for k, v in enumerate(flat.variables):
        text = attrs.get(id(v.attrs))
        if text is None:
            text = attrs[id(v.attrs)] = ex.ref(repr(v.attrs))
        h("v", v.name, ex(v.symbol), text, v.component, v.component_class,
          v.kind, ex.ref(v.hint))
        ex.memo[v.symbol] = f"\x1c{k}"
    n = len(flat.variables)
    for k, p in enumerate(flat.parameters):
        h("p", p.name, ex(p.symbol), ex(p.value), p.unit, ex.ref(p.description),
          p.component, p.component_class, ex(p.min), ex(p.max), p.fixed)
        ex.memo[p.symbol] = f"\x1c{n + k}"
    for eqs, tag in ((flat.equations, "e"), (flat.initial_equations, "i")):
        for e in eqs:
            # the residual of an equation written as Eq(lhs, rhs) is made from it by
            # flattening (whose source the fingerprint covers) and the parameters and
            # derivatives hashed here, so its exact text says nothing more; a residual
            # made otherwise (a connection set's sum, an equation read back from its
            # text) is hashed itself
            made = "" if isinstance(e.source, Equation) else ex(e.residual) \
                if e.unmade is None else "+-(" + ",".join(
                    ex(q) + ("+" if c == 1 else "-") for q, c in e.unmade.items()) + ")"
            # a connection set's equations are each located by all its ports: a long
            # text, written once (a ground of 1000 capacitors: 1001 equations, 10 kB each)
            where = e.component if len(e.component) < 64 else ex.ref(e.component)
            h(tag, e.kind, made, source(e), where, e.component_class, e.label)
    for x, d in flat.derivatives.items():
        h("d", ex(x), ex(d))
    for w in flat.whens:
        h("w", ex(w.condition), w.origin, w.origin_class,
          *[f"{type(a).__name__}:{ex(a.variable)}:={ex(a.value)}" for a in w.actions])
    h("z", *flat.structural_zeros)
    h("ports", *map(repr, flat.ports))
    h("components", *map(repr, flat.components.items()))
    h("defs", *ex.defs)
    return h.hexdigest()


def _key_text():
    """``ExactText(_plain)`` with long texts that repeat (a class's name, a symbol's
    assumptions, a variable's declared attributes) written once: each is replaced by a
    reference, ``\x1d`` and its number in order of first use, and the texts themselves
    are hashed at the end (``defs``).  A model's key text was 28 MB, three quarters of
    it such repetitions, and hashing it a quarter of the key's time.  The expressions are
    walked by recursion up to a depth of 100."""
    import sympy as sp

    from ...components.realsymbol import SYMBOLS
    from ..algebra.symbolic import ExactText

    class KeyText(ExactText):
        facts: dict = {}

        def __init__(self, plain):
            super().__init__(plain)
            self.refs = {}       # a long text -> its reference
            self.defs = []       # the long texts, in the order of their first use

        def ref(self, text: str) -> str:
            if not text:
                return text
            out = self.refs.get(text)
            if out is None:
                out = self.refs[text] = f"\x1d{len(self.defs)}"
                self.defs.append(text)
            return out

        def _name(self, node) -> str:
            t = type(node)
            name = self.names.get(t)
            if name is None:
                name = self.names[t] = self.ref(f"{t.__module__}.{t.__name__}")
            return name

        def __call__(self, e) -> str:
            if not isinstance(e, sp.Basic):
                return self.plain(e)
            out = self.memo.get(e)
            if out is not None:
                return out
            try:
                return self._text(e, 0)
            except RecursionError:      # a very deep expression: the iterative walk
                return super().__call__(e)

        def _text(self, e, depth: int) -> str:
            """The same text as ExactText's walk, by recursion (models' expressions are
            shallow, and a call per node is cheaper than the walk's stack entries)."""
            out = self.memo.get(e)
            if out is None:
                args = e.args
                if not args:
                    out = self._atom(e)
                else:
                    if depth > 100:
                        raise RecursionError
                    out = self._name(e) + "(" + ",".join(
                        [self._text(a, depth + 1) for a in args]) + ")"
                self.memo[e] = out
            return out

        def _atom(self, node) -> str:
            if type(node) not in SYMBOLS:
                return super()._atom(node)
            key = tuple(sorted(node.assumptions0.items()))
            facts = self.facts.get(key)
            if facts is None:
                facts = ",".join(f"{k}={v}" for k, v in sorted(dict(key).items()))
                self.facts[key] = facts
            return f"{self._name(node)}[{node.name};{self.ref(facts)}]"
    return KeyText(_plain)


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


_INSTALLED = ("site-packages", "dist-packages")


def _where(path: str) -> str:
    """``"installed"`` (a package in site-packages), ``"python"`` (the standard
    library, versioned with the interpreter) or ``"project"`` (anything else)."""
    path = os.path.abspath(path)
    if any(part in _INSTALLED for part in path.split(os.sep)):
        return "installed"
    prefixes = {sys.prefix, sys.base_prefix, sys.exec_prefix}
    if any(path.startswith(os.path.abspath(p) + os.sep) for p in prefixes):
        return "python"
    return "project"


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
        if x.dtype == object:      # its bytes are addresses: describe the elements
            return f"array(object,{x.shape},{_plain(x.tolist(), depth + 1)})"
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


def _module_closure(modules: list) -> tuple[list, list]:
    """(modules, packages): the modules that ``modules`` (those of the model's classes)
    reference through their globals, transitively -- the code an ``equations()`` can
    call -- whose sources the key covers; and the installed packages outside them that
    they reach, which the key covers by their versions.

    Covered by their sources: the project's modules and every module of an installed
    package that one of the model's classes comes from (a component library in
    site-packages).  Not followed: the standard library (the interpreter's version is in
    the key), acausal's own compiler and library (its :func:`fingerprint`), and other
    installed packages (their version: a change inside them that keeps the version is
    not seen)."""
    own = {m.split(".")[0] for m in modules}
    seen, order, stack, packages = set(), [], list(modules), set()
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
        where = _where(path)
        if where == "python" or _fingerprinted(name):
            continue          # versioned with the interpreter; the package, a fingerprint
        if where == "installed" and name.split(".")[0] not in own:
            packages.add(name.split(".")[0])
            continue
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
    return sorted(order), sorted(packages)


def _describe_package(name: str, h) -> None:
    """An installed package by its version (or its ``__init__``'s source)."""
    mod = sys.modules.get(name)
    version = getattr(mod, "__version__", None)
    if not isinstance(version, str):
        path = getattr(mod, "__file__", None)
        version = _file_hash(path) if path else "unknown"
    h("package", name, version)


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
        described, packages = _module_closure(sorted(modules))
        for name in described:
            _describe_module(name, h)
        for name in packages:
            _describe_package(name, h)
        return h.hexdigest()
    except (_Unstable, OSError, AttributeError):
        return None
