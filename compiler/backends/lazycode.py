"""Generated Python source, compiled when one of its functions is first called.

Compiling the source of a large model is a large part of its build (CPython compiles
some 40 000 lines a second), and with the C backend (or the numpy backend's array code)
the Python functions are only the fallback for a call whose output is not finite: most
runs never call them.  So the source is printed when first needed
(:func:`acausal.compiler.backends.codegen.python_code`), and compiled, in one piece (a
traceback's line number is its line in the whole source,
:mod:`acausal.runtime.diagnostics`), by the first call of any of its functions, and
then kept.  Nothing here imports sympy: a model loaded from the compile cache uses
it too.
"""
from __future__ import annotations

import marshal
import math
from importlib.util import MAGIC_NUMBER as _MAGIC

import numpy as np

__all__ = ["GeneratedModule", "GeneratedFunction", "FILENAME", "ArrayFunction",
           "install_array_code", "ModuleSource"]

FILENAME = "<acausal generated>"
ARRAY_FILENAME = "<acausal arrays>"


def _list(a):
    return a.tolist() if hasattr(a, "tolist") else list(a)


class GeneratedModule:
    """``source`` (and, when given, the bytecode it was compiled to by a Python of this
    bytecode version), executed on first use.  ``source`` may also be a function of no
    arguments that prints it, called when the text is first needed (to compile it, or
    to read a failing line); ``names`` then lists the functions it defines."""

    def __init__(self, source, bytecode: bytes | None = None, filename: str = FILENAME,
                 names=None):
        printed = isinstance(source, str)
        self._source = source if printed else None
        self._printer = None if printed else source
        self.names = tuple(names) if names is not None else None
        self.filename = filename
        self.code_object = None
        self._bytecode = bytecode
        self._namespace = None

    @property
    def source(self) -> str:
        source = self._source
        if source is None:
            printer = self._printer
            if printer is None:         # printed by another thread meanwhile
                return self._source
            source = self._source = printer()
            self._printer = None
        return source

    @property
    def printed(self) -> bool:
        """Whether the source text exists yet (see the class docstring)."""
        return self._source is not None

    @property
    def compiled(self) -> bool:
        return self._namespace is not None

    def namespace(self) -> dict:
        if self._namespace is None:
            code = None
            data = self._bytecode
            if data is not None and data[:len(_MAGIC)] == _MAGIC:
                try:
                    code = marshal.loads(data[len(_MAGIC):])
                except (ValueError, EOFError, TypeError):
                    code = None
            if code is None:
                code = compile(self.source, self.filename, "exec")
            # the names the generated functions read (acausal.compiler.backends.codegen.python_code)
            namespace = {"math": math, "_list": _list}
            exec(code, namespace)
            self.code_object, self._namespace = code, namespace
        return self._namespace

    def bytecode(self) -> bytes:
        """The marshalled bytecode (compiling the source if that has not happened)."""
        self.namespace()
        return _MAGIC + marshal.dumps(self.code_object)

    def defines(self, name: str) -> bool:
        if self.names is not None:
            return name in self.names
        return f"\ndef {name}(" in self.source

    def function(self, name: str):
        """The function ``name`` of the source, or None when the source defines none."""
        if not self.defines(name):
            return None
        return GeneratedFunction(self, name)


class ModuleSource:
    """``source`` and ``digest`` of a generated code whose functions live in
    ``self.module`` (a :class:`GeneratedModule`): read, and printed if need be, on
    demand."""

    @property
    def source(self) -> str:
        return self.module.source

    @property
    def digest(self) -> str:
        import hashlib
        return hashlib.sha1(self.source.encode()).hexdigest()[:16]


class GeneratedFunction:
    """A function of a :class:`GeneratedModule`, ``f(t, y, p, m, out) -> out``."""

    __slots__ = ("module", "name", "fn")

    def __init__(self, module: GeneratedModule, name: str):
        self.module, self.name, self.fn = module, name, None

    def __call__(self, *args):
        fn = self.fn
        if fn is None:
            fn = self.fn = self.module.namespace()[self.name]
        return fn(*args)

    def __repr__(self) -> str:
        return f"<generated function {self.name}>"


class ArrayFunction:
    """A function of an array module (:mod:`acausal.compiler.backends.arraycode`) with the
    contract f(t, y, p, m, out) -> out; an output that is not finite is computed again
    by the scalar function ``fallback``, which raises what the runtime reports with the
    failing equation."""

    __slots__ = ("module", "name", "fallback", "fn")

    def __init__(self, module: GeneratedModule, name: str, fallback):
        self.module, self.name, self.fallback, self.fn = module, name, fallback, None

    def __call__(self, t, y, p, m, out):
        fn = self.fn
        if fn is None:
            fn = self.fn = self.module.namespace()[self.name]
        fn(t, y, p, m, out)
        if not np.isfinite(out).all():
            return self.fallback(t, y, p, m, out)
        return out

    def __repr__(self) -> str:
        return f"<array function {self.name}>"


def install_array_code(code, source: str) -> None:
    """Put the functions of the array module ``source`` in front of the scalar functions
    of ``code`` (a GeneratedCode or a model loaded from the cache); compiled on first
    call, like the scalar module."""
    module = GeneratedModule(source, filename=ARRAY_FILENAME)
    for name in ("residual", "jacobian", "roots", "scales", "expand"):
        scalar = getattr(code, name, None)
        if scalar is not None and f"\ndef {name}(" in source:
            setattr(code, name, ArrayFunction(module, name, scalar))
    code.array_source = source

