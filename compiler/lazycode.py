"""Generated Python source, compiled when one of its functions is first called.

Compiling the source of a large model is a large part of its build (CPython compiles
some 40 000 lines a second), and with the C backend the Python functions are only the
fallback for a call whose output is not finite: most runs never call them.  So the
source is compiled, in one piece (a traceback's line number is its line in the whole
source, :mod:`acausal.runtime.diagnostics`), by the first call of any of its functions,
and then kept.  Nothing here imports sympy: a model loaded from the compile cache uses
it too.
"""
from __future__ import annotations

import marshal
import math
from importlib.util import MAGIC_NUMBER as _MAGIC

__all__ = ["GeneratedModule", "GeneratedFunction", "FILENAME"]

FILENAME = "<acausal generated>"


def _list(a):
    return a.tolist() if hasattr(a, "tolist") else list(a)


class GeneratedModule:
    """``source`` (and, when given, the bytecode it was compiled to by a Python of this
    bytecode version), executed on first use."""

    def __init__(self, source: str, bytecode: bytes | None = None):
        self.source = source
        self.code_object = None
        self._bytecode = bytecode
        self._namespace = None

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
                code = compile(self.source, FILENAME, "exec")
            # the names the generated functions read (acausal.compiler.codegen.python_code)
            namespace = {"math": math, "_list": _list}
            exec(code, namespace)
            self.code_object, self._namespace = code, namespace
        return self._namespace

    def bytecode(self) -> bytes:
        """The marshalled bytecode (compiling the source if that has not happened)."""
        self.namespace()
        return _MAGIC + marshal.dumps(self.code_object)

    def function(self, name: str):
        """The function ``name`` of the source, or None when the source defines none."""
        if f"\ndef {name}(" not in self.source:
            return None
        return GeneratedFunction(self, name)


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
