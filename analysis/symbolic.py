"""Symbolic linearization: A(p), B(p), C(p), D(p) as sympy matrices, for small models.

The compiler's own symbolic passes are run again (flatten, alias elimination, index
reduction with static state selection, BLT causalization), and instead of generating
code the causal form is kept as expressions:

    x' = f(x, t_r, p),   0 = R(x, t_r, p)          (t_r: torn variables, if any)

every assigned variable substituted by its expression in evaluation order.  Then
(Egeland & Gravdahl (1.20)-(1.23), the torn part eliminated by the implicit function
theorem)

    A = f_x - f_t R_t^-1 R_x,   B = f_p - f_t R_t^-1 R_p,   and C, D alike for y = h.

The inputs are parameters (or top-level RealInputs, driven by a parameter as in
:mod:`.operating`); parameters stay symbols, so ``print(sys.A)`` shows A in terms of
R, L, k, J.  A parameter equal to 0 is a structural zero of the compiled model and
appears as 0.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from ..compiler.frontend.alias import eliminate_aliases
from ..compiler.structure.causalize import causalize
from ..compiler.frontend.flatten import flatten
from ..compiler.assemble import solve_linear
from ..compiler.index.reduction import reduce_index
from ..compiler.algebra.symbolic import SymbolicSystem
from .plant import _Harness, top_level_inputs
from .statespace import StateSpace

__all__ = ["linearize_symbolic", "SymbolicStateSpace"]


class SymbolicStateSpace:
    """A, B, C, D as sympy matrices with the names of states, inputs and outputs.

    ``subs({"motor.R": 2.0, ...})`` substitutes values by name; ``numeric(values)``
    gives a numeric :class:`StateSpace` (every remaining symbol must get a value).
    """

    def __init__(self, A, B, C, D, states, inputs, outputs):
        self.A, self.B, self.C, self.D = A, B, C, D
        self.states, self.inputs, self.outputs = states, inputs, outputs

    @property
    def symbols(self) -> set:
        out = set()
        for M in (self.A, self.B, self.C, self.D):
            out |= M.free_symbols
        return out

    def subs(self, values: dict) -> "SymbolicStateSpace":
        rep = {s: values[s.name] for s in self.symbols if s.name in values}
        return SymbolicStateSpace(*(M.xreplace(rep) for M in (self.A, self.B, self.C, self.D)),
                                  self.states, self.inputs, self.outputs)

    def numeric(self, values: dict | None = None) -> StateSpace:
        s = self.subs(values or {})
        left = s.symbols
        if left:
            raise ValueError("no value for " + ", ".join(sorted(x.name for x in left)))
        return StateSpace(*(np.array(M.tolist(), dtype=float).reshape(M.shape)
                            for M in (s.A, s.B, s.C, s.D)), self.states, self.inputs, self.outputs)

    def __repr__(self):
        return f"<SymbolicStateSpace states {self.states}\nA = {self.A}\nB = {self.B}\n" \
               f"C = {self.C}\nD = {self.D}>"


def linearize_symbolic(model, inputs=(), outputs=(), at=None,
                       simplify: bool = True) -> SymbolicStateSpace:
    """Linearize a Component symbolically (see the module docstring).

    Parameters
    ----------
    model : Component
    inputs : list of str
        Parameters or top-level RealInput ports.
    outputs : list of str
        Variables of the model (aliases resolved), ``der(x)`` of a state included.
    at : dict, optional
        Values substituted after differentiation: states (the operating point of a
        nonlinear model), parameters, inputs.  Unlisted ones stay symbols.
    simplify : bool
        Simplify each entry (``sympy.simplify``; turn off for larger models).

    Returns
    -------
    SymbolicStateSpace
    """
    root, prefix, input_params = _root(model)
    flat = flatten(root)
    reduced, aliases = eliminate_aliases(flat)
    system = SymbolicSystem.from_flat(reduced)
    reduction = reduce_index(system, system.structure())
    if reduction.dynamic:
        raise NotImplementedError("symbolic linearization needs a static choice of states; "
                                  "this model selects its states at run time")
    caus = causalize(reduction)
    syms = system.symbols
    subs = _assignments(system, caus)
    x = [syms[v] for v in caus.z[: caus.n_states]]
    tr = [syms[v] for v in caus.z[caus.n_states:]]
    f = sp.Matrix([syms[reduction.structure.var_to_diff[v]].xreplace(subs)
                   for v in caus.z[: caus.n_states]])
    R = sp.Matrix([system.equations[e].residual.xreplace(subs) for e in caus.residual_eqs])
    u = [_parameter_symbol(reduced, input_params.get(n, prefix + n)) for n in inputs]
    h = sp.Matrix([_output_expression(flat, aliases, syms, prefix + n, subs) for n in outputs])
    A, B, C, D = _jacobians(f, R, h, x, tr, u)
    free = set().union(*(M.free_symbols for M in (A, B, C, D)))
    rename = {s: sp.Symbol(s.name[len(prefix):], real=True)
              for s in free if prefix and s.name.startswith(prefix)}
    rename.update({sp.Symbol(input_params[n], real=True): sp.Symbol(n, real=True)
                   for n in input_params})
    mats = [M.xreplace(rename) for M in (A, B, C, D)]
    out = SymbolicStateSpace(*mats, [s.name[len(prefix):] for s in x], list(inputs),
                             list(outputs))
    if at:
        out = out.subs(at)
    if simplify:
        out = SymbolicStateSpace(*(M.applyfunc(sp.simplify) for M in (out.A, out.B, out.C, out.D)),
                                 out.states, out.inputs, out.outputs)
    return out


def _root(model):
    names = top_level_inputs(model)
    if not names:
        return model._clone(), "", {}
    params = {n: f"input{k}.k" for k, n in enumerate(names)}
    params.update({f"{n}.signal": p for n, p in list(params.items())})
    return _Harness(model._clone(), {n: 1.0 for n in names}), "plant.", params


def _assignments(system, caus) -> dict:
    """Each assigned variable's expression in the states and torn variables."""
    syms = system.symbols
    subs = {}
    for v, e in caus.assignments:
        subs[syms[v]] = solve_linear(system.equations[e].residual, syms[v]).xreplace(subs)
    return subs


def _parameter_symbol(reduced, name):
    for p in reduced.parameters:
        if p.name == name:
            return p.symbol
    raise KeyError(f"no parameter or top-level input '{name}' (a parameter equal to 0 is "
                   "a structural zero and cannot be an input)")


def _output_expression(flat, aliases, syms, name, subs):
    if name in aliases.constants:
        return sp.Float(aliases.constants[name])
    sign, root = aliases.resolve(name)
    by_name = {s.name: s for s in syms}
    if root not in by_name:
        raise KeyError(f"no variable '{name}' in the model")
    return sign * by_name[root].xreplace(subs)


def _jacobians(f, R, h, x, tr, u):
    X, U = sp.Matrix(x), sp.Matrix(u)
    if not tr:
        return f.jacobian(X), _jac(f, U), h.jacobian(X), _jac(h, U)
    T = sp.Matrix(tr)
    Rt_inv = R.jacobian(T).inv()
    dT_dx, dT_du = -Rt_inv * R.jacobian(X), -Rt_inv * _jac(R, U)
    return (f.jacobian(X) + f.jacobian(T) * dT_dx, _jac(f, U) + f.jacobian(T) * dT_du,
            h.jacobian(X) + h.jacobian(T) * dT_dx, _jac(h, U) + h.jacobian(T) * dT_du)


def _jac(M, U):
    return M.jacobian(U) if len(U) else sp.zeros(M.shape[0], 0)
