"""The compiler: a model instance to generated code and name maps.

:func:`compile_model` runs the passes of :data:`PASSES` (``pipeline.py``) in order.  The
rooms: ``frontend/`` (the language to the flat model), ``algebra/`` (the sympy side),
``structure/`` (integers only), ``index/`` (numeric checks of structural decisions),
``backends/`` (the generated code) and ``cache/``; the flat model's types
(``flatmodel.py``), the form the solver sees (``assemble.py``), the product
(``modelcode.py``) and the index report (``report.py``).  Names are imported on first
use (PEP 562): a model found in the compile cache loads neither sympy nor the passes.
"""
from .. import _lazy_exports

__all__ = ["compile_model", "PASSES", "Pass", "Compilation", "ModelCode", "IndexReport",
           "FlatModel", "FlatVariable", "FlatParameter", "FlatEquation"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".pipeline": ("compile_model", "PASSES", "Pass", "Compilation"),
    ".modelcode": ("ModelCode",),
    ".report": ("IndexReport",),
    ".flatmodel": ("FlatModel", "FlatVariable", "FlatParameter", "FlatEquation"),
}, submodules=("frontend", "algebra", "structure", "index", "backends", "cache"))
