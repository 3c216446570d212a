"""Outputs of many points at once: a model's ``expand`` run on arrays, for the outputs
asked for only.

A result holds the solver's unknowns z at its points; every other variable is computed
from them by the generated ``expand`` function, one point at a time.  For a million
points that is a million calls computing every output, when a reader wants one.  Here
the same generated Python statements run once on arrays of points: the statements of
``expand`` that the asked outputs need (read off the source: each statement names what
it assigns, ``_aK`` or ``_cK``, and what it reads), with ``y[k]``, ``m[k]`` and ``t``
arrays over the points, the ``math`` functions numpy's, and an if-expression
``np.where`` of both branches (evaluated with floating-point errors silenced; the one
not taken discarded), as the array code of the numpy backend does
(:mod:`acausal.compiler.backends.arraycode`).  The operations are those of the
generated statements in the same order; numpy's functions agree with ``math``'s to
rounding, so values agree with a point-by-point ``expand`` to rounding, not bitwise.
Every result of a model on the numpy backend reads its values this way, and so does a
large result of a model behind its C library; a smaller one reads them from its C
``expand`` point by point (:func:`pointwise`: no Python source, no sympy for a model
loaded from the compile cache).  What a run gives depends neither on how it is read
nor on what ran before.
"""
from __future__ import annotations

import ast
import functools

import numpy as np

__all__ = ["VectorOutputs", "evaluate", "expand_points", "pointwise", "POINTWISE"]

_CACHED = 64            # compiled selections kept per model


class _Math:
    """``math`` for arrays: numpy's functions under math's names."""

    _NAMES = {"asin": "arcsin", "acos": "arccos", "atan": "arctan", "atan2": "arctan2",
              "asinh": "arcsinh", "acosh": "arccosh", "atanh": "arctanh", "pow": "power",
              "fabs": "abs", "fmod": "fmod"}

    def __getattr__(self, name):
        return getattr(np, self._NAMES.get(name, name))


def _reduce(fn):
    return lambda *args: functools.reduce(fn, args)


_NAMESPACE = {"math": _Math(), "_where": np.where, "_and": _reduce(np.logical_and),
              "_or": _reduce(np.logical_or), "_not": np.logical_not, "_abs": np.abs,
              "_min": _reduce(np.fmin), "_max": _reduce(np.fmax),
              "_float": lambda x: np.asarray(x, dtype=float)}
_CALLS = {"abs": "_abs", "min": "_min", "max": "_max", "float": "_float"}


class _Vectorize(ast.NodeTransformer):
    """The generated statements' scalar Python as array operations."""

    def visit_IfExp(self, node):
        self.generic_visit(node)
        return ast.Call(ast.Name("_where", ast.Load()), [node.test, node.body, node.orelse],
                        [])

    def visit_BoolOp(self, node):
        self.generic_visit(node)
        name = "_and" if isinstance(node.op, ast.And) else "_or"
        return ast.Call(ast.Name(name, ast.Load()), node.values, [])

    def visit_UnaryOp(self, node):
        self.generic_visit(node)
        if isinstance(node.op, ast.Not):
            return ast.Call(ast.Name("_not", ast.Load()), [node.operand], [])
        return node

    def visit_Call(self, node):
        self.generic_visit(node)
        if isinstance(node.func, ast.Name) and node.func.id in _CALLS:
            node.func = ast.Name(_CALLS[node.func.id], ast.Load())
        return node


def _reads(node) -> set:
    return {n.id for n in ast.walk(node) if isinstance(n, ast.Name)
            and isinstance(n.ctx, ast.Load)}


class VectorOutputs:
    """``columns(cols, t, y, p, m)``: the outputs ``cols`` of ``expand`` (their indices)
    at every point, ``t`` an array of n times, ``y[k]`` and ``m[k]`` arrays of n values
    (anything indexable so: ``Z.T``), ``p[k]`` a number or an array of n."""

    def __init__(self, source: str):
        self.source = source
        self._parsed = None
        self._compiled = {}

    def _parse(self):
        if self._parsed is None:
            start = self.source.index("\ndef expand(")
            end = self.source.find("\ndef ", start + 1)
            text = self.source[start + 1:] if end < 0 else self.source[start + 1:end]
            body = ast.parse(text).body[0].body
            defs, outs = {}, {}
            for k, st in enumerate(body):
                if not isinstance(st, ast.Assign) or len(st.targets) != 1:
                    continue
                target = st.targets[0]
                if isinstance(target, ast.Name):
                    if isinstance(st.value, ast.Call) and getattr(st.value.func, "id", "") \
                            == "_list":
                        continue                    # y = _list(y): arrays stay arrays
                    defs[target.id] = k
                elif isinstance(target, ast.Subscript) and isinstance(target.slice,
                                                                      ast.Constant):
                    outs[target.slice.value] = st.value
            self._parsed = (body, defs, outs)
        return self._parsed

    def _function(self, cols: tuple):
        fn = self._compiled.get(cols)
        if fn is not None:
            return fn
        body, defs, outs = self._parse()
        exprs = [outs[c] for c in cols]
        need, stack = set(), [n for e in exprs for n in _reads(e)]
        while stack:
            name = stack.pop()
            k = defs.get(name)
            if k is not None and k not in need:
                need.add(k)
                stack.extend(_reads(body[k].value))
        statements = [body[k] for k in sorted(need)]
        module = ast.parse("def _columns(t, y, p, m):\n    pass\n")
        module.body[0].body = statements + [ast.Return(ast.Tuple(list(exprs), ast.Load()))]
        module = _Vectorize().visit(module)
        ast.fix_missing_locations(module)
        namespace = dict(_NAMESPACE)
        exec(compile(module, "<acausal outputs>", "exec"), namespace)
        fn = namespace["_columns"]
        if len(self._compiled) >= _CACHED:
            self._compiled.pop(next(iter(self._compiled)))
        self._compiled[cols] = fn
        return fn

    def columns(self, cols, t, y, p, m) -> list:
        """[array of len(t)] for each output index in ``cols``."""
        cols = tuple(int(c) for c in cols)
        t = np.asarray(t, dtype=float)
        with np.errstate(all="ignore"):
            values = self._function(cols)(t, y, p, m)
        return [np.broadcast_to(np.asarray(v, dtype=float), t.shape).copy()
                if np.ndim(v) == 0 or np.shape(v) != t.shape else np.asarray(v, dtype=float)
                for v in values]


_CHUNK = 1 << 22     # values (points x outputs) computed at once, at most


POINTWISE = 2_000_000   # points x outputs up to which a C library's own expand is read


def pointwise(compiled, n_points: int) -> bool:
    """Whether a result of ``n_points`` points of ``compiled`` reads its outputs from the
    model's C ``expand``, point by point: for a model behind its C library and a result
    of at most :data:`POINTWISE` values (points x outputs), which then needs neither the
    generated Python source nor sympy to print it (a model loaded from the compile
    cache); a larger result is read on arrays from the Python source, printed if need be.
    The choice depends on the model and the result only, never on what ran before (the
    two agree to rounding, not bitwise)."""
    return getattr(compiled.code, "backend", None) == "c" and \
        n_points * max(len(compiled.outputs), 1) <= POINTWISE


def evaluate(compiled, cols, t, z, parameters, discrete, index, delayed=None) -> list:
    """The outputs ``cols`` (columns of ``compiled``'s ``expand``) at the points
    ``t`` (unknowns ``z``, one row a point), each point in the discrete state
    ``discrete[index[k]]``; ``parameters`` the run's p (its tunable parameters, then
    the delayed values' slots); ``delayed``: the delayed values recorded at each point.
    In chunks of points that bound the memory."""
    n = len(t)
    if compiled.code.expand is None:
        return [np.array(z[:, k], dtype=float) for k in cols]
    if pointwise(compiled, n):        # the model's own C expand, point by point
        y = expand_points(compiled, t, z, parameters, list(discrete), list(index), delayed)
        return [y[:, k] for k in cols]
    vec = getattr(compiled, "_vector_outputs", None)
    if vec is None:
        vec = compiled._vector_outputs = VectorOutputs(compiled.code.source)
    table = np.array(discrete, dtype=float).reshape(len(discrete), -1)
    index = np.asarray(index, dtype=np.int64)
    params = [float(x) for x in parameters]
    # the values recorded at each point: the delayed ones (read after the tunable
    # parameters), then the top-level inputs' (read from their slots), when they varied
    slots = []
    if delayed is not None and np.ndim(delayed) == 2 and len(delayed) == n:
        lines = getattr(compiled, "delays", None)
        n_delayed = lines.n if lines is not None else 0
        first = len(compiled.param_names)
        slots = list(range(first, first + n_delayed))
        inputs = getattr(compiled, "inputs", None)
        if inputs is not None and np.shape(delayed)[1] > n_delayed:
            slots += [int(k) for k in inputs.slots]
        slots = slots[:np.shape(delayed)[1]]
    step = max(1024, _CHUNK // max(1, len(cols)))
    parts = []
    for lo in range(0, max(n, 1), step):
        hi = min(n, lo + step)
        p = params
        if slots:
            p = list(params)
            recorded = np.asarray(delayed[lo:hi], dtype=float)
            for j, k in enumerate(slots):
                p[k] = recorded[:, j]
        parts.append(vec.columns(cols, t[lo:hi], np.asarray(z[lo:hi]).T, p,
                                 _Modes(table, index[lo:hi])))
    return [np.concatenate([part[j] for part in parts]) if len(parts) > 1
            else parts[0][j] for j in range(len(cols))]


class _Modes:
    """``m[k]``: the value of discrete variable k at every point (from the snapshots
    the points were integrated in), made when first read."""

    def __init__(self, table, index):
        self.table, self.index, self.made = table, index, {}

    def __getitem__(self, k):
        out = self.made.get(k)
        if out is None:
            out = self.made[k] = self.table[self.index, k]
        return out


def expand_points(compiled, t, z, p, discrete, index, delayed=None) -> np.ndarray:
    """Every variable at every output time, from the solver vector z, each point in the
    discrete state (relation values) it was integrated in: values computed from
    if-expressions are those of the branch the integrator used there, so an output never
    contradicts the trajectory (at an event, the point before it is in the old modes and
    the point after it in the new).  ``delayed``: the delayed values recorded at each
    point, for a model with delay()."""
    saved, saved_p = compiled.m.copy(), compiled.p.copy()
    compiled.p[:] = p
    known = len(index) == len(t) and discrete
    lines = getattr(compiled, "delays", None)
    # the recorded values: the delayed ones, then those of inputs that varied
    n_delayed = lines.n if lines is not None else 0
    inputs = getattr(compiled, "inputs", None)
    varied = inputs is not None and delayed is not None and len(delayed) == len(t) \
        and np.ndim(delayed) == 2 and delayed.shape[1] > n_delayed
    if lines is not None and (delayed is None or len(delayed) != len(t)):
        raise ValueError("the values of this result's delay() expressions were not "
                         "recorded (a result of a model with delays needs the values the "
                         "run recorded at its points)")
    try:
        rows = []
        for k, (tk, zk) in enumerate(zip(t, z)):
            if lines is not None:
                lines.held = delayed[k][:n_delayed]
            if varied:
                compiled.p[inputs.slots] = delayed[k][n_delayed:]
            if known:
                compiled.m[:] = discrete[index[k]]
            else:                      # a result without its modes: take them from the point
                compiled.init_modes(tk, zk)
            rows.append(compiled.expand(tk, zk))
        return np.array(rows).reshape(len(t), -1)
    finally:
        if lines is not None:
            lines.held = None
        compiled.m[:] = saved
        compiled.p[:] = saved_p
