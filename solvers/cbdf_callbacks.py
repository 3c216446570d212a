"""A model's generated numpy code behind the compiled step loop's function pointers.

``cbdf.c`` calls a compiled model's residual, Jacobian values and zero-crossing
functions through pointers with the generated C's contract,

    int f(double t, const double *y, const double *p, const double *m, double *out,
          double *w)

(:mod:`acausal.compiler.backends.cbackend`).  A model on the numpy backend gives the loop ctypes
callbacks of that contract around its generated functions, so it runs in the same
compiled loop as the C backend -- predictor, corrector with the stored LU, error test,
step and order control, the sparse LU of a large system -- and Python is entered only
for the functions themselves.  It is the arrangement of IDA with a Python residual.

Why: on a large model the numpy functions are a few array operations each
(:mod:`acausal.compiler.backends.arraycode`), and the Python loop's own work per step (a few
dozen numpy calls on vectors of the model's size) costs more than they do; on a small
model the loop's interpreter overhead is most of a step.  Measured in
``benchmarks/peers.py`` (README, design section).

What a callback does: ``y`` and ``out`` are read and written in place through numpy
views of the loop's buffers, made once per address (the loop passes a handful of
buffers); ``p`` and ``m`` are the model's own arrays, the ones the loop was given.  A
point outside a function's domain is NaN, as in C, and is kept in words in the model's
``evaluation_errors`` (:meth:`CompiledModel._call`).  Any other exception is kept and
raised by :meth:`Callbacks.reraise` when the loop returns.
"""
from __future__ import annotations

import ctypes

import numpy as np

__all__ = ["Callbacks", "GENFN"]

GENFN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, *([ctypes.c_void_p] * 5))


class Callbacks:
    """The ctypes callbacks of one model's generated functions; ``address(name, n_out)``
    is what goes into the loop's function-pointer slot."""

    def __init__(self, model):
        self.model = model
        self.n = int(model.n)
        self.error = None
        self._views = {}
        self._keep = []          # the callbacks must live as long as the loop may call them

    def _view(self, address: int, size: int) -> np.ndarray:
        key = (address, size)
        a = self._views.get(key)
        if a is None:
            a = self._views[key] = np.ctypeslib.as_array(
                (ctypes.c_double * max(size, 1)).from_address(address))[:size]
        return a

    def address(self, name: str, n_out: int) -> int:
        model, n, view = self.model, self.n, self._view
        fn = getattr(model.code, name)

        def call(t, y, p, m, out, w):
            o = view(out, n_out)
            try:
                model._call(fn, t, view(y, n), n_out, o)
            except BaseException as exc:     # noqa: BLE001  (raised when the loop returns)
                o[:] = np.nan
                if self.error is None:
                    self.error = exc
                return 1
            return 0

        cb = GENFN(call)
        self._keep.append(cb)
        return ctypes.cast(cb, ctypes.c_void_p).value

    def reraise(self) -> None:
        """Raise what a callback raised during the last run of the loop, if anything."""
        exc, self.error = self.error, None
        if exc is not None:
            raise exc
