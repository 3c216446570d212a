"""Balance check: as many equations as unknowns, and a perfect structural matching.

Counting follows Modelica: an unknown is a variable together with its derivatives (a
derivative chain), so ``der(x) = v`` and ``m*der(v) = f`` count as two equations for
the two unknowns x and v.  When the model is not balanced, the Dulmage-Mendelsohn
decomposition (:func:`acausal.compiler.structure.matching.diagnose`) names the equations that
are too many and the variables that nothing determines, with their components.
"""
from __future__ import annotations

from dataclasses import replace

from ..structure.graph import Structure
from ..structure.matching import check_structure
from ...errors import StructuralError
from ...words import zero_causes

__all__ = ["check_balance"]


def check_balance(system, structure: Structure, flat, aliases=None, n_flat=None) -> None:
    """Raise Over-/UnderdeterminedModel or StructurallySingular, naming the user's terms.

    The message counts the whole model first (as written, before alias elimination) and
    lists the trivial equations that alias elimination removed for the variables named,
    so an equation the user wrote is never silently missing from the explanation.
    """
    named = _with_components(system, structure)
    try:
        check_structure(named)
    except StructuralError as err:
        extra = ""
        if n_flat is not None:
            extra += (f"\n  the model as written has {n_flat[0]} equations for "
                      f"{n_flat[1]} variables")
        involved = set(getattr(err, "variables", []) or [])
        removed = _removed_for(aliases, involved)
        if removed:
            extra += "\n  trivial equations already used for these variables: " + "; ".join(removed)
        zeros = zero_causes(getattr(flat, "structural_zeros", ()),
                            [n.split(" [")[1].split(" (")[0] for n in involved if " [" in n],
                            flat)
        if zeros:
            extra += f"\n  {zeros}"
        err.args = (str(err) + extra,) + err.args[1:]
        raise


def _removed_for(aliases, involved_names) -> list:
    if aliases is None:
        return []
    bases = {n.split(" [")[0] for n in involved_names}
    out = []
    for eq in aliases.removed:
        names = {s.name for s in eq.residual.free_symbols}
        if names & bases or any(aliases.resolve(n)[1] in bases for n in names):
            out.append(f"{eq.text} [{eq.where}]")
    return out[:10]


def _with_components(system, s: Structure) -> Structure:
    """A copy of s whose variable names also say which component declares them."""
    names = []
    for sym, info in zip(system.symbols, system.base_infos()):
        hint = _port_hint(info)
        names.append(f"{sym.name} [{info.where}]" + (f" -- {hint}" if hint else ""))
    return replace(s, var_names=names)


def _port_hint(info) -> str:
    return info.hint
