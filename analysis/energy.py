"""Energy audit along a simulation, and a numerical passivity check.

Stored energy and dissipated power are declared per component class in a registry
(``register_storage`` / ``register_dissipation``) as functions of the component's own
variable and parameter names, so library files need not change:

    register_storage(Capacitor, lambda v, p: 0.5 * p("C") * v("v")**2)

The audit of a model (Egeland & Gravdahl 2.3, the energy functions of (2.58), (3.32),
(3.93), (4.66), (4.91)) checks, at every output time,

    dE/dt = P_in - P_diss

with E the sum of the registered storages, P_diss of the registered dissipations, and
P_in the power that enters through the model's own ports plus the power delivered by
every leaf component that has neither (sources; lossless transducers and sensors
deliver none).  Port power is effort x flow (``Port.effort``/``Port.flow``); a heat
port's energy flow is its heat flow.

dE/dt is not differenced from the output grid: at each output point the consistent
z' of the DAE is computed (states from the model, the algebraic part from
G_z z' + G_t = 0), and every variable's time derivative is a central difference along
(1, z'), accurate to round-off, so the residual measures the model and the solver's
accuracy, not the output spacing.

Passivity (Egeland & Gravdahl 2.4, (2.82), (2.149)): a component with storage S >= 0
is passive when the power into its ports is at least dS/dt along every motion;
``is_passive`` checks this inequality along a simulation.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..components.component import Component, Port
from ..ports import HeatPort
from ..ports.base import SignalPort
from .operating import constant_value

__all__ = ["energy_balance", "is_passive", "register_storage", "register_dissipation",
           "EnergyBalance", "Passivity"]

_STORAGE: dict = {}
_DISSIPATION: dict = {}


def register_storage(cls, fn) -> None:
    """Declare the stored energy of a component class: ``fn(v, p) -> energy``, where
    ``v("name")`` gives the component's variable (``v("der(x)")`` its derivative) and
    ``p("name")`` its parameter values."""
    _STORAGE[cls] = fn


def register_dissipation(cls, fn) -> None:
    """Declare the dissipated power (>= 0) of a component class, as for storage."""
    _DISSIPATION[cls] = fn


def _lookup(registry, component):
    _load_library_entries()
    for klass in type(component).__mro__:
        if klass in registry:
            return registry[klass]
    return None


_LOADED = []


def _load_library_entries():
    """The library's entries, registered on first use (the library imports late)."""
    if _LOADED:
        return
    _LOADED.append(True)
    from ..library import electrical as el, rotational as rot, thermal as th
    from ..library import translational as tr
    half = 0.5
    register_storage(el.Capacitor, lambda v, p: half * p("C") * v("v") ** 2)
    register_storage(el.Inductor, lambda v, p: half * p("L") * v("i") ** 2)
    register_dissipation(el.Resistor, lambda v, p: v("v") * v("i"))
    register_storage(rot.Inertia, lambda v, p: half * p("J") * v("w") ** 2)
    register_storage(rot.Spring, lambda v, p: half * p("c") * (v("phi_rel") - p("phi_rel0")) ** 2)
    register_storage(rot.SpringDamper,
                     lambda v, p: half * p("c") * (v("phi_rel") - p("phi_rel0")) ** 2)
    register_dissipation(rot.SpringDamper, lambda v, p: p("d") * v("der(phi_rel)") ** 2)
    register_dissipation(rot.Damper, lambda v, p: v("tau") * v("der(phi_rel)"))
    register_storage(tr.Mass, lambda v, p: half * p("m") * v("v") ** 2)
    register_storage(tr.Spring, lambda v, p: half * p("c") * (v("s_rel") - p("s_rel0")) ** 2)
    register_storage(tr.SpringDamper,
                     lambda v, p: half * p("c") * (v("s_rel") - p("s_rel0")) ** 2)
    register_dissipation(tr.SpringDamper, lambda v, p: p("d") * v("der(s_rel)") ** 2)
    register_dissipation(tr.Damper, lambda v, p: v("f") * v("der(s_rel)"))
    register_storage(th.HeatCapacitor, lambda v, p: p("C") * v("T"))
    try:
        from ..library import hydraulics as hy
    except ImportError:
        return
    if hasattr(hy, "Volume"):     # W_p = V p^2 / (2 beta)  (4.66)
        register_storage(hy.Volume, lambda v, p: p("V") * v("p") ** 2 / (2 * p("beta")))
    for name in ("LaminarOrifice", "TurbulentOrifice"):
        if hasattr(hy, name):
            register_dissipation(getattr(hy, name), lambda v, p: v("dp") * v("q"))


# -- the trajectory: every variable and its time derivative ----------------------------------
class _Trajectory:
    """Values and time derivatives of every variable of a result, by name."""

    def __init__(self, result, model: Component):
        self.result, self.model = result, model
        self.c = result.compiled
        self.X, self.Xdot = _values_and_rates(self.c, result.t, result._z)
        self._params = _parameter_values(self.c)

    def value(self, name: str, rate: bool = False) -> np.ndarray:
        if name.startswith("der(") and name.endswith(")"):
            return self.value(name[4:-1], rate=True)
        sign, k = self.c.outputs[name]
        if sign is None:
            return np.full(len(self.result.t), 0.0 if rate else constant_value(self.c, k))
        return sign * (self.Xdot if rate else self.X)[:, k]

    def parameter(self, component: Component, name: str) -> float:
        """The value the simulation used: tunable parameters from the compiled model,
        bindings (``ref``) followed up to the parameter they name."""
        key = f"{component.path}.{name}" if component.path else name
        for _ in range(64):
            if key in self._params:
                return self._params[key]
            value = component.parameter_value(name)
            if not hasattr(value, "name"):
                return float(value)
            key = value.name
            path, _, name = key.rpartition(".")
            component = _find(self.model, path) if path else self.model
        raise ValueError(f"parameter binding chain too deep at '{key}'")

    def accessors(self, component, rate=False, h=0.0):
        """v(name), p(name) for a component; with ``h``, values shifted by h x rate."""
        prefix = f"{component.path}." if component.path else ""

        def v(name):
            if name.startswith("der("):
                return self.value(f"der({prefix}{name[4:-1]})")
            x = self.value(prefix + name)
            return x + h * self.value(prefix + name, rate=True) if h else x

        return v, (lambda name: self.parameter(component, name))


def _parameter_values(c) -> dict:
    return dict(zip(c.param_names, c.p.tolist()))


def _values_and_rates(c, t, Z):
    saved = c.m.copy()
    X, Xd = [], []
    try:
        for tk, zk in zip(t, Z):
            c.init_modes(tk, zk)
            zdot = _consistent_rate(c, tk, zk)
            h = 1e-6 * (1.0 + abs(tk))
            X.append(c.expand(tk, zk))
            ahead, behind = c.expand(tk + h, zk + h * zdot), c.expand(tk - h, zk - h * zdot)
            Xd.append((ahead - behind) / (2 * h))
    finally:
        c.m[:] = saved
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
        zdot[alg] = np.linalg.solve(Gz[:, alg], -(Gz[:, S] @ zdot[S] + Gt))
    return zdot


# -- the audit -----------------------------------------------------------------------------
@dataclass
class EnergyBalance:
    """dE/dt = P_in - P_diss along a simulation (see the module docstring).

    Arrays over ``t``: ``E`` (total stored), ``dE_dt``, ``P_in``, ``P_diss``,
    ``residual`` = dE/dt - (P_in - P_diss); dicts by component path: ``stored``,
    ``dissipated``, ``sources`` (power delivered by each unregistered leaf), ``ports``
    (power into the model through each of its own ports).
    """

    t: np.ndarray
    E: np.ndarray
    dE_dt: np.ndarray
    P_in: np.ndarray
    P_diss: np.ndarray
    residual: np.ndarray
    stored: dict
    dissipated: dict
    sources: dict
    ports: dict

    def relative_residual(self) -> float:
        """max |residual| / max(max |E|, ...) : the worst imbalance per unit of energy
        scale (for a decaying system, the initial energy)."""
        return float(np.max(np.abs(self.residual)) / max(np.max(np.abs(self.E)), 1e-300))


def energy_balance(result, model: Component, *, storage=None, dissipation=None) -> EnergyBalance:
    """Energy audit of a simulation result.

    Parameters
    ----------
    result : Result
        From ``acausal.simulate``.
    model : Component
        The model instance that was simulated (its instance tree gives the components).
    storage, dissipation : dict, optional
        Extra or overriding entries ``{component path: fn(v, p)}`` for this audit.

    Returns
    -------
    EnergyBalance
    """
    _bind(model, result)
    traj = _Trajectory(result, model)
    stored, dissipated, sources = {}, {}, {}
    for comp in _components(model, storage, dissipation):
        s, d = _entries(comp, storage, dissipation)
        if s is not None:
            stored[comp.path] = (s, comp)
        if d is not None:
            dissipated[comp.path] = d(*traj.accessors(comp))
        if s is None and d is None:
            power = _port_power(traj, comp)
            if np.max(np.abs(power), initial=0.0) > 0.0:
                sources[comp.path] = -power
    sources = _significant(sources)
    E, dE = _storage_and_rate(traj, stored)
    ports = {p.path: _one_port_power(traj, p) for p in _ports(model)}
    P_in = sum(sources.values(), np.zeros(len(result.t))) + sum(ports.values(),
                                                                 np.zeros(len(result.t)))
    P_diss = sum(dissipated.values(), np.zeros(len(result.t)))
    return EnergyBalance(result.t, E, dE, P_in, P_diss, dE - (P_in - P_diss),
                         {k: fn(*traj.accessors(c)) for k, (fn, c) in stored.items()},
                         dissipated, sources, ports)


def _significant(sources):
    """Drop leaves whose power is round-off (an EMF's v i - tau w, a sensor's)."""
    peak = max((np.max(np.abs(p)) for p in sources.values()), default=0.0)
    return {k: p for k, p in sources.items() if np.max(np.abs(p)) > 1e-10 * peak}


def _bind(model, result):
    if model._path is None:            # a fresh instance of the simulated model's class
        model._bind("")


def _entries(comp, storage, dissipation):
    s = (storage or {}).get(comp.path) or _lookup(_STORAGE, comp)
    d = (dissipation or {}).get(comp.path) or _lookup(_DISSIPATION, comp)
    return s, d


def _components(root, storage=None, dissipation=None):
    """Registered components (not descended into) and unregistered leaves."""
    out = []
    for child in root.children().values():
        if isinstance(child, Port):
            continue
        s, d = _entries(child, storage, dissipation)
        subs = [c for c in child.children().values() if not isinstance(c, Port)]
        if s is not None or d is not None or not subs:
            out.append(child)
        else:
            out.extend(_components(child, storage, dissipation))
    return out


def _ports(comp):
    return [c for c in comp.children().values()
            if isinstance(c, Port) and not isinstance(c, SignalPort)]


def _one_port_power(traj, port):
    flow = traj.value(_qualified(port.path, port.flow))
    if isinstance(port, HeatPort):
        return flow                        # a heat flow is already an energy flow
    return traj.value(_qualified(port.path, port.effort)) * flow


def _qualified(path, name):
    if name.startswith("der("):
        return f"der({path}.{name[4:-1]})"
    return f"{path}.{name}"


def _port_power(traj, comp):
    return sum((_one_port_power(traj, p) for p in _ports(comp)), np.zeros(len(traj.result.t)))


def _storage_and_rate(traj, stored):
    n = len(traj.result.t)
    E, dE = np.zeros(n), np.zeros(n)
    h = 1e-6
    for fn, comp in stored.values():
        v, p = traj.accessors(comp)
        E += fn(v, p)
        vp, _ = traj.accessors(comp, h=h)
        vm, _ = traj.accessors(comp, h=-h)
        dE += (fn(vp, p) - fn(vm, p)) / (2 * h)
    return E, dE


# -- passivity -------------------------------------------------------------------------------
@dataclass
class Passivity:
    """Outcome of :func:`is_passive`: ``passive``, and along ``t`` the port power
    ``supply``, the storage rate ``dS_dt`` and ``margin`` = supply - dS/dt (>= 0 where
    the dissipation inequality holds)."""

    passive: bool
    t: np.ndarray
    supply: np.ndarray
    dS_dt: np.ndarray
    margin: np.ndarray

    def __bool__(self):
        return self.passive


def is_passive(result, model: Component, component: str, *, tol: float = 1e-6) -> Passivity:
    """Check the dissipation inequality P_ports >= dS/dt of one component along a run.

    ``S`` is the sum of the registered storages inside the component (0 if none).
    Passive means the inequality holds at every output time to ``tol`` relative to the
    largest power involved (Egeland & Gravdahl (2.82) in differential form (2.149)).
    A simulation shows one motion only: a True answer is evidence, a False one a proof.
    """
    _bind(model, result)
    comp = _find(model, component)
    traj = _Trajectory(result, model)
    supply = _port_power(traj, comp)
    parts = [c for c in _components(comp) if _lookup(_STORAGE, c) is not None]
    if _lookup(_STORAGE, comp) is not None:
        parts = [comp]
    _, dS = _storage_and_rate(traj, {c.path: (_lookup(_STORAGE, c), c) for c in parts})
    margin = supply - dS
    scale = max(np.max(np.abs(supply)), np.max(np.abs(dS)), 1e-300)
    return Passivity(bool(np.min(margin) >= -tol * scale), result.t, supply, dS, margin)


def _find(model, path):
    comp = model
    for part in path.split("."):
        children = comp.children()
        if part not in children:
            raise KeyError(f"no component '{path}' in the model ({part} not in "
                           f"{sorted(children)})")
        comp = children[part]
    return comp
