"""The numbers behind the energy audit: every variable and its rate along a result,
port powers, and the components' declared energies evaluated on them.

A component's ``stored_energy()`` and ``loss_power()`` are sympy expressions in the
symbols of its variables and parameters (named by their dotted paths, as in its
equations).  They are evaluated with numpy on the whole trajectory at once: a variable
symbol takes its values, a parameter its value in the run, ``time`` the output times,
``der(x)`` the rate of x.  The rate of a stored energy is the chain rule

    dE/dt = sum_s dE/ds ds/dt + dE/dtime

on the same values (exact, no differencing of E).

Port power (positive into the component): e f for an electrical or fluid port, the heat
flow for a heat port (an energy flow already), and sum_k through_k der(across_k) for a
mechanical port whose flow is a derivative (flanges: tau der(phi); planar frames:
fx der(x) + fy der(y) + tau der(phi)).
"""
from __future__ import annotations

import inspect
from types import FunctionType

import numpy as np
import sympy as sp

from ..components.component import Component, Port
from ..components.portgroups import leaf_ports
from ..components.symbols import der, time
from ..ports import HeatPort
from ..ports.base import SignalPort
from .operating import constant_value

__all__ = ["Trajectory", "symbolic_term", "storage_rate", "port_power", "leaf_port_power",
           "power_ports", "find_component"]


class Trajectory:
    """Values and time derivatives of every variable of a result, by name."""

    def __init__(self, result, model: Component):
        self.result, self.model = result, model
        self.c = result.compiled
        self.t = np.asarray(result.t, dtype=float)
        from ..runtime.delays import refuse_delays
        refuse_delays(self.c, "the energy audit does not evaluate delay() (the rates of "
                              "delayed values need the run's history)", "Use PadeDelay")
        self.X, self.Xdot = _values_and_rates(self.c, result)
        self._params = dict(zip(self.c.param_names, result.parameters.tolist()))

    def value(self, name: str, rate: bool = False) -> np.ndarray:
        if name.startswith("der(") and name.endswith(")"):
            return self.value(name[4:-1], rate=True)
        sign, k = self.c.outputs[name]
        if sign is None:
            return np.full(len(self.t), 0.0 if rate else constant_value(self.c, k))
        return sign * (self.Xdot if rate else self.X)[:, k]

    def has(self, name: str) -> bool:
        return name in self.c.outputs

    def parameter(self, component: Component, name: str) -> float:
        """The value the simulation used: tunable parameters from the compiled model,
        bindings (``ref``) and expressions of other parameters evaluated in turn."""
        key = f"{component.path}.{name}" if component.path else name
        if key in self._params:
            return self._params[key]
        value = component.parameter_value(name)
        if isinstance(value, sp.Basic) and not value.is_number:
            value = value.xreplace({s: self.symbol_value(s) for s in value.free_symbols})
        return float(value)

    def accessors(self, component, h=0.0):
        """v(name), p(name) for a component; with ``h``, values shifted by h x rate."""
        prefix = f"{component.path}." if component.path else ""

        def v(name):
            if name.startswith("der("):
                return self.value(f"der({prefix}{name[4:-1]})")
            x = self.value(prefix + name)
            return x + h * self.value(prefix + name, rate=True) if h else x

        return v, (lambda name: self.parameter(component, name))

    # -- symbols -------------------------------------------------------------------------
    def symbol_value(self, sym: sp.Symbol, rate: bool = False):
        """The values (or rates) of a variable symbol, the value of a parameter one."""
        name = sym.name
        if sym == time:
            return np.ones_like(self.t) if rate else self.t
        if self.has(name):
            return self.value(name, rate)
        path, _, local = name.rpartition(".")
        owner = find_component(self.model, path) if path else self.model
        if local not in owner.declarations():
            raise KeyError(f"'{name}' in an energy declaration is neither a variable of "
                           "the simulated model nor a parameter")
        return np.zeros_like(self.t) if rate else self.parameter(owner, local)


def _values_and_rates(c, result):
    """Every variable and its rate at each output point, in the modes of that point."""
    t, Z = result.t, result._z
    known = len(result._discrete_index) == len(t) and result._discrete
    saved, saved_p = c.m.copy(), c.p.copy()
    c.p[:] = result.parameters
    X, Xd = [], []
    try:
        for k, (tk, zk) in enumerate(zip(t, Z)):
            if known:
                c.m[:] = result._discrete[result._discrete_index[k]]
            else:
                c.init_modes(tk, zk)
            zdot = _consistent_rate(c, tk, zk)
            h = 1e-6 * (1.0 + abs(tk))
            X.append(c.expand(tk, zk))
            ahead, behind = c.expand(tk + h, zk + h * zdot), c.expand(tk - h, zk - h * zdot)
            Xd.append((ahead - behind) / (2 * h))
    finally:
        c.m[:] = saved
        c.p[:] = saved_p
    return np.array(X).reshape(len(t), -1), np.array(Xd).reshape(len(t), -1)


def _consistent_rate(c, t, z):
    """z' with x' from the model and a' from G_a a' = -(G_x x' + G_t)."""
    zdot = np.zeros(c.n)
    S = np.asarray(c.state_index, dtype=int)
    zdot[S] = c.state_derivatives(t, z)
    alg = np.flatnonzero(c.algebraic)
    if alg.size:
        Gz = c.dG_dy(t, z).toarray()
        h = 1e-7 * (1.0 + abs(t))
        Gt = (c.G(t + h, z) - c.G(t - h, z)) / (2 * h)
        zdot[alg] = np.linalg.lstsq(Gz[:, alg], -(Gz[:, S] @ zdot[S] + Gt), rcond=None)[0]
    return zdot


# -- declared terms ---------------------------------------------------------------------------
def _with_rates(expr):
    """expr with der(x) of symbols x replaced by fresh symbols; {fresh: x}."""
    expr = sp.sympify(expr)
    rates = {}
    for d in sorted(expr.atoms(der), key=sp.srepr):
        arg = d.args[0]
        if not isinstance(arg, sp.Symbol):
            raise ValueError(f"energy declarations take der() of a variable, not of "
                             f"{arg}: expand it by the chain rule")
        rates[d] = sp.Dummy(f"der_{arg.name}")
    return expr.xreplace(rates), {v: k.args[0] for k, v in rates.items()}


def _evaluate(traj, expr, rate_of):
    symbols = sorted(expr.free_symbols, key=lambda s: s.name)
    if not symbols:
        return np.full(len(traj.t), float(expr))
    values = [traj.symbol_value(rate_of[s], rate=True) if s in rate_of
              else traj.symbol_value(s) for s in symbols]
    fn = sp.lambdify(symbols, expr, modules="numpy")
    return np.broadcast_to(np.asarray(fn(*values), dtype=float), traj.t.shape).copy()


def symbolic_term(traj, expr, where: str = "") -> np.ndarray:
    """A declared power (``loss_power``) along the trajectory."""
    try:
        body, rate_of = _with_rates(expr)
        return _evaluate(traj, body, rate_of)
    except (KeyError, ValueError, TypeError) as err:
        raise ValueError(f"energy declaration of '{where}': {err}") from None


def storage_rate(traj, expr, where: str = ""):
    """(E, dE/dt) of a declared stored energy, the rate by the chain rule."""
    expr = sp.sympify(expr)
    if expr.has(der):
        raise ValueError(f"stored_energy() of '{where}' contains der(): a stored energy "
                         "is a function of the state, not of its rates")
    E = symbolic_term(traj, expr, where)
    dE = np.zeros_like(E)
    for s in sorted(expr.free_symbols, key=lambda s: s.name):
        if s != time and not traj.has(s.name):
            continue                   # a parameter: constant along the run
        partial = sp.diff(expr, s)
        if partial != 0:
            dE += symbolic_term(traj, partial, where) * traj.symbol_value(s, rate=True)
    return E, dE


# -- ports ------------------------------------------------------------------------------------
def power_ports(comp) -> list:
    """The component's own ports that carry power (not signal ports); a group of ports
    (``ac.PortGroup``) stands for its members."""
    return [q for c in comp.children().values() if isinstance(c, Port)
            for q in leaf_ports(c) if not isinstance(q, SignalPort)]


def port_power(traj, port) -> np.ndarray:
    """Power into the component through one port (module docstring).  A port whose
    power is not a sum of across-rate x through products defines ``power(value, rate)``
    (of functions giving a port variable's values and rates by its name; with a third
    argument ``parameter``, the function giving a component's parameter in the run,
    ``parameter(component, name)``)."""
    if not getattr(port, "carries_power", True):
        raise ValueError(f"energy audit: the port '{port.path}' ({type(port).__name__}) "
                         f"carries {port.effort} and {port.flow}, whose product is not a "
                         "power; the audit does not cover this domain")
    own = getattr(type(port), "power", None)
    if isinstance(own, FunctionType):          # a method, not a variable named power
        extra = ({"parameter": traj.parameter}   # the value of a component's parameter
                 if "parameter" in inspect.signature(own).parameters else {})
        return own(port, lambda name: traj.value(f"{port.path}.{name}"),
                   lambda name: traj.value(f"der({port.path}.{name})"), **extra)
    if isinstance(port, HeatPort):
        return traj.value(f"{port.path}.{port.flow}")
    if port.flow.startswith("der("):
        across, through = port.across(), port.through()
        return sum((traj.value(f"{port.path}.{f}") * traj.value(f"der({port.path}.{e})")
                    for e, f in zip(across, through)), np.zeros(len(traj.t)))
    return traj.value(f"{port.path}.{port.effort}") * traj.value(f"{port.path}.{port.flow}")


def leaf_port_power(traj, comp) -> np.ndarray:
    return sum((port_power(traj, p) for p in power_ports(comp)), np.zeros(len(traj.t)))


def find_component(model, path):
    comp = model
    for part in path.split("."):
        children = comp.children()
        if part not in children:
            raise KeyError(f"no component '{path}' in the model ({part} not in "
                           f"{sorted(children)})")
        comp = children[part]
    return comp
