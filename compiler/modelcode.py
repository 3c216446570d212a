"""What the compiler hands to the runtime: generated code and name maps, nothing that runs.

:func:`acausal.compiler.pipeline.compile_model` returns a :class:`ModelCode`; the runtime
(:class:`acausal.runtime.CompiledModel`) is built from it.  Everything here is plain data
(arrays, lists, names) or generated functions of ``(t, z, p, m, out)``; the compiler never
imports the solvers, and the runtime never sees sympy.

The solver vector ``z`` (see the README's design section): in the causal form the states
(first ``n_states`` entries) and the tearing variables; in the full form every variable.
``m`` is the discrete state: ``n_relations`` relation values (1.0 true, 0.0 false) followed
by ``n_discrete`` frozen floor values, then held(y) and pre(y) of each of the ``n_held``
discrete variables (:mod:`acausal.compiler.frontend.sampled`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["ModelCode", "RelationInfo", "WhenCode", "DynamicSets", "InitialCode", "DelayCode",
           "InputCode"]


@dataclass
class RelationInfo:
    """The relations of discontinuous expressions and the frozen floor values.

    ``ops[k]``: the sympy class name of relation k (``StrictGreaterThan``, ``GreaterThan``,
    ``StrictLessThan``, ``LessThan``); ``texts[k]``: the relation as written, with the
    component it comes from; ``nominal[k]``: the largest nominal value of the variables in
    it (the floor of its own scale).  ``discrete_texts[j]``: ``floor(u)`` as written.
    ``time_linear``: indices into the roots rows (relations, then floor arguments) of the
    items that are linear in time with coefficients frozen between events: their next
    crossing is known in advance (time events).
    """

    ops: list = field(default_factory=list)
    texts: list = field(default_factory=list)
    nominal: list = field(default_factory=list)
    discrete_texts: list = field(default_factory=list)
    time_linear: list = field(default_factory=list)
    held_names: list = field(default_factory=list)     # the discrete variables
    held_start: list = field(default_factory=list)     # their values before t0
    # initial() (true while the initial values are found) is read from m after the
    # held and pre values when a model uses it
    has_initial: bool = False
    # the value type of each discrete variable: "Real", "Boolean" or "Integer"
    held_types: list = field(default_factory=list)

    @property
    def n_relations(self) -> int:
        return len(self.ops)

    @property
    def n_discrete(self) -> int:
        return len(self.discrete_texts)

    @property
    def n_held(self) -> int:
        return len(self.held_names)


@dataclass
class WhenCode:
    """When-clauses: rows ``0..n_when-1`` of ``code`` are the conditions (1/0; 0 for a
    clock), condition row k of clause ``cond_owners[k]`` (a clause ``when([c1, c2])``
    has a row for each, and fires when one becomes true), then one reinit value per
    reinit action, applied to ``z[targets[k]]`` when clause ``owners[k]`` fires, then
    one value per assignment, written to the held value ``assign_slots[k]`` of the
    discrete variables when ``assign_owners[k]`` fires, in the order of
    ``assign_levels`` (data flow), then start and period of the clock of each clause in
    ``clocks``.  The clauses in ``always`` are the equations of Boolean and Integer
    variables: they have no condition row and are evaluated at every event."""

    code: object
    n_when: int
    targets: list = field(default_factory=list)
    owners: list = field(default_factory=list)
    texts: list = field(default_factory=list)
    assign_slots: list = field(default_factory=list)
    assign_owners: list = field(default_factory=list)
    assign_levels: list = field(default_factory=list)
    clocks: list = field(default_factory=list)
    cond_owners: list = None          # None: one condition row per clause, in order
    always: list = field(default_factory=list)
    n_clauses: int = None             # None: n_when
    # held values set by a tick, y = sample(start, period), and false once it is over
    pulse_slots: list = field(default_factory=list)


@dataclass
class DynamicSets:
    """Data for dynamic state selection (see :mod:`acausal.runtime.dynamic`): the level
    rows, the derivative variables in each row, the derivative maps (-1: none), each
    variable's state_select priority (0 never .. 4 always) and derivative order."""

    levels: list
    row_vars: dict
    var_to_diff: list
    diff_to_var: list
    priority: list
    orders: list
    names: list


@dataclass
class InitialCode:
    """Initial-condition rows over z; ``rows`` are those kept (mandatory rows, then the
    start-value rows a structural matching chose), ``descriptions`` label every row.

    The first ``n_mandatory`` rows are the user's initial equations and fixed start
    values; ``redundant`` lists those among them that the structure cannot use beside
    the others (more conditions than states, or two fixing the same unknowns): the
    runtime then chooses the kept rows numerically and checks the dropped ones at the
    initial point (:mod:`acausal.runtime.initial`)."""

    code: object
    descriptions: list
    rows: np.ndarray
    redundant: list = field(default_factory=list)
    n_mandatory: int = 0
    sizes: list = field(default_factory=list)    # |start| + nominal of a fixed start


@dataclass
class DelayCode:
    """The delays of a model (:mod:`acausal.compiler.frontend.delays`): row j of ``code``'s
    residual is the delayed expression of delay j, whose value the generated functions
    read from ``p[n_params + j]``; ``times[j]`` is its delay time, a float or a function
    of the tunable parameters ``f(p)``; ``texts``/``wheres`` name it and its component;
    ``feedback``: whether a delayed value may reach a delayed expression (a loop)."""

    code: object
    texts: list
    times: list
    wheres: list
    feedback: bool = True


@dataclass
class InputCode:
    """The top-level inputs of a model (:mod:`acausal.compiler.frontend.inputs`): input j,
    ``names[j]``, is read from ``p[n_params + n_delays + j]``; ``types[j]`` is Real,
    Boolean or Integer, ``starts[j]`` its value where none is given."""

    names: list
    types: list
    starts: list


@dataclass
class ModelCode:
    code: object                      # GeneratedCode: residual, jacobian, roots, scales, expand
    names: list                       # name of each z entry
    param_names: list
    param_values: list
    n_res: int                        # rows of the model equations proper
    state_z: list                     # causal form: the states, der(s) computed by the code
    pairs: list                       # full form: (s, der(s)) links
    dummies: list                     # full form: derivative variables without a link
    nominal: list
    start: list
    outputs: dict                     # every variable's name -> (sign, index into expand)
    relations: RelationInfo
    initial: InitialCode
    whens: WhenCode | None = None
    dynamic: DynamicSets | None = None
    report: object = None
    meta: dict = field(default_factory=dict)
    delays: DelayCode | None = None
    inputs: InputCode | None = None
