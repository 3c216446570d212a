"""A model's generated numpy code behind the compiled step loop's function pointers.

``cbdf.c`` calls a compiled model's residual, Jacobian values and zero-crossing
functions through pointers with the generated C's contract,

    int f(double t, const double *y, const double *p, const double *m, double *out,
          double *w)

(solver contract item 18).  A model on the numpy backend gives the loop its generated
functions as Python callables, which become ctypes callbacks of that contract, so it runs in the same
compiled loop as the C backend -- predictor, corrector with the stored LU, error test,
step and order control, the sparse LU of a large system -- and Python is entered only
for the functions themselves.  It is the arrangement of IDA with a Python residual.

Why: on a large model the numpy functions are a few array operations each
(the numpy backend's array code), and the Python loop's own work per step (a few
dozen numpy calls on vectors of the model's size) costs more than they do; on a small
model the loop's interpreter overhead is most of a step.  Measured in
``benchmarks/peers.py`` (README, design section).

What a callback does: ``y`` and ``out`` are read and written in place through numpy
views of the loop's buffers, made once per address (the loop passes a handful of
buffers); the callable reads the model's own ``p`` and ``m``, the arrays the loop was
given.  A point outside a function's domain is NaN, as in C (the model keeps its words
for the message).  Any other exception is kept and raised by
:meth:`Callbacks.reraise` when the loop returns.
"""
from __future__ import annotations

import ctypes

import numpy as np

__all__ = ["Callbacks", "GENFN", "problem_callbacks"]

GENFN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, *([ctypes.c_void_p] * 5))


class Callbacks:
    """ctypes callbacks of a model's generated functions given as Python callables
    ``f(t, z, out)`` (a :class:`~.base.LoopModel`'s); ``address(f, n, n_out)`` is what goes
    into the loop's function-pointer field."""

    def __init__(self):
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

    def address(self, fn, n: int, n_out: int) -> int:
        view = self._view

        def call(t, y, p, m, out, w):
            o = view(out, n_out)
            try:
                fn(t, view(y, n), o)
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


def problem_callbacks(p, n_roots) -> list:
    """The residual, Jacobian and roots of any problem (contract items 2, 3, 8) as the
    loop's mode-1 callbacks (for tests of the loop against the Python one);
    ``n_roots()`` is the number of roots the loop watches."""
    n = p.n
    dbl = ctypes.POINTER(ctypes.c_double)

    def vec(a, k):
        return np.ctypeslib.as_array(a, (k,)).copy()

    def res(t, y, yp, out):
        try:
            np.ctypeslib.as_array(out, (n,))[:] = p.residual(t, vec(y, n), vec(yp, n))
        except Exception:   # a failed evaluation is a failed Newton iterate
            np.ctypeslib.as_array(out, (n,))[:] = np.nan
        return 0

    def jac(t, y, yp, cj, out):
        J = p.jacobian(t, vec(y, n), vec(yp, n), cj)
        J = J.toarray() if hasattr(J, "toarray") else np.asarray(J, float)
        np.ctypeslib.as_array(out, (n * n,))[:] = J.ravel()
        return 0

    def roots(t, y, yp, out):
        np.ctypeslib.as_array(out, (n_roots(),))[:] = p.roots(t, vec(y, n), vec(yp, n))
        return 0

    return [ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, dbl, dbl, dbl)(res),
            ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, dbl, dbl, ctypes.c_double,
                             dbl)(jac),
            ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, dbl, dbl, dbl)(roots)]
