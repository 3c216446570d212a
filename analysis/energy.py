"""Energy audit along a simulation, and a numerical passivity check.

Every component owns its energy (the Modelica Standard Library's ``lossPower`` idea).
A component class says what it is with any of

* ``stored_energy(self)``: the energy it stores, an expression in its own variables and
  parameters (``self.C * self.v**2 / 2``);
* ``loss_power(self)``: the power it dissipates, >= 0 for a passive element
  (``self.v * self.i``; ``ac.der(x)`` may appear);
* ``created_power(self)``, rarely: power its equations create beyond what its stored
  energy accounts for, where the model has no exact energy function (a constant-beta
  chamber with a moving piston); booked in the balance and listed, not a violation;
* ``energy_role``: ``"source"`` (it delivers power from outside the model: voltage,
  torque, pressure sources, a fixed temperature) or ``"lossless"`` (a transducer, an
  ideal gear, a joint, a sensor, a ground: the power into its ports sums to zero).

(:mod:`.energy_terms` evaluates them.)  The audit (Egeland & Gravdahl 2.3, the energy
functions of (2.58), (3.32), (3.93), (4.66), (4.91)) classifies *every* leaf component
of the model -- storage, dissipation, source, lossless, or unclassified -- and checks,
at every output time,

    dE/dt = P_in + P_created - P_diss                                  (the balance)

with E the sum of the stored energies, P_diss of the loss powers, P_created of the
created powers and P_in the power delivered by the sources and unclassified leaves and
through the model's own ports.
A component that declares energy is not descended into (a composite may declare its
own); one that does not is, down to its leaves.  A leaf without power ports (a signal
block) carries no power.  Per-audit overrides (``storage=``, ``dissipation=``, by
component path) and class overrides (:func:`register_storage`,
:func:`register_dissipation`) take precedence, as functions ``fn(v, p)`` of the
component's variable and parameter values.

Beyond the balance the audit judges each component on its own, relative to the power
scale of the run (the largest power any term carries, at least the stored energy per
run time), and lists as ``violations``:

* a dissipative element whose loss power is negative (it delivers power: a friction
  law of the wrong sign, a negative resistance);
* a lossless element whose net port power is not ~0;
* a classified component whose own balance P_ports + P_created,c = dE_c/dt + P_loss,c
  fails (its declaration does not match its equations);
* an unclassified component (its power is booked as delivered, and named).

dE/dt is not differenced from the output grid: at each output point the consistent z'
of the DAE is computed (states from the model, the algebraic part from
G_z z' + G_t = 0), every variable's rate is a central difference along (1, z'), and the
stored energies are differentiated by the chain rule, so the residual measures the
model and the solver's accuracy, not the output spacing.

Passivity (Egeland & Gravdahl 2.4, (2.82), (2.149)): a component with storage S >= 0
is passive when the power into its ports is at least dS/dt along every motion;
``is_passive`` checks this inequality along a simulation.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..components.component import Component, Connection, Port
from ..components.inheritance import all_items
from ..components.portgroups import leaf_ports
from .energy_terms import (Trajectory, find_component, leaf_port_power, port_power,
                           power_ports, storage_rate, symbolic_term)

__all__ = ["energy_balance", "is_passive", "register_storage", "register_dissipation",
           "classify", "EnergyBalance", "Passivity", "Violation", "ROLES"]

ROLES = ("storage", "dissipation", "storage+dissipation", "source", "lossless",
         "no power", "unclassified")

_STORAGE: dict = {}
_DISSIPATION: dict = {}


def register_storage(cls, fn) -> None:
    """Override the stored energy of a component class for every audit:
    ``fn(v, p) -> energy``, where ``v("name")`` gives the component's variable
    (``v("der(x)")`` its derivative) and ``p("name")`` its parameter values.  For a class
    of your own, prefer a ``stored_energy`` method (module docstring)."""
    _STORAGE[cls] = fn


def register_dissipation(cls, fn) -> None:
    """Override the dissipated power (>= 0) of a component class, as for storage.  For
    a class of your own, prefer a ``loss_power`` method (module docstring)."""
    _DISSIPATION[cls] = fn


def _registered(registry, component):
    for klass in type(component).__mro__:
        if klass in registry:
            return registry[klass]
    return None


# -- what each component declares -------------------------------------------------------------
@dataclass
class _Entry:
    """A component's declaration: its role and how to evaluate its terms."""

    component: Component
    role: str
    storage: object = None        # callable(trajectory) -> (E, dE/dt) arrays
    loss: object = None           # callable(trajectory) -> P_loss array
    created: object = None        # callable(trajectory) -> P_created array


def _declared(comp, storage, dissipation):
    """The _Entry of a component that declares something, else None."""
    s_fn = (storage or {}).get(comp.path) or _registered(_STORAGE, comp)
    d_fn = (dissipation or {}).get(comp.path) or _registered(_DISSIPATION, comp)
    cls = type(comp)
    s_sym = getattr(cls, "stored_energy", None) if s_fn is None else None
    d_sym = getattr(cls, "loss_power", None) if d_fn is None else None
    role = getattr(cls, "energy_role", None)
    store = _accessor_storage(s_fn, comp) if s_fn else (
        _symbolic_storage(comp) if callable(s_sym) else None)
    loss = _accessor_term(d_fn, comp) if d_fn else (
        _symbolic_loss(comp) if callable(d_sym) else None)
    if store is None and loss is None and role is None:
        return None
    if store is not None or loss is not None:
        role = "+".join(k for k, f in (("storage", store), ("dissipation", loss)) if f)
    elif role not in ("source", "lossless"):
        raise ValueError(f"{cls.__name__}.energy_role = {role!r}: a class declares "
                         "'source' or 'lossless' (storage and dissipation are declared by "
                         "stored_energy() and loss_power() methods)")
    made = getattr(cls, "created_power", None)
    created = (lambda traj: symbolic_term(traj, comp.created_power(), comp.path)) \
        if callable(made) else None
    return _Entry(comp, role, store, loss, created)


def _symbolic_storage(comp):
    return lambda traj: storage_rate(traj, comp.stored_energy(), comp.path)


def _symbolic_loss(comp):
    return lambda traj: symbolic_term(traj, comp.loss_power(), comp.path)


def _accessor_term(fn, comp):
    return lambda traj: np.broadcast_to(fn(*traj.accessors(comp)), traj.t.shape).astype(float)


def _accessor_storage(fn, comp):
    def evaluate(traj):
        v, p = traj.accessors(comp)
        h = 1e-6
        vp, _ = traj.accessors(comp, h=h)
        vm, _ = traj.accessors(comp, h=-h)
        E = np.broadcast_to(fn(v, p), traj.t.shape).astype(float)
        return E, (fn(vp, p) - fn(vm, p)) / (2 * h)
    return evaluate


def classify(model: Component, storage=None, dissipation=None) -> dict:
    """{component path: role} of every component the audit books (see ``ROLES``):
    declared components (not descended into) and the leaves below undeclared ones."""
    if model._path is None:
        model._bind("")
    return {e.component.path: e.role for e in _entries(model, storage, dissipation)}


def _entries(root, storage=None, dissipation=None):
    """Declared components and leaves, in the model's declaration order."""
    out = []
    for child in root.children().values():
        if isinstance(child, Port):
            continue
        entry = _declared(child, storage, dissipation)
        subs = [c for c in child.children().values() if not isinstance(c, Port)]
        if entry is not None:
            out.append(entry)
        elif subs and _structural(child):
            out.extend(_entries(child, storage, dissipation))
        else:
            out.append(_Entry(child, "unclassified" if power_ports(child) else "no power"))
    return out


def _structural(comp) -> bool:
    """A composite whose power ports are all connected to its parts: its power flows
    through them (a DCMotor).  One that writes its ports into its own equations (a line
    whose sub-components only hold variables) is a leaf of its own."""
    ports = power_ports(comp)
    if not ports:
        return True
    connected = {id(q) for item in all_items(comp, "equations")
                 if isinstance(item, Connection) for p in item.ports for q in leaf_ports(p)}
    return all(id(p) in connected for p in ports)


# -- the audit ------------------------------------------------------------------------------
@dataclass
class Violation:
    """One component that breaks what it declares: ``kind`` is "negative loss",
    "not lossless", "inconsistent declaration" or "unclassified"; ``worst`` the
    offending power [W] at time ``t`` (for "unclassified", its largest delivered power)."""

    kind: str
    path: str
    worst: float
    t: float
    message: str

    def __str__(self):
        return self.message


@dataclass
class EnergyBalance:
    """dE/dt = P_in - P_diss along a simulation (see the module docstring).

    Arrays over ``t``: ``E`` (total stored), ``dE_dt``, ``P_in``, ``P_diss``,
    ``residual`` = dE/dt - (P_in + P_created - P_diss); dicts by component path: ``stored``,
    ``dissipated``, ``sources`` (power delivered by each source and each unclassified
    leaf), ``ports`` (power into the model through each of its own ports), ``lossless``
    (net power into each lossless element, ~0), ``created`` (``created_power``, with
    its sum ``P_created``).  ``roles`` classifies every booked
    component, ``unclassified`` lists those that declare nothing, ``violations`` what
    breaks its declaration (judged against ``tol`` x ``power_scale``); ``ok`` is True
    when there are none and the balance closes to the same tolerance.
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
    roles: dict = field(default_factory=dict)
    lossless: dict = field(default_factory=dict)
    unclassified: list = field(default_factory=list)
    violations: list = field(default_factory=list)
    power_scale: float = 0.0
    tol: float = 1e-6
    created: dict = field(default_factory=dict)
    P_created: np.ndarray = None

    @property
    def ok(self) -> bool:
        return not self.violations and self.balance_closes

    @property
    def balance_closes(self) -> bool:
        """max |residual| <= tol x power scale."""
        return bool(np.max(np.abs(self.residual), initial=0.0) <= self.tol * self.power_scale)

    def relative_residual(self) -> float:
        """max |residual| / max(max |E|, ...) : the worst imbalance per unit of energy
        scale (for a decaying system, the initial energy)."""
        return float(np.max(np.abs(self.residual)) / max(np.max(np.abs(self.E)), 1e-300))

    def __repr__(self) -> str:
        """The summary (bounded: the arrays and whole lists are in the attributes)."""
        return (f"<EnergyBalance of {len(self.t)} points: "
                f"{'ok' if self.ok else 'not ok'}>\n{self.summary()}")

    def summary(self) -> str:
        """The audit in words: the balance, each role, each violation (lists of names
        end with "and N more")."""
        from ..words import listed, shortened
        lines = [f"energy balance: max |dE/dt - (P_in + P_created - P_diss)| = "
                 f"{np.max(np.abs(self.residual), initial=0.0):.3g} W, power scale "
                 f"{self.power_scale:.3g} W ({'closes' if self.balance_closes else 'FAILS'})"]
        for role in ROLES:
            paths = [p for p, r in self.roles.items() if r == role]
            if paths:
                lines.append(f"  {role}: {listed(paths, 12)}")
        if self.created:
            lines.append(f"  created by model equations (no exact energy function): "
                         f"{listed(self.created, 12)}, up to "
                         f"{np.max(np.abs(self.P_created), initial=0.0):.3g} W")
        lines += [f"  VIOLATION {shortened(v, 300)}" for v in self.violations[:8]]
        if len(self.violations) > 8:
            lines.append(f"  and {len(self.violations) - 8} more violations")
        return "\n".join(lines)


def energy_balance(result, model: Component, *, storage=None, dissipation=None,
                   tol: float = 1e-6) -> EnergyBalance:
    """Energy audit of a simulation result.

    Parameters
    ----------
    result : Result
        From ``acausal.simulate``.
    model : Component
        The model instance that was simulated (its instance tree gives the components).
    storage, dissipation : dict, optional
        Extra or overriding entries ``{component path: fn(v, p)}`` for this audit.
    tol : float
        Violations and the balance are judged against tol x the power scale of the run.

    Returns
    -------
    EnergyBalance
    """
    _bind(model)
    traj = Trajectory(result, model)
    n = len(result.t)
    stored, rates, dissipated, sources, lossless, own = {}, {}, {}, {}, {}, {}
    created = {}
    entries = _entries(model, storage, dissipation)
    for e in entries:
        path = e.component.path
        if e.storage is not None:
            stored[path], rates[path] = e.storage(traj)
        if e.loss is not None:
            dissipated[path] = e.loss(traj)
        if e.created is not None:
            created[path] = e.created(traj)
        if e.role in ("source", "unclassified", "lossless") or \
                e.storage is not None or e.loss is not None:
            own[path] = leaf_port_power(traj, e.component)
        if e.role in ("source", "unclassified"):
            sources[path] = -own[path]
        elif e.role == "lossless":
            lossless[path] = own[path]
    ports = {p.path: port_power(traj, p) for p in power_ports(model)}
    zero = np.zeros(n)
    E, dE = sum(stored.values(), zero), sum(rates.values(), zero)
    P_in = sum(sources.values(), zero) + sum(ports.values(), zero)
    P_diss = sum(dissipated.values(), zero)
    P_created = sum(created.values(), zero)
    scale = _power_scale(traj.t, E, [dE, P_in, P_diss], rates, dissipated, own, ports)
    roles = {e.component.path: e.role for e in entries}
    unclassified = [p for p, r in roles.items() if r == "unclassified"]
    violations = _violations(traj.t, roles, rates, dissipated, created, own, scale, tol)
    return EnergyBalance(result.t, E, dE, P_in, P_diss, dE - (P_in + P_created - P_diss),
                         stored, dissipated, sources, ports, roles, lossless, unclassified,
                         violations, scale, tol, created, P_created)


def _power_scale(t, E, totals, *dicts) -> float:
    """The largest power any term carries; for a model that hardly moves (a pendulum
    hanging at rest) at least the change of its stored energy per run time, and 1e-6 of
    its stored energy per run time, so that the round-off of powers near zero is not
    judged against itself.  The change, not the level: an energy measured from a far
    datum (C T from 0 K, m g y) would otherwise set a scale that hides real violations
    (a 300 K heat capacitor next to a milliwatt circuit)."""
    peaks = [np.max(np.abs(a), initial=0.0) for a in totals]
    peaks += [np.max(np.abs(a), initial=0.0) for d in dicts for a in d.values()]
    span = float(t[-1] - t[0]) if len(t) > 1 else 0.0
    level = max(np.ptp(E) if len(E) else 0.0, 1e-6 * np.max(np.abs(E), initial=0.0))
    floor = level / span if span > 0 else 0.0
    return float(max(peaks + [floor]))


def _violations(t, roles, rates, dissipated, created, own, scale, tol):
    """Each component judged on its own declaration (module docstring)."""
    limit = tol * scale
    out = []
    zero = np.zeros(len(t))
    for path, role in roles.items():
        if role == "unclassified":
            k = int(np.argmax(np.abs(own[path])))
            out.append(Violation("unclassified", path, float(-own[path][k]), float(t[k]),
                                 f"'{path}' declares neither stored energy, loss power nor "
                                 "a role (source, lossless): its power is booked as "
                                 f"delivered (up to {abs(own[path][k]):.3g} W)"))
            continue
        if path in dissipated:
            k = int(np.argmin(dissipated[path]))
            if dissipated[path][k] < -limit:
                out.append(Violation("negative loss", path, float(dissipated[path][k]),
                                     float(t[k]), f"'{path}' is dissipative but its loss "
                                     f"power is {dissipated[path][k]:.3g} W at t = {t[k]:.6g}"
                                     ": it delivers power"))
        if role == "lossless":
            k = int(np.argmax(np.abs(own[path])))
            if abs(own[path][k]) > limit:
                out.append(Violation("not lossless", path, float(own[path][k]), float(t[k]),
                                     f"'{path}' is declared lossless but takes "
                                     f"{own[path][k]:.3g} W through its ports at "
                                     f"t = {t[k]:.6g}"))
        elif role not in ("source", "no power"):
            gap = own[path] + created.get(path, zero) - rates.get(path, zero) \
                - dissipated.get(path, zero)
            k = int(np.argmax(np.abs(gap)))
            if abs(gap[k]) > limit:
                out.append(Violation("inconsistent declaration", path, float(gap[k]),
                                     float(t[k]), f"'{path}': its port power differs from "
                                     f"dE/dt + P_loss by {gap[k]:.3g} W at t = {t[k]:.6g} "
                                     "(its stored_energy/loss_power do not match its "
                                     "equations)"))
    return out


def _bind(model):
    if model._path is None:            # a fresh instance of the simulated model's class
        model._bind("")


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

    def __repr__(self) -> str:
        worst = float(np.min(self.margin, initial=0.0))
        return (f"<Passivity: {'passive' if self.passive else 'not passive'} over "
                f"{len(self.t)} points, least margin {worst:.3g} W>")


def is_passive(result, model: Component, component: str, *, tol: float = 1e-6) -> Passivity:
    """Check the dissipation inequality P_ports >= dS/dt of one component along a run.

    ``S`` is the sum of the stored energies declared inside the component (0 if none).
    Passive means the inequality holds at every output time to ``tol`` relative to the
    largest power involved (Egeland & Gravdahl (2.82) in differential form (2.149)).
    A simulation shows one motion only: a True answer is evidence, a False one a proof.
    """
    _bind(model)
    comp = find_component(model, component)
    traj = Trajectory(result, model)
    supply = leaf_port_power(traj, comp)
    own = _declared(comp, None, None)
    parts = [own] if own is not None else _entries(comp)
    dS = np.zeros(len(result.t))
    for e in parts:
        if e.storage is not None:
            dS = dS + e.storage(traj)[1]
    margin = supply - dS
    scale = max(np.max(np.abs(supply)), np.max(np.abs(dS)), 1e-300)
    return Passivity(bool(np.min(margin) >= -tol * scale), result.t, supply, dS, margin)
