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
  -- variables and all their attributes, parameters and values, every equation printed
  exactly (:class:`~acausal.compiler.algebra.symbolic.ExactText`: its source as written, and its
  residual where flattening did not make it from that source),
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
import importlib.util
import marshal
import math
import os
import pickle
import tempfile
import time as _time
from dataclasses import fields, is_dataclass, replace

import numpy as np

from .keys import fingerprint, flat_key, tree_key
from ..backends.lazycode import GeneratedModule, ModuleSource, install_array_code

__all__ = ["LoadedCode", "ParameterFunction", "portable", "load_notes", "flat_key",
           "tree_key", "fingerprint", "lookup", "store", "store_index", "enabled",
           "models_dir"]

DEFAULT_SIZE = 512 * 2**20
_MAGIC = importlib.util.MAGIC_NUMBER


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
    # the namespace the generated Python expects (acausal.compiler.backends.codegen.python_code)
    namespace = {"math": math, "_list": _list}
    exec(code, namespace)
    return namespace


class LoadedCode(ModuleSource):
    """A generated code without its Program: the functions executed from ``source``
    when first called (:mod:`acausal.compiler.backends.lazycode`), and the C library behind them
    when ``c`` is given.  Reads like a
    :class:`~acausal.compiler.backends.codegen.GeneratedCode` (``program`` is None) and pickles
    as its sources (with the bytecode of the Python source, used when the receiving
    Python has the same bytecode version; a source behind a C library that never ran
    goes without), so it is rebuilt, not unpickled, in the receiving process.  A code loaded from the compile cache finds its Program in the
    entry's side file when something asks for it (an FMU export prints its C from it):
    only then are the Program and sympy loaded.

    In a compile cache entry (:func:`store`) a Python source that is only the fallback
    of a C library or of array code and was never printed is not printed for it either:
    the entry keeps the names of its functions, and the source is printed from the
    Program in the side file when first needed (a failing statement to name, a call the
    C library could not finish).  An entry whose side file is gone is not loaded
    (:func:`lookup`)."""

    _in_cache_entry = False     # pickled into a cache entry, which has the side file

    @property
    def program(self):
        return self._place.get()

    @program.setter
    def program(self, value) -> None:
        place = self.__dict__.get("_place")
        if place is None:
            self._place = _ProgramPlace(value)
        else:               # the place its module's printer reads stays the same
            place.program = value

    @property
    def _program_file(self):
        return self._place.file

    @_program_file.setter
    def _program_file(self, where) -> None:
        """(path of the side file, which code), set by :func:`lookup`."""
        self._place.file = where


    def __init__(self, source, jac_rows, jac_cols, n_rows, n_roots, names=None, c=None,
                 bytecode=None, array_source=None):
        self.bytecode = bytecode if bytecode and bytecode[:len(_MAGIC)] == _MAGIC else None
        self.program = None
        if source is None:          # printed from the Program of the entry's side file
            source = self._place.python_source
        # executed when a function is first called: behind a C library, rarely
        self.module = module = GeneratedModule(source, self.bytecode, names=names)
        fn = module.function
        self.residual, self.jacobian, self.roots = fn("residual"), fn("jacobian"), fn("roots")
        self.scales, self.expand = fn("scales"), fn("expand")
        self.jac_rows = np.asarray(jac_rows, dtype=np.int64)
        self.jac_cols = np.asarray(jac_cols, dtype=np.int64)
        self.n_rows, self.n_roots = int(n_rows), int(n_roots)
        self.backend = "numpy"
        self.load_note = None
        if array_source is not None:
            install_array_code(self, array_source)
        if c is not None:
            from ...errors import BackendError
            from ..backends.cbackend import reattach
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
                             if k not in ("program", "_place")})
        out.program = None
        out.load_note = None
        out.bytecode = None
        return out

    def __reduce__(self):
        c = None
        if self.backend == "c":
            c = {"library": self.library, "source": self.c_source, "layout": self.c_layout}
        bytecode = self._bytes()
        module = self.module
        source = module.source if module.printed or not self._in_cache_entry else None
        return (LoadedCode, (source, self.jac_rows, self.jac_cols, self.n_rows,
                             self.n_roots, module.names, c, bytecode,
                             getattr(self, "array_source", None)))

    def _fallback_only(self) -> bool:
        # behind a C library or array code the scalar functions are the fallback
        return self.backend == "c" or bool(getattr(self, "array_source", None))

    def _bytes(self) -> bytes | None:
        """The bytecode an entry keeps: that of the compile which ran the functions
        (compiled now for the numpy backend, whose functions will run); a source behind
        a C library that was never called is stored without, and compiled where needed."""
        if getattr(self, "bytecode", None) is None:      # compiled once, then kept
            module = self.module
            if module.compiled or not self._fallback_only():
                self.bytecode = module.bytecode()
        return self.bytecode


class _ProgramPlace:
    """Where a :class:`LoadedCode`'s Program is: in memory, in a cache entry's side file
    (loaded on first use), or nowhere; and the printer of its Python source from it
    (the code's module holds this, not the code: no reference cycle)."""

    __slots__ = ("program", "file")

    def __init__(self, program=None):
        self.program, self.file = program, None

    def get(self):
        if self.program is None and self.file is not None:
            self.program = _load_program(*self.file)
            self.file = None
        return self.program

    def python_source(self) -> str:
        """The Python source, printed from the Program as the code generator printed
        it when the model was compiled (:func:`acausal.compiler.backends.codegen.python_source`)."""
        from ...errors import BackendError
        from ..backends.codegen import python_source
        prog = self.get()
        if prog is None:
            raise BackendError("the Python functions of this model are printed from its "
                               "compile cache entry's side file, which is gone; compile "
                               "the model again")
        return python_source(prog)


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
            **({"whens": mc.whens.code} if mc.whens is not None else {}),
            **({"delays": mc.delays.code} if mc.delays is not None else {})}


def _load_program(path: str, which: str):
    """The Program of one code from an entry's side file, or None (pruned, unreadable)."""
    try:
        with open(path, "rb") as f:
            return pickle.load(f).get(which)
    except Exception:      # noqa: BLE001 - without it only what needs a Program fails
        return None


def portable(mc, entry: bool = False):
    """``mc`` with every generated code as a :class:`LoadedCode`: picklable, and loadable
    without sympy.  The functions themselves are shared, not rebuilt.  ``entry``: for a
    compile cache entry, whose side file keeps the Programs (a fallback source not
    printed yet is then left to be printed from there)."""
    def loaded(code):
        out = LoadedCode.of(code)
        if entry and out is not code:
            out._in_cache_entry = True
        return out

    out = replace(mc, code=loaded(mc.code),
                  initial=replace(mc.initial, code=loaded(mc.initial.code)),
                  meta=dict(mc.meta))
    if mc.whens is not None:
        out.whens = replace(mc.whens, code=loaded(mc.whens.code))
    if mc.delays is not None:
        out.delays = replace(mc.delays, code=loaded(mc.delays.code))
    return out


def load_notes(mc) -> list:
    """What went differently when the codes of ``mc`` were loaded: a C library that could
    be neither loaded nor rebuilt makes the numpy backend run the whole model."""
    codes = [mc.code, mc.initial.code] + ([mc.whens.code] if mc.whens is not None else []) \
        + ([mc.delays.code] if mc.delays is not None else [])
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


# -- the store ----------------------------------------------------------------------------------
def enabled() -> bool:
    return os.environ.get("ACAUSAL_COMPILE_CACHE", "1").strip().lower() not in (
        "0", "no", "off", "false")


def models_dir() -> str:
    from ..backends.cbackend import cache_dir
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
    Returns (ModelCode, seconds spent loading).  An unreadable entry is removed.
    Entries this process is still storing beside its work (:mod:`sidejobs`) are
    waited for first."""
    from ..sidejobs import settle
    settle()
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
    side = _side_file(path)
    codes = _codes(mc)
    if not all(c.module.printed for c in codes.values()) and not os.path.exists(side):
        _remove(path)      # a source to be printed from the side file: compile again
        return None
    with contextlib.suppress(OSError):
        os.utime(path)      # recently used: pruned last
    for which, code in codes.items():
        if isinstance(code, LoadedCode):
            code._program_file = (side, which)
    return mc, _time.perf_counter() - t0


def store(key: str, mc, tree: str | None = None) -> None:
    """Write the portable form of ``mc`` under ``key`` (and the index for ``tree``),
    atomically; a cache that cannot be written is skipped, never an error."""
    try:
        root = models_dir()
        path = os.path.join(root, f"{key}.pkl")
        # the side file first: an entry whose fallback sources are printed from its
        # Programs is only found with them (a concurrent lookup finds both or neither)
        programs = {w: getattr(c, "program", None) for w, c in _codes(mc).items()}
        try:
            _atomic_write(_side_file(path),
                          pickle.dumps(programs, protocol=pickle.HIGHEST_PROTOCOL))
            sided = True
        except Exception:      # noqa: BLE001 - then the entry keeps every source printed
            sided = False
        _atomic_write(path, pickle.dumps(portable(mc, entry=sided),
                                         protocol=pickle.HIGHEST_PROTOCOL))
        if tree is not None:
            store_index(tree, key)
        _prune(os.path.dirname(root))
    except Exception:      # noqa: BLE001 - the cache saves time; it never fails a compile
        return


def _side_file(path: str) -> str:
    """The side file of the entry ``path``: the Programs of its codes (FMU export, and
    the Python sources not printed at compile time, :class:`LoadedCode`)."""
    return path[:-len(".pkl")] + ".programs.pkl"


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
    """Remove least recently used entries and libraries until the cache fits its size;
    an entry's side file goes with it (and counts with it)."""
    limit = int(os.environ.get("ACAUSAL_CACHE_SIZE", DEFAULT_SIZE))
    items = []
    for d in (root, os.path.join(root, "models")):
        for entry in os.scandir(d):
            name = entry.name
            if name.endswith(".programs.pkl"):
                continue
            if name.endswith((".so", ".pkl")) or name.startswith("tree-"):
                try:
                    st = entry.stat()
                except OSError:
                    continue
                size, paths = st.st_size, [entry.path]
                if name.endswith(".pkl"):
                    paths.append(_side_file(entry.path))
                    with contextlib.suppress(OSError):
                        size += os.stat(paths[1]).st_size
                items.append((st.st_mtime, paths, size))
    total = sum(s for _, _, s in items)
    for _, paths, size in sorted(items):
        if total <= limit:
            break
        for p in paths:     # a library still named by an entry is rebuilt on load
            _remove(p)
        total -= size
