"""Code generation: the language-independent :class:`Program`, and its printers -- the
scalar Python module (compiled when first called), numpy array code for large models,
C and looped C compiled into a library -- with what puts a built library behind a
model's functions.  Names are imported on first use (PEP 562): a model loaded from the
compile cache attaches its library without the printers, which need sympy (0.3 s)."""
from ... import _lazy_exports

__all__ = ["Program", "GeneratedCode", "generate", "python_code", "Emitter", "use_array_code",
           "c_source", "prepare", "bind", "BACKENDS", "attach", "reattach", "CFunction",
           "GeneratedModule", "ModuleSource", "ParameterFunction", "parameter_functions"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".codegen": ("Program", "GeneratedCode", "generate", "python_code"),
    ".emit": ("Emitter",),
    ".arraycode": ("use_array_code",),
    ".cbackend": ("c_source", "prepare", "bind", "BACKENDS"),
    ".clibrary": ("attach", "reattach", "CFunction"),
    ".lazycode": ("GeneratedModule", "ModuleSource", "ParameterFunction"),
    ".parametric": ("parameter_functions",),
})
