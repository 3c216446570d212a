"""The library as data: its domains, and each component's ports and parameters.

What ``acausal list`` prints, and what a documentation page or a notebook can show:
read from the classes (their docstrings, declared ports and parameters), never from a
hand-kept table.
"""
from __future__ import annotations

import importlib

__all__ = ["library_domains", "describe_domain", "port_domain"]


def library_domains() -> list:
    """The domain packages of ``acausal.library``, alphabetically (not ``examples``)."""
    import pkgutil

    from .. import library
    return sorted(m.name for m in pkgutil.iter_modules(library.__path__)
                  if m.ispkg and m.name != "examples")


def describe_domain(domain: str) -> dict:
    """``{"doc", "components": {name: {"module", "doc", "ports", "parameters"}}}`` for the
    Component classes a domain exports (its ``__all__``, in that order; ports excluded)."""
    from ..components import Component, Port
    package = importlib.import_module(f"{__package__}.{domain}")
    components = {}
    for name in getattr(package, "__all__", ()):
        cls = getattr(package, name, None)
        if isinstance(cls, type) and issubclass(cls, Component) and not issubclass(cls, Port):
            components[name] = {"module": cls.__module__, "doc": _first_line(cls),
                                "ports": _ports(cls), "parameters": _parameters(cls)}
    return {"doc": _first_line(package), "components": components}


def _first_line(obj) -> str:
    """The docstring's first paragraph on one line (without the colon that introduces
    the equations after it)."""
    paragraph = (obj.__doc__ or "").strip().split("\n\n")[0]
    return " ".join(paragraph.split()).rstrip(":")


def _class_attributes(cls, kind) -> dict:
    """Class attributes of type ``kind`` over the MRO, base classes first (declaration
    order, as the component sees them)."""
    out = {}
    for klass in reversed(cls.__mro__):
        for name, value in vars(klass).items():
            if isinstance(value, kind):
                out[name] = value
    return out


def _ports(cls) -> list:
    from ..components import Port
    try:
        # an instance also has the ports its __init__ creates
        found = {n: c for n, c in cls().children().items() if isinstance(c, Port)}
    except Exception:          # noqa: BLE001 - needs arguments: the declared ports only
        found = _class_attributes(cls, Port)
    return [{"name": n, "type": type(p).__name__, "domain": port_domain(type(p))}
            for n, p in found.items()]


def port_domain(port_cls) -> str:
    """The physical domain of a port class, from the connector it derives from."""
    from .. import ports
    table = ((ports.Pin, "electrical"), (ports.RotationalFlange, "rotational"),
             (ports.TranslationalFlange, "translational"), (ports.Frame, "planar"),
             (ports.FluidPort, "hydraulic"), (ports.GasPort, "gas"),
             (ports.NormalizedGasPort, "gas (normalized)"), (ports.HeatPort, "thermal"),
             (ports.FlowPort, "fluid heat flow"),
             (ports.RealInput, "signal in"), (ports.RealOutput, "signal out"))
    for base, domain in table:
        if issubclass(port_cls, base):
            return domain
    return port_cls.__name__


def _parameters(cls) -> list:
    from ..components import Parameter, ref
    out = []
    for n, p in _class_attributes(cls, Parameter).items():
        v = p.value
        if isinstance(v, ref):
            default = f"{v.name} (of the enclosing component)"
        elif callable(v) and not isinstance(v, (int, float)):
            default = "(computed from other parameters)"
        elif v is None:
            default = "(none)"
        else:                  # a number (JSON keeps it one), or an expression's text
            try:
                default = float(v)
            except (TypeError, ValueError):
                default = str(v)
        out.append({"name": n, "default": default, "unit": p.unit,
                    "description": p.description})
    return out
