"""Greedy shrinking of a failing case to a smaller netlist that fails the same way.

Steps, repeated until none applies: drop one element; make a source a single sine of
amplitude 1 (or, where a single sine is not allowed, the zero-slope pair of amplitude
1); set a parameter to 1 in its decade's unit.  A step is kept when the edited netlist
still has the same expectation (case_from_netlist) and ``run`` gives the same
``signature``: the category and the first words of the message.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Callable, Optional

from .harness import Case, Outcome, case_from_netlist
from .netlists import SOURCE_KINDS, Netlist

__all__ = ["shrink", "signature"]


def signature(out: Outcome) -> tuple:
    """What must stay the same while shrinking: the category and the error's type (or,
    for a failed run, the message up to the first digit)."""
    head = out.detail.split(":", 1)[0] if out.detail else ""
    if head.startswith("simulation failed"):
        rest = out.detail.split(":", 2)[1] if out.detail.count(":") else ""
        head += ":" + "".join(ch for ch in rest.split("(")[0] if not ch.isdigit()).strip()
    return out.category, head if out.category != "wrong" else ""


def _edits(net: Netlist):
    """Candidate smaller netlists, most reducing first."""
    els = list(net.elements)
    for i in range(len(els)):
        if els[i].name in net.culprits or (net.extra and els[i].name == net.extra[0]):
            continue
        yield net.with_elements(els[:i] + els[i + 1:])
    for i, el in enumerate(els):
        if el.kind in SOURCE_KINDS:
            # simpler waves in order; only ever towards the simpler ones
            f1 = el.terms[0][1]
            simpler = (((1.0, f1),), ((1.0, f1), (-0.5, 2 * f1)))
            for terms in simpler[:simpler.index(el.terms) if el.terms in simpler else 2]:
                yield net.with_elements(els[:i] + [replace(el, terms=terms)] + els[i + 1:])
            if el.realize == "signal" and len(el.terms) == 1:
                yield net.with_elements(els[:i] + [replace(el, realize="library")] + els[i + 1:])
        elif el.value is not None and el.kind != "gear":
            simple = "1e" + el.value.split("e")[1]
            if el.value != simple:
                yield net.with_elements(els[:i] + [replace(el, value=simple)] + els[i + 1:])


def shrink(case: Case, outcome: Outcome, run: Callable[[Case], Outcome],
           budget: int = 200, log: Optional[Callable[[str], None]] = None) -> Case:
    """The smallest case found (within ``budget`` runs) that fails like ``outcome``."""
    target, runs = signature(outcome), 0
    improved = True
    while improved and runs < budget:
        improved = False
        for net in _edits(case.net):
            smaller = case_from_netlist(net)
            if smaller is None:
                continue
            runs += 1
            out = run(smaller)
            if signature(out) == target:
                case, improved = smaller, True
                if log:
                    log(f"  shrunk to {len(net.elements)} elements: {out.detail[:100]}")
                break
            if runs >= budget:
                break
    return case
