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

__all__ = ["check_balance", "zero_causes"]


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


def zero_causes(zeros, components, flat=None) -> str:
    """A sentence naming the parameters given exactly 0 (structural zeros: the terms
    they multiply were removed, derivatives with them) of the ``components`` an error
    is about, or of the model when none of those has one; "" when there are none.
    With the flat model, only those that multiplied a derivative (a state lost: what
    changes the structure), not a temperature coefficient left at its default 0."""
    if flat is not None:
        zeros = [z for z in zeros if _multiplies_derivative(flat, z)]
    if not zeros:
        return ""
    from ...words import listed
    places = {c for c in components if c}
    near = [z for z in zeros if z.rsplit(".", 1)[0] in places
            or any(z.startswith(c + ".") for c in places)]
    named = near or list(zeros)
    where = "of these components " if near else ""
    return (f"the parameters {where}given 0 are structural zeros, which removed the terms "
            f"they multiply (a derivative with them): {listed(named)}; give them a "
            "non-zero value if that is not meant")


def _multiplies_derivative(flat, zero: str) -> bool:
    """Whether the parameter ``zero`` stands in an equation of its component that has a
    derivative (as written: ``V/beta*der(p) = port.q``)."""
    import re
    component, _, local = zero.rpartition(".")
    # named in full (vol.V, as flattening prints it) or by its own name (V)
    word = re.compile(rf"(?<![\w.])({re.escape(zero)}|{re.escape(local)})(?![\w(])")
    for e in flat.equations:
        if e.component == component:
            text = str(e.source)
            if "der(" in text and word.search(text):
                return True
    return False


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
