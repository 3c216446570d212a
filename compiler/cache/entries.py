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
  the modules they reference (with their plain constants), installed component
  libraries included; other installed packages they reach by their versions.  ``<cache>/models/tree-<key>`` names the flat key it led
  to.  No tree key (only the flat one) when a part has no description that is the same
  in every process: a class without a source file (a notebook, ``python -c``), a local
  class, a value whose repr is an address.  Not seen by a tree key: equations reading
  mutable state elsewhere (a dict filled at run time, a file, the environment): that is
  why the default is the flat key, which is exact.

The fingerprint hashes the sources that determine a ModelCode (compiler, components,
ports, the model library, the model functions) and the versions of Python, numpy and
sympy (sympy's release file, found without importing it).  It is taken once a process, at
its first compile, so that it names the code the process runs: a source edited while the
process runs changes the name only for processes started after the edit.

Writes are atomic (temporary file, then ``os.replace``): processes compiling at once each
find a whole entry or none.  Every entry, side file and index is sealed with the SHA-256
of its bytes, and every C library has its checksum beside it, checked before anything is
unpickled or loaded; a damaged one is removed, with one line saying so, and compiled
again.  The cache directory is private, and a file that is not this user's is not read
(:mod:`acausal.native.cachefiles`, which also skips a cache that cannot be created or
written, with one warning).  The cache is pruned to ``$ACAUSAL_CACHE_SIZE`` bytes
(default 512 MiB), least recently used entries and C libraries first;
``$ACAUSAL_COMPILE_CACHE=0`` switches the entries off.
"""
from __future__ import annotations

import contextlib
import importlib.util
import marshal
import math
import os
import pickle
import time as _time
from dataclasses import fields, is_dataclass, replace

import numpy as np

from ..backends.clibrary import reattach
from ..backends.lazycode import GeneratedModule, ModuleSource, install_array_code
from .keys import fingerprint, flat_key, tree_key
from ...errors import BackendError
from ...native import cachefiles as files

__all__ = ["from_cache", "find_by_tree", "LoadedCode", "portable", "load_notes", "flat_key",
           "tree_key", "fingerprint", "lookup", "store", "store_index", "enabled",
           "models_dir"]

DEFAULT_SIZE = files.DEFAULT_SIZE
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
        # imported here: the printer needs sympy, which loading a model does not
        from ..backends.codegen import python_source
        prog = self.get()
        if prog is None:
            raise BackendError("the Python functions of this model are printed from its "
                               "compile cache entry's side file, which is gone; compile "
                               "the model again")
        return python_source(prog)


def _codes(mc) -> dict:
    return {"code": mc.code, "initial": mc.initial.code,
            **({"whens": mc.whens.code} if mc.whens is not None else {}),
            **({"delays": mc.delays.code} if mc.delays is not None else {})}


def _load_program(path: str, which: str):
    """The Program of one code from an entry's side file, or None (pruned, damaged)."""
    data = files.read_sealed(path, "side file")
    if data is None:
        return None
    try:
        return pickle.loads(data).get(which)
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
    """Whether models are kept in the compile cache (``$ACAUSAL_COMPILE_CACHE``); a
    malformed ``$ACAUSAL_CACHE_SIZE`` is an error here, before anything is compiled."""
    if os.environ.get("ACAUSAL_COMPILE_CACHE", "1").strip().lower() in (
            "0", "no", "off", "false"):
        return False
    files.size_limit()
    return True


def models_dir() -> str | None:
    """``<cache>/models``, or None when the cache cannot be used (warned once,
    :mod:`acausal.native.cachefiles`)."""
    return files.subdir("models")


def _read_index(tree: str) -> str | None:
    """The flat key the tree key ``tree`` leads to, from its sealed index file (which
    names the tree key it was written for: an index copied from another is refused)."""
    where = models_dir()
    data = None if where is None else files.read_sealed(
        os.path.join(where, f"tree-{tree}"), "index")
    if data is None:
        return None
    named, _, key = data.decode("ascii", "replace").partition("\n")
    if named != tree or not key.isalnum():
        files.discard(os.path.join(where, f"tree-{tree}"), "index", "names another tree key")
        return None
    return key


def lookup(key: str | None = None, tree: str | None = None):
    """The cached ModelCode for a flat key or a tree key (tried in that order), or None.
    Returns (ModelCode, seconds spent loading).  An entry is unpickled only when its
    checksum holds (a damaged one is removed, with one line saying so, and compiled
    again)."""
    if key is None and tree is not None:
        key = _read_index(tree)
    where = models_dir() if key is not None else None
    if where is None:
        return None
    path = os.path.join(where, f"{key}.pkl")
    t0 = _time.perf_counter()
    data = files.read_sealed(path)
    if data is None:
        return None
    try:
        mc = pickle.loads(data)
        if not (is_dataclass(mc) and {f.name for f in fields(mc)} >= {"code", "report"}):
            raise ValueError("not a compiled model")
    except Exception:       # noqa: BLE001 - a foreign entry (whole, but not ours): compile again
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


def from_cache(found, seconds: float, how: str):
    """The ModelCode of a ``lookup`` result, its report noting that it came from the
    cache (found by ``how``) and the ``seconds`` the look-up took."""
    mc, _ = found
    report = mc.report
    report.timings["cache_lookup"] = seconds
    report.notes += load_notes(mc)
    report.notes.append(f"came from the compile cache (found by {how}, loaded in "
                        f"{seconds * 1e3:.1f} ms); the other timings are those of the "
                        "original compile")
    return mc


def find_by_tree(model, backend: str) -> tuple:
    """(ModelCode or None, tree key): the model found in the cache by its instance tree
    (:func:`~acausal.compiler.cache.keys.tree_key`), without flattening or sympy."""
    t0 = _time.perf_counter()
    tree = tree_key(model, backend)
    found = lookup(tree=tree) if tree is not None else None
    if found is None:
        return None, tree
    model._bind("")     # the instance named as a compile leaves it
    return from_cache(found, _time.perf_counter() - t0, "its instance tree"), tree


def store(key: str, mc, tree: str | None = None) -> None:
    """Write the portable form of ``mc`` under ``key`` (and the index for ``tree``),
    sealed (:func:`acausal.native.cachefiles.seal`) and atomically; a cache that
    cannot be written is skipped with one warning, never an error."""
    root = models_dir()
    if root is None:
        return
    try:
        path = os.path.join(root, f"{key}.pkl")
        # the side file first: an entry whose fallback sources are printed from its
        # Programs is only found with them (a concurrent lookup finds both or neither)
        programs = {w: getattr(c, "program", None) for w, c in _codes(mc).items()}
        try:
            sided = files.write_sealed(_side_file(path), pickle.dumps(
                programs, protocol=pickle.HIGHEST_PROTOCOL))
        except Exception:      # noqa: BLE001 - then the entry keeps every source printed
            sided = False
        if not files.write_sealed(path, pickle.dumps(portable(mc, entry=sided),
                                                     protocol=pickle.HIGHEST_PROTOCOL)):
            return
        if tree is not None:
            store_index(tree, key)
        files.prune(os.path.dirname(root))
    except Exception:      # noqa: BLE001 - the cache saves time; it never fails a compile
        return


def _side_file(path: str) -> str:
    """The side file of the entry ``path``: the Programs of its codes (FMU export, and
    the Python sources not printed at compile time, :class:`LoadedCode`)."""
    return path[:-len(".pkl")] + ".programs.pkl"


def store_index(tree: str, key: str) -> None:
    """Record that the tree key ``tree`` leads to the flat key ``key``."""
    where = models_dir()
    if where is not None:
        files.write_sealed(os.path.join(where, f"tree-{tree}"), f"{tree}\n{key}".encode())


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.remove(path)


def _prune(root: str) -> None:
    """:func:`acausal.native.cachefiles.prune`."""
    files.prune(root)
