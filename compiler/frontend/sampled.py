"""Discrete-time variables: values held between events, assigned in when-clauses.

Modelica Language Specification 3.6, sec. 8.3.5 (when-equations), 3.8.3 (discrete-time
expressions) and 3.7.5 (``sample``); the Modelica Standard Library's
``Modelica.Blocks.Discrete`` is built on them.  A variable declared ``discrete=True``
keeps its value between events and changes only where ``ac.assign(y, expr)`` in a
when-clause fires; its start value is its value before the first assignment (its
``pre`` value at t0).

The pass (``sampled`` in :mod:`acausal.compiler.pipeline`, after ``discrete``) gives each
discrete variable y two values in the discrete state the runtime holds,

    held(y)   its value since its last assignment,
    pre(y)    its value before the current instant (equal to held(y) between events),

and puts the equation ``y = held(y)`` in the flat model where the assignment was.  So
continuous equations read the held value through an ordinary variable that alias
elimination, the BLT, the results and the reports see like any other, and held(y),
pre(y) are constant between events for index reduction, as parameters and frozen
floor values are.  The assignment itself writes held(y).

Several clauses can fire at one instant (two samplers of one period, a sampler and a
hold behind it).  Modelica sorts the when-equations by data flow (sec. 8.4): an
assignment that reads y (not pre(y)) runs after the assignment of y.
:func:`assignment_levels` computes that order at compile time, reading through the
explicit assignments of the BLT; a cycle is an algebraic loop through discrete
variables and an error naming its clauses.

Checked here, each a :class:`DiscreteVariableError` naming the component and variable:
an assignment of something that is not a discrete variable (a state is changed with
``reinit``), a discrete variable assigned twice, a discrete variable that no clause
assigns, ``der`` or ``reinit`` of a discrete variable; an equation that also determines
a discrete variable is found by the balance check (:func:`explain_overdetermined`).
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from ...components.symbols import Assign, Reinit, Sample, When, no_event
from ...components.symbols import Pre as pre
from ...components.declarations import TYPE_NAMES
from ..flatmodel import FlatEquation
from ...errors import DiscreteVariableError, ModelError

__all__ = ["HeldValue", "declare_discrete_variables",
           "pre_after_aliases", "when_rows", "explain_overdetermined",
           "reinit_targets_are_states"]


@dataclass
class HeldValue:
    """One discrete variable: ``symbol`` stands for held(y), ``pre`` for pre(y)."""

    name: str
    variable: sp.Symbol
    symbol: sp.Symbol
    pre: sp.Symbol
    start: float
    where: str
    clause: str

    @property
    def text(self) -> str:
        return f"{self.name} (held)"


def _clause_text(w) -> str:
    if getattr(w, "equation", None) is not None:
        return f"the equation '{w.equation}' in {w.origin or '(model)'} ({w.origin_class})"
    return f"when {w.condition} in {w.origin or '(model)'} ({w.origin_class})"


def _local(v) -> str:
    return v.name[len(v.component) + 1:] if v.component else v.name


def _shown(v) -> str:
    """A variable's name as the user reads it (a signal by its port's name)."""
    return v.name[: -len(".signal")] if v.kind == "signal" and v.name.endswith(
        ".signal") else v.name


def _typed(v) -> bool:
    """A Boolean or Integer variable: discrete by nature."""
    return getattr(v.attrs, "type", float) is not float


def declare_discrete_variables(flat) -> list:
    """Check the discrete variables and their assignments, add ``y = held(y)`` for each,
    replace ``pre(y)`` by its symbol everywhere (in place); return the
    :class:`HeldValue` list in declaration order.

    The equation of a Boolean or Integer variable, ``ac.Eq(y, expr)`` with y alone on
    its left, becomes a clause that is evaluated at every event (``When.equation``):
    y is held between events and takes expr, relations in it switching at located
    events, as Modelica's event iteration evaluates the discrete equations."""
    discrete = {v.symbol: v for v in flat.variables if v.attrs.discrete or _typed(v)}
    if discrete:
        _clauses_of_equations(flat, discrete)
    if not discrete and not flat.whens:
        return []                      # most models: nothing to check, nothing held
    by_symbol = {v.symbol: v for v in flat.variables}
    params = {p.symbol for p in flat.parameters}
    assigned = {}
    for w in flat.whens:
        read = sorted(q.name for q in (w.clock.free_symbols if w.clock is not None else ())
                      if q in by_symbol)
        if read:
            raise DiscreteVariableError(
                f"{_clause_text(w)}: the start and period of sample() are numbers or "
                f"parameters, not variables ({', '.join(read)})")
        for act in w.actions:
            v = by_symbol.get(act.variable)
            if isinstance(act, Reinit):
                if v is not None and (v.attrs.discrete or _typed(v)):
                    raise DiscreteVariableError(
                        f"reinit({v.name}, ...) in {_clause_text(w)}: '{_local(v)}' of "
                        f"{v.where} is a discrete variable; assign it with "
                        f"ac.assign({_local(v)}, ...) (reinit restarts a state)")
                continue
            _check_target(act, v, w, params, assigned)
            assigned[v.symbol] = w
    helds = []
    for v in discrete.values():
        if v.symbol in flat.derivatives:
            raise DiscreteVariableError(
                f"der({v.name}) in {v.where}: '{_local(v)}' is a discrete variable, "
                "constant between events; its derivative is 0")
        if v.symbol not in assigned:
            if _typed(v):      # an input, or equal to one through a connection
                continue
            raise DiscreteVariableError(
                f"'{_local(v)}' of {v.where} is declared discrete, but no when-clause "
                f"assigns it: a discrete variable changes only in when-clauses "
                f"(ac.when(..., ac.assign({_local(v)}, ...))); an equation that determines "
                "it makes it a continuous variable (drop discrete=True)")
        start = float(v.attrs.start) if v.attrs.start is not None else 0.0
        if v.attrs.fixed:        # the start value is the value before t0 in any case
            flat.variables[flat.variables.index(v)] = replace(v, attrs=replace(v.attrs,
                                                                              fixed=None))
        helds.append(HeldValue(v.name, v.symbol, sp.Symbol(f"held({v.name})", real=True),
                               sp.Symbol(f"pre({v.name})", real=True), start, v.where,
                               _clause_text(assigned[v.symbol])))
    if not helds:
        return helds
    _substitute(flat, helds)
    for h in helds:
        v = by_symbol[h.variable]
        flat.equations.append(FlatEquation(
            h.variable - h.symbol, f"{h.name} = its value assigned in {h.clause}",
            v.component, v.component_class, "discrete"))
    return helds


def _clauses_of_equations(flat, by_symbol) -> None:
    """The equations ``y = expr`` of Boolean and Integer variables y become clauses
    evaluated at every event (in place: taken out of ``flat.equations``); ``by_symbol``
    holds the model's discrete variables at least."""
    kept = []
    for eq in flat.equations:
        v = by_symbol.get(eq.defines) if eq.kind == "equation" else None
        if v is None or not _typed(v):
            kept.append(eq)
            continue
        value = v.symbol - eq.residual
        tick = _tick_of(value)
        if tick is not None:      # y = sample(start, period): true at each tick only
            w = When(tick, Assign(v.symbol, sp.Integer(1)))
            w.origin, w.origin_class, w.pulse = eq.component, eq.component_class, True
            flat.whens.append(w)
            continue
        if value.has(Sample):
            raise DiscreteVariableError(
                f"equation '{eq.text}' in {eq.where}: sample() is a value only as the "
                "whole right-hand side of a Boolean variable's equation, "
                "ac.Eq(y, ac.sample(start, period)) (true at each tick), or as the "
                "whole condition of a when-clause")
        own = value.xreplace({q: sp.Integer(0) for q in value.atoms(pre)})
        if v.symbol in own.free_symbols:
            name = _shown(v)
            raise DiscreteVariableError(
                f"equation '{eq.text}' in {eq.where}: the {_type_name(v)} variable "
                f"'{name}' is read on its own right-hand side (at an event its value is "
                f"the expression's); read its value before the event with "
                f"ac.pre({name})")
        w = When(True, Assign(v.symbol, value))
        w.origin, w.origin_class, w.equation = eq.component, eq.component_class, eq.text
        flat.whens.append(w)
    flat.equations[:] = kept


def _tick_of(value):
    """The clock of ``Piecewise((1, sample(...)), (0, True))``, else None."""
    if isinstance(value, sp.Piecewise) and len(value.args) == 2 and \
            isinstance(value.args[0][1], Sample) and value.args[0][0] == 1 \
            and value.args[1][0] == 0:
        return value.args[0][1]
    return None


def _type_name(v) -> str:
    return TYPE_NAMES[getattr(v.attrs, "type", float)]


def _check_target(act, v, w, params, assigned) -> None:
    q = act.variable
    where = f"assign({q.name}, ...) in {_clause_text(w)}"
    if v is None:
        what = "a parameter" if q in params else "not a variable of the model"
        raise DiscreteVariableError(f"{where}: {q.name} is {what}; only a discrete "
                                    "variable can be assigned in a when-clause")
    if not (v.attrs.discrete or _typed(v)):
        raise DiscreteVariableError(
            f"{where}: '{_local(v)}' of {v.where} is not a discrete variable; declare it "
            "ac.Variable(discrete=True) (a port's value: signal={'discrete': True}); a "
            "continuous state is changed with reinit()")
    if q in assigned:
        raise DiscreteVariableError(
            f"{where}: '{_local(v)}' of {v.where} is assigned twice, also in "
            f"{_clause_text(assigned[q])}; a discrete variable has one assignment (give "
            "one clause several conditions, ac.when([c1, c2], ...), and choose the value "
            "with ac.if_else)")


def _substitute(flat, helds) -> None:
    """pre(y) of a discrete y is the symbol pre(y); assignments write held(y)."""
    to_pre = {pre(h.variable): h.pre for h in helds}
    to_held = {h.variable: h.symbol for h in helds}
    for eq in flat.equations + flat.initial_equations:
        if not eq.is_plain() and eq.residual.has(pre):      # (a plain sum holds no pre())
            eq.residual = eq.residual.xreplace(to_pre)
    for w in flat.whens:
        if w.condition.has(pre):
            w.condition = w.condition.xreplace(to_pre)
        for act in w.actions:
            act.value = act.value.xreplace(to_pre)
            if isinstance(act, Assign):
                act.variable = to_held[act.variable]


def pre_after_aliases(reduced, aliases, helds) -> None:
    """pre() of a variable that alias elimination found equal to a discrete variable (an
    input connected to a sampler's output) is that variable's pre value (in place).
    What pre() is left reads a continuous-time variable outside a when-clause's body:
    a :class:`DiscreteVariableError` (:func:`_pre_of_continuous`)."""
    if helds:
        _pre_of_discrete_aliases(reduced, aliases, helds)
    for eq in reduced.equations:
        if not eq.is_plain() and eq.residual.has(pre):
            _pre_of_continuous(eq.residual, f"the equation '{eq.text}' in {eq.where}")
    for w in reduced.whens:
        if w.condition.has(pre):
            _pre_of_continuous(w.condition, f"the condition of {_clause_text(w)}")


def _pre_of_continuous(expr, where):
    """pre(x) of a continuous-time x is defined where x is a discrete-time expression:
    in the body of a when-clause (its value before the event there).  In a continuous
    equation or a when-condition it is not (Modelica Language Specification 3.6, sec.
    3.7.5 with 3.8.5)."""
    names = sorted(sp.sstr(q.args[0]) for q in expr.atoms(pre))
    shown = ", ".join(f"pre({n})" for n in names[:4])
    raise DiscreteVariableError(
        f"{shown} in {where}: {', '.join(names[:4])} "
        f"{'is a continuous-time variable' if len(names) == 1 else 'are continuous-time'}; "
        "pre() reads the value before an event of a discrete variable (discrete=True, "
        "Boolean, Integer), or of any variable inside a when-clause's reinit or assign")


def _pre_of_discrete_aliases(reduced, aliases, helds) -> None:
    to_pre = {}
    by_name = {v.name: v.symbol for v in reduced.variables}
    for h in helds:
        sign, root = aliases.resolve(h.name)
        if root in by_name:
            to_pre[pre(by_name[root])] = sign * h.pre
    for eq in reduced.equations + reduced.initial_equations:
        if eq.residual.has(pre):
            eq.residual = eq.residual.xreplace(to_pre)
    for w in reduced.whens:
        if w.condition.has(pre):
            w.condition = w.condition.xreplace(to_pre)
        for act in w.actions:
            act.value = act.value.xreplace(to_pre)


def explain_overdetermined(err, helds) -> None:
    """Raise a DiscreteVariableError if the structural error ``err`` involves the
    equation ``y = held(y)`` of a discrete variable: something else determines y too."""
    texts = " ".join(list(getattr(err, "equations", [])) + [str(err)])
    for h in helds:
        if f"{h.name} = its value assigned in" in texts:
            raise DiscreteVariableError(
                f"'{h.name}' of {h.where} is a discrete variable, assigned in {h.clause}, "
                "and an equation outside the when-clause determines it as well (the "
                "model is over-determined there): a discrete variable changes only in "
                f"its when-clause.  {err}") from err


# -- the when-clauses as rows of generated code ------------------------------------------
def when_rows(whens, z_syms, caus, pairs, helds, assigned):
    """Rows and layout of the when-clauses (see :class:`~.modelcode.WhenCode`):
    conditions (1/0; 0 for a clock; one row per condition of ``when([c1, c2])``, none
    for the equation of a Boolean or Integer variable, which is evaluated at every
    event), reinit values, assigned values, then start and period of each clock."""
    z_index = {s: k for k, s in enumerate(z_syms)}
    states = set(range(caus.n_states)) if caus.causal else {a for a, _ in pairs}
    slot = {h.symbol: k for k, h in enumerate(helds)}
    conds, cond_owners, always, reinits, targets, owners = [], [], [], [], [], []
    values, slots, assign_owners, clocks, clock_rows = [], [], [], [], []
    for w_i, w in enumerate(whens):
        if w.clock is not None:
            conds.append(sp.Integer(0))
            cond_owners.append(w_i)
            clocks.append(w_i)
            clock_rows += [w.clock.start, w.clock.period]
        elif w.equation is not None:
            always.append(w_i)
        else:
            for c in w.conditions:
                conds.append(sp.Piecewise((1, c), (0, True)))
                cond_owners.append(w_i)
        for act in w.actions:
            if isinstance(act, Assign):
                # relations in a when-equation are evaluated where it fires, not frozen
                # (they generate no events: Modelica 3.6, sec. 8.5); those of the
                # equation of a Boolean or Integer variable generate events
                value = act.value
                if value.has(pre):      # pre() of a continuous variable: its value
                    value = value.replace(lambda e: isinstance(e, pre), lambda e: e.args[0])
                quiet = w.equation is None and value.has(
                    sp.Piecewise, sp.Min, sp.Max, sp.Abs, sp.sign)
                values.append(no_event(value) if quiet else value)
                slots.append(slot[act.variable])
                assign_owners.append(w_i)
                continue
            k = z_index.get(act.variable)
            if k is None or k not in states:
                raise ModelError(f"reinit({act.variable.name}, ...) in {w.origin or '(model)'} "
                                 f"({w.origin_class}): {act.variable.name} is not a state of "
                                 "the model, so it cannot be re-initialized")
            reinits.append(act.value.replace(lambda e: isinstance(e, pre), lambda e: e.args[0]))
            targets.append(k)
            owners.append(w_i)
    levels = assignment_levels(values, slots, assign_owners, helds, whens, z_syms,
                               set(range(len(z_syms))) - states, assigned)
    layout = {"targets": targets, "owners": owners, "assign_slots": slots,
              "assign_owners": assign_owners, "assign_levels": levels, "clocks": clocks,
              "cond_owners": cond_owners, "always": always, "n_clauses": len(whens),
              "pulse_slots": sorted({slot[a.variable] for w in whens if w.pulse
                                     for a in w.actions})}
    return conds + reinits + values + clock_rows, layout


def assignment_levels(values, slots, owners, helds, whens, z_syms, algebraic, assigned):
    """The data-flow level of each assignment: 0 if it reads no discrete variable assigned
    at the same instant, else one more than the level of those it reads (through the
    explicit assignments; a torn algebraic unknown counts as reading every held value the
    model's equations read)."""
    held_syms = {h.symbol: k for k, h in enumerate(helds)}
    expr_of = dict(assigned)
    memo = {}

    def reads(e) -> set:
        out = set()
        for q in e.free_symbols:
            if q in held_syms:
                out.add(held_syms[q])
            elif q in expr_of:
                if q not in memo:
                    memo[q] = set()          # no cycles in the BLT's assignments
                    memo[q] = reads(expr_of[q])
                out |= memo[q]
        return out

    torn = {z_syms[k] for k in algebraic}
    own = {h.variable: k for k, h in enumerate(helds)}
    unknowns = set(z_syms)
    deps = []
    for e in values:
        e = _without_modes(e, expr_of, unknowns)
        d = reads(e)
        for q in _closure(e, expr_of) & torn:
            # a discrete variable solved as an unknown (the full form) reads its own
            # held value; any other unknown solved with them may read any of them
            d |= {own[q]} if q in own else set(held_syms.values())
        deps.append(d)
    by_slot = {s: a for a, s in enumerate(slots)}
    level = [None] * len(values)
    for start in range(len(values)):
        _level_of(start, deps, by_slot, level, [], values, slots, owners, helds, whens)
    return level


def _without_modes(e, expr_of, unknowns):
    """``e`` with its relations on the solver's unknowns replaced by a placeholder: such
    a relation is a mode, frozen between events and switched by the event iteration
    when the unknowns it reads contradict it, so an equation of a Boolean that reads it
    (``off = s < 0 or pre(off) and not fire``, where s depends on off) reads no value
    assigned at the same instant through it (Modelica 3.6, sec. 8.6)."""
    if isinstance(e, no_event):
        return e
    modes = {r: sp.true for r in e.atoms(sp.core.relational.Relational)
             if _closure(r, expr_of) & unknowns}
    return e.xreplace(modes) if modes else e


def _closure(e, expr_of) -> set:
    seen, stack = set(), list(e.free_symbols)
    while stack:
        q = stack.pop()
        if q in seen:
            continue
        seen.add(q)
        if q in expr_of:
            stack.extend(expr_of[q].free_symbols)
    return seen


def _level_of(a, deps, by_slot, level, path, values, slots, owners, helds, whens) -> int:
    if level[a] is not None:
        return level[a]
    if a in path:
        loop = path[path.index(a):] + [a]
        names = " -> ".join(helds[slots[k]].name for k in loop)
        raise DiscreteVariableError(
            "the when-clauses assign discrete variables that read each other at the same "
            f"instant, an algebraic loop ({names}): "
            + "; ".join(_clause_text(whens[owners[k]]) for k in loop[:-1])
            + "; read the value before the instant with pre() to break it")
    path.append(a)
    lv = 0
    for s in sorted(deps[a]):
        b = by_slot.get(s)
        if b is not None:
            lv = max(lv, 1 + _level_of(b, deps, by_slot, level, path, values, slots,
                                       owners, helds, whens))
    path.pop()
    level[a] = lv
    return lv


def reinit_targets_are_states(flat) -> None:
    """A variable that a when-clause re-initializes must be a state (Modelica 3.6, sec.
    8.3.6: tools treat it as stateSelect = always), so state selection keeps it one,
    wherever index reduction could otherwise put the states (the motor side of a gear)."""
    targets = {act.variable for w in flat.whens for act in w.actions
               if isinstance(act, Reinit)}
    if not targets:
        return
    for k, v in enumerate(flat.variables):
        if v.symbol in targets:
            if v.attrs.state_select == "never":
                raise ModelError(f"reinit({v.name}) in {v.where}: the variable has "
                                 "state_select='never', but only a state can be re-initialized")
            flat.variables[k] = replace(v, attrs=replace(v.attrs, state_select="always"))
