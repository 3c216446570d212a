"""The index report: what the compiler did to the user's equations, in their names.

``compiled.report`` prints as text (``print(report)``), converts to a dict / JSON
(``report.as_dict()``) and draws the incidence with its BLT ordering as Graphviz DOT
text (``report.to_dot()``) or with matplotlib (``report.plot()``).

A pickled report (a saved or cached model) keeps everything it prints, converts and
draws, as plain data: the alias table as an :class:`AliasSummary`, the conversion as
its dict; the compiler's intermediate ``reduction`` (integer structures, sympy
equations) is not kept.  Unpickling it needs no sympy.

Two parts are made when first read, not by the compile: the texts of the equations
(``equations``) and the index of the equations as written (``sigma`` and
``differential_index``: Pantelides and the Sigma-method on the whole flat model, a
tenth of a large model's build).  Pickling a report makes both (a cached model's report
is plain data); computing the index later from a pickle would need the flat model's
incidence and the text of each of its equations, which cost more to make than the index.
"""
from __future__ import annotations

import json
import textwrap
from collections.abc import Sequence
from dataclasses import dataclass, field
from .structure.causalize import FILL_LIMIT
from .structure.graph import UNASSIGNED

__all__ = ["IndexReport", "AliasSummary", "EquationNames", "mode_structures"]


@dataclass
class AliasSummary:
    """The alias table as plain data: ``aliases[name] = (sign, representative)``,
    ``constants[name]`` the text of a constant value, and the equation counts."""

    aliases: dict = field(default_factory=dict)
    constants: dict = field(default_factory=dict)
    equations_before: int = 0
    equations_after: int = 0

    def resolve(self, name: str):
        return self.aliases.get(name, (1, name))

    @classmethod
    def of(cls, table) -> "AliasSummary":
        if table is None or isinstance(table, cls):
            return table
        return cls({k: (int(s), str(r)) for k, (s, r) in table.aliases.items()},
                   {k: str(v) for k, v in table.constants.items()},
                   table.equations_before, table.equations_after)


@dataclass
class IndexReport:
    model_name: str
    timings: dict = field(default_factory=dict)
    counts: dict = field(default_factory=dict)
    aliases: object = None
    reduction: object = None
    differential_index: int = 0     # of the model as written (before alias elimination)
    index_after_alias: int = 0
    equations: list = field(default_factory=list)      # per equation of the reduced system
    states: list = field(default_factory=list)
    dummy_derivatives: list = field(default_factory=list)
    state_sets: list = field(default_factory=list)
    blocks: list = field(default_factory=list)
    kept_for_fill: list = field(default_factory=list)   # names (causalize._bound_fill)
    sigma: dict = field(default_factory=dict)
    conversion: object = None       # compiler.conversion.ConversionResult
    notes: list = field(default_factory=list)
    # per component with modes (a ``mode_structure()`` method): path, class and, per
    # mode, the relations that select it and what determines its unknowns there
    modes: list = field(default_factory=list)
    units: object = None            # compiler.unitcheck.UnitCheck
    derived_parameters: dict = field(default_factory=dict)   # name -> (binding, value)
    # the parameters found by initialization (fixed=False): name -> start (the guess)
    initial_parameters: dict = field(default_factory=dict)
    # the variables held between events (Boolean, Integer, discrete Real): name, type
    # and what sets them (an equation evaluated at every event, or a when-clause)
    discrete: list = field(default_factory=list)

    def __getstate__(self):
        self.equations                 # noqa: B018  (prints the texts not printed yet)
        self.sigma                     # noqa: B018  (the index as written, if not yet)
        state = dict(self.__dict__)
        state["aliases"] = AliasSummary.of(self.aliases)
        state["reduction"] = None
        if self.conversion is not None and not isinstance(self.conversion, dict):
            state["conversion"] = _conversion_dict(self.conversion)
        return state

    def count(self, stage: str, **numbers) -> None:
        self.counts[stage] = numbers

    def fill(self, system, reduction, compiled) -> None:
        """Collect the per-equation and per-variable facts after all passes ran
        (``compiled`` is the ModelCode the passes produced)."""
        s = reduction.structure
        names = [sym.name for sym in system.symbols]
        self.index_after_alias = reduction.index
        conv = self.conversion
        after = None
        if conv is not None and conv.changed:
            # the structural index of the equations as written is not their index: the
            # converted system's is (Pantelides on it, cross-checked by Sigma below)
            after = {"index_sigma": conv.sigma.index, "dof": conv.sigma.dof,
                     "c": conv.sigma.c,
                     "agrees": conv.sigma.index == reduction.index
                     and list(conv.sigma.c) == list(reduction.diff_counts)}
            self.notes += conv.notes()
        if "_as_written" in self.__dict__:
            self.__dict__["_as_written_after"] = (reduction.index, after)
        else:
            _index_from(self, self.sigma, reduction.index, after)
        if conv is not None and conv.numeric_blocks:
            self.notes.append(
                f"{len(conv.numeric_blocks)} block(s) of the Sigma-method's system Jacobian "
                "depend on the variables, so their regularity is not decided at compile "
                "time (a check at the initial point can evaluate them): "
                + "; ".join("[" + ", ".join(b.variables[:4])
                            + (" ..." if len(b.variables) > 4 else "") + "]"
                            for b in conv.numeric_blocks[:10])
                + (" ..." if len(conv.numeric_blocks) > 10 else ""))
        for level, before, after in getattr(reduction.selection, "numeric_changes", []):
            self.notes.append(
                f"dummy derivatives at level {level}: the structural choice "
                f"{', '.join(names_of(system, before))} has a singular constant coefficient "
                f"matrix; chosen by exact rank instead: {', '.join(names_of(system, after))}")
        # every equation's text ("text": None here) is printed when the rows are first
        # read (_rows_with_texts): most reports of a large model are never shown
        self.equations = [{
            "index": k, "text": None, "label": _label(system, eq),
            "component": eq.component,
            "kind": eq.kind, "order": eq.order,
            "derivative_of": eq.derivative_of,
            "differentiated": _times_differentiated(s, k),
        } for k, eq in enumerate(system.equations)]
        self.__dict__["_texts_of"] = system
        self.states = [names[v] for v in reduction.states]
        self.dummy_derivatives = [names[v] for v in reduction.dummies]
        self.state_sets = [{"level": ss.level,
                            "candidates": [names[c] for c in ss.candidates],
                            "n_dummies": ss.n_dummies,
                            "constraints": [system.equations[r].name(system)
                                            for r in ss.equations]}
                           for ss in reduction.selection.state_sets]
        if self.state_sets:
            self.notes.append(
                "the choice of dummy derivatives is only valid locally (coefficients that "
                "depend on the variables, listed as dynamic state sets): the states are "
                "re-chosen at run time where the constraint Jacobian calls for it")
        self._names = names
        self._graph = [list(vs) for vs in s.graph]
        rel = compiled.relations
        self.counts["solver"] = {
            "unknowns": len(compiled.names),
            "states": len(compiled.state_z) + len(compiled.pairs) - len(compiled.dummies),
            "zero_crossings": rel.n_relations + 2 * rel.n_discrete}

    # -- output --------------------------------------------------------------------------
    def as_dict(self) -> dict:
        return {
            "model": self.model_name,
            "differential_index": self.differential_index,
            "index_after_alias": self.index_after_alias,
            "counts": self.counts,
            "aliases_removed": (self.aliases.equations_before - self.aliases.equations_after)
            if self.aliases else 0,
            "equations": self.equations,
            "states": self.states,
            "dummy_derivatives": self.dummy_derivatives,
            "state_sets": self.state_sets,
            "blocks": self.blocks,
            "kept_for_fill": getattr(self, "kept_for_fill", []),
            "sigma": self.sigma,
            "modes": getattr(self, "modes", []),
            "conversion": _conversion_dict(self.conversion),
            "timings_s": self.timings,
            "notes": self.notes,
            "units": self.units.as_dict() if self.units is not None else None,
            "derived_parameters": {k: {"binding": b, "value": v}
                                   for k, (b, v) in self.derived_parameters.items()},
            "discrete_variables": list(getattr(self, "discrete", [])),
            "initial_parameters": dict(getattr(self, "initial_parameters", {})),
        }

    def blt_order(self) -> tuple[list, list]:
        """Equations and variables in BLT order (rows and columns of the picture)."""
        eqs = [e for b in self.blocks for e in b["equations"]]
        vars_ = [v for b in self.blocks for v in b["variables"]]
        return eqs, vars_

    def to_dot(self) -> str:
        """Graphviz DOT text: one node per BLT block, edges from the blocks it needs."""
        owner = {v: k for k, b in enumerate(self.blocks) for v in b["variables"]}
        lines = [f'digraph "{self.model_name}" {{', "  rankdir=LR;", "  node [shape=box];"]
        for k, b in enumerate(self.blocks):
            label = ", ".join(self._names[v] for v in b["variables"][:4])
            label += " ..." if len(b["variables"]) > 4 else ""
            style = ' style=filled fillcolor="#f4c7c3"' if b.get("torn") else ""
            lines.append(f'  b{k} [label="{k}: {label}\\n({b["size"]} eq, {b["solved"]})"{style}];')
        for k, b in enumerate(self.blocks):
            needs = {owner[v] for e in b["equations"] for v in self._graph[e]
                     if v in owner and owner[v] != k}
            lines += [f"  b{j} -> b{k};" for j in sorted(needs)]
        return "\n".join(lines + ["}"])

    def plot(self, ax=None, path=None):
        """The incidence matrix in BLT order with the blocks outlined (matplotlib)."""
        import matplotlib          # an optional dependency (the plot extra), used here only
        if path is not None:
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.patches import Rectangle
        eqs, vars_ = self.blt_order()
        col = {v: j for j, v in enumerate(vars_)}
        pts = [(i, col[v]) for i, e in enumerate(eqs) for v in self._graph[e] if v in col]
        if ax is None:
            size = min(12, 3 + 0.25 * len(vars_))
            _, ax = plt.subplots(figsize=(size, size))
        if pts:
            ax.scatter([j for _, j in pts], [i for i, _ in pts], s=12, marker="s", c="k")
        k = 0
        for b in self.blocks:
            n = b["size"]
            ax.add_patch(Rectangle((k - 0.5, k - 0.5), n, n, fill=False,
                                   ec="tab:red" if b.get("torn") else "tab:blue"))
            k += n
        ax.set_xticks(range(len(vars_)), [self._names[v] for v in vars_], rotation=90, fontsize=7)
        ax.set_yticks(range(len(eqs)), [str(e) for e in eqs], fontsize=7)
        ax.invert_yaxis()
        ax.set_title(f"{self.model_name}: incidence in BLT order (red: torn blocks)")
        if path is not None:
            ax.figure.savefig(path, dpi=120, bbox_inches="tight")
        return ax

    def to_json(self, **kw) -> str:
        return json.dumps(self.as_dict(), default=str, **kw)

    def __str__(self) -> str:
        lines = [f"Index report for {self.model_name}",
                 f"  differential index: {self.differential_index}"
                 + (f" (after alias elimination: {self.index_after_alias})"
                    if self.index_after_alias != self.differential_index else "")]
        lines.append("  equations / variables after each pass:")
        for stage, c in self.counts.items():
            lines.append("    " + f"{stage:<16}" + ", ".join(f"{k} {v}" for k, v in c.items()))
        diffed = [e for e in self.equations if e["differentiated"] and e["order"] == 0]
        if diffed:
            lines.append("  differentiated equations (Pantelides):")
            for e in diffed:
                lines += _wrapped(f"    {e['differentiated']}x  ", e["text"])
        lines.append("  states: " + (", ".join(self.states) or "(none)"))
        if self.dummy_derivatives:
            lines.append("  dummy derivatives: " + ", ".join(self.dummy_derivatives))
        for ss in self.state_sets:
            lines.append(f"  dynamic state set (level {ss['level']}): {ss['n_dummies']} dummy "
                         f"derivative(s) chosen at run time among {', '.join(ss['candidates'])}")
        if self.blocks:
            sizes = [b["size"] for b in self.blocks]
            torn = sum(1 for b in self.blocks if b.get("torn"))
            lines.append(f"  BLT: {len(sizes)} blocks, largest {max(sizes)}, {torn} torn")
        kept = getattr(self, "kept_for_fill", [])
        if kept:
            lines.append(f"  fill: {len(kept)} assigned variable(s) kept as unknowns (gradient "
                         f"over {FILL_LIMIT} entries and its equation's), e.g. "
                         + ", ".join(kept[:3]))
        if self.sigma.get("error"):
            lines.append(f"  cross-check of the model as written failed: {self.sigma['error']}")
        elif self.sigma.get("hidden"):
            after = self.sigma["after_conversion"]
            lines.append(f"  the equations as written look like index "
                         f"{self.sigma['index_sigma']} with {self.sigma['dof']} degrees of "
                         "freedom to the structural analysis, but hide a singular constant "
                         "coefficient matrix (notes below)")
            lines.append(f"  cross-check after conversion, Pryce's Sigma-method: index "
                         f"{after['index_sigma']}, {after['dof']} degrees of freedom; "
                         + ("agrees with Pantelides" if after["agrees"]
                            else "DISAGREES with Pantelides"))
        elif self.sigma:
            lines.append(f"  cross-check, Pryce's Sigma-method: index {self.sigma['index_sigma']}, "
                         f"{self.sigma['dof']} degrees of freedom; "
                         + ("agrees with Pantelides" if self.sigma["agrees"] else
                            "DISAGREES with Pantelides on: "
                            + ", ".join(self.sigma["disagreements"]) +
                            " (hidden cancellation or a structural singularity?)"))
            if self.sigma["dof"] != len(self.states) and not self.state_sets:
                lines.append(f"  note: the Sigma-method counts {self.sigma['dof']} degrees "
                             "of freedom in the equations as written; the model has "
                             f"{len(self.states)} states after alias elimination, structural "
                             "zeros and index reduction")
        for comp in getattr(self, "modes", []):      # (a report pickled before modes)
            lines.append(f"  modes of {comp['component']} ({comp['class']}), the first "
                         "whose relation holds:")
            for m in comp["modes"]:
                lines.append(f"    {m['mode']:<15}[{m['when']}]  {m['structure']}")
        held = getattr(self, "discrete", [])
        if held:
            lines.append("  variables held between events (changed only at events):")
            for d in held[:50]:
                lines += _wrapped(f"    {d['name']} ({d['type']}): ", d["set_by"])
            if len(held) > 50:
                lines.append(f"    ... ({len(held) - 50} more)")
        found = getattr(self, "initial_parameters", {})
        if found:
            lines.append("  parameters found by initialization (fixed=False), with their "
                         "start (Newton's guess):")
            lines += [f"    {name} (start {start:.6g})" for name, start in found.items()]
        if self.derived_parameters:
            lines.append("  derived parameters (bound to other parameters):")
            for name, (binding, value) in self.derived_parameters.items():
                lines += _wrapped(f"    {name} = ", f"{binding} = " + (
                    f"{value:.6g}" if value is not None else
                    "(follows a parameter found by initialization)"))
        if self.units is not None:
            lines += _wrapped("  ", self.units.summary())
        for note in self.notes:
            lines.append(f"  note: {note}")
        total = sum(self.timings.values())
        lines.append(f"  compile time: {total:.3f} s")
        return "\n".join(lines)


def _rows_with_texts(report) -> list:
    """``report.equations``: the rows, their texts printed on the first read (from the
    symbolic system :meth:`IndexReport.fill` left, which is then let go)."""
    system = report.__dict__.pop("_texts_of", None)
    rows = report.__dict__["equations"]
    if system is not None:
        for row, eq in zip(rows, system.equations):
            row["text"] = eq.name(system)
    return rows


def _set_rows(report, rows) -> None:
    report.__dict__.pop("_texts_of", None)
    report.__dict__["equations"] = rows


# a property over the dataclass field (whose __init__, comparison and repr go through it)
IndexReport.equations = property(_rows_with_texts, _set_rows,
                                 doc="per equation of the reduced system: index, text, "
                                     "label, component, kind, order, derivative_of, "
                                     "differentiated")


def _settle(report) -> None:
    """The index as written, computed on the first read of ``sigma`` or
    ``differential_index`` from what :meth:`IndexReport.written_by` left (the compile
    does not compute it: most reports are never read)."""
    compute = report.__dict__.pop("_as_written", None)
    if compute is None:
        return
    after = report.__dict__.pop("_as_written_after", None)
    report.__dict__["sigma"] = sigma = compute()
    if after is not None:                       # IndexReport.fill ran
        _index_from(report, sigma, *after)


def _index_from(report, sigma, index_after_alias, after) -> None:
    """The differential index the report gives: that of the equations as written, unless
    the conversion found it hidden (``after``: the converted system's cross-check)."""
    report.__dict__["differential_index"] = sigma.get("index_pantelides", index_after_alias)
    if after is not None:
        report.__dict__["differential_index"] = index_after_alias
        sigma["hidden"] = True
        sigma["after_conversion"] = after


def _settled(name):
    def get(report):
        _settle(report)
        return report.__dict__[name]

    def put(report, value):
        _settle(report)
        report.__dict__[name] = value
    return property(get, put)


def _written_by(self, compute) -> None:
    """``compute()`` (no arguments) gives :func:`acausal.compiler.index.as_written`'s
    dict; it is called when the report is first read."""
    self.__dict__.pop("_as_written_after", None)
    self.__dict__["_as_written"] = compute


IndexReport.written_by = _written_by
IndexReport.sigma = _settled("sigma")
IndexReport.differential_index = _settled("differential_index")


class EquationNames(Sequence):
    """The names (``SymbolicEquation.name``) of the equations ``rows`` of ``system``, as a
    read-only list printed on its first read; it pickles as a plain list."""

    def __init__(self, system, rows):
        self._system, self._rows, self._names = system, list(rows), None

    def _list(self) -> list:
        if self._names is None:
            system = self._system
            self._names = [system.equations[e].name(system) for e in self._rows]
            self._system = None
        return self._names

    def __getitem__(self, k):
        return self._list()[k]

    def __iter__(self):
        return iter(self._list())

    def __len__(self) -> int:
        return len(self._rows)

    def __eq__(self, other):
        return list(self) == (list(other) if isinstance(other, Sequence) else other)

    __hash__ = None

    def __repr__(self) -> str:
        return repr(self._list())

    def __reduce__(self):
        return list, (self._list(),)


def _conversion_dict(conv):
    if conv is None or isinstance(conv, dict):      # a loaded report keeps the dict
        return conv
    return {"conversions": [{"replaced": c.replaced, "text": c.text,
                             "terms": [list(t) for t in c.terms], "cancelled": c.columns,
                             "parameter_dependent": c.parameter_dependent,
                             "value_before": c.value_before, "value_after": c.value_after}
                            for c in conv.conversions],
            "index": conv.index, "dof": conv.sigma.dof if conv.sigma else None,
            "numeric_blocks": [{"equations": b.equation_names, "variables": b.variables}
                               for b in conv.numeric_blocks],
            "error": conv.error}


WIDTH = 100      # the text report wraps at this width; it never cuts an equation


def _wrapped(first: str, text: str) -> list:
    """``first + text`` as lines of at most WIDTH characters where it can break, the
    continuation lines indented under the text (no character of it is dropped)."""
    return textwrap.wrap(text, WIDTH, initial_indent=first,
                         subsequent_indent=" " * len(first), break_long_words=False,
                         break_on_hyphens=False) or [first]


def _label(system, eq):
    """The user's label of the equation an equation of the system derives from."""
    while eq.derivative_of is not None:
        eq = system.equations[eq.derivative_of]
    return eq.label


def names_of(system, variables) -> list:
    return [system.symbols[v].name for v in variables]


def _times_differentiated(s, e) -> int:
    k = 0
    while e < len(s.eq_to_diff) and s.eq_to_diff[e] is not UNASSIGNED:
        e = s.eq_to_diff[e]
        k += 1
    return k


def mode_structures(model) -> list:
    """The modes of every component that describes them (``mode_structure()``), in
    declaration order, for the index report."""
    out, stack = [], [model]
    while stack:
        comp = stack.pop()
        describe = getattr(comp, "mode_structure", None)
        if callable(describe):
            out.append({"component": comp.path, "class": type(comp).__name__,
                        "modes": describe()})
        stack.extend(reversed([c for c in comp.children().values()
                               if hasattr(c, "children")]))
    return out
