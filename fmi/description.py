"""modelDescription.xml of an exported model (FMI 2.0, sec. 2.2 of the standard).

Variables, in the order of their value references: the tunable parameters
(causality parameter, variability tunable, start, unit, description, min/max where the
library has them), the top-level inputs, the top-level outputs, then every other
variable of the model by its dotted name (causality local; the states and their
derivatives among them, the derivative marked with ``derivative=``).  A variable whose
start value is one of the initial conditions (``s = start`` of a state, a ``fixed=True``
start) has ``initial="exact"`` and that start value, which the importer may set before
initialization; the others are ``calculated``.  ``ModelStructure``
lists the outputs, the derivatives and the initial unknowns with their structural
dependencies (:mod:`.structure`).
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

__all__ = ["FmiVariable", "model_description", "naming_convention"]

_STRUCTURED = re.compile(r"^(der\()?[A-Za-z_][A-Za-z0-9_]*(\[\d+(,\d+)*\])?"
                         r"(\.[A-Za-z_][A-Za-z0-9_]*(\[\d+(,\d+)*\])?)*(?(1)\))$")


@dataclass
class FmiVariable:
    """One scalar variable (Real, Boolean or Integer: ``type``); ``kind``/``index``/
    ``sign``/``value`` say where the C code takes its value from (fmi/acausal_fmu.h:
    AC_PARAM, AC_EXPAND, AC_CONST, AC_DERIV); a Boolean's value is 1 or 0."""

    name: str
    kind: int
    index: int = 0
    sign: float = 1.0
    value: float = 0.0
    causality: str = "local"
    variability: str = "continuous"
    initial: str | None = None
    start: float | None = None
    unit: str = ""
    description: str = ""
    minimum: float | None = None
    maximum: float | None = None
    derivative: int | None = None       # 1-based index of the state this is der() of
    start_slot: int = -1                # a settable start value: its initial row
    deps: list = field(default_factory=list)         # ModelStructure (1-based indices)
    init_deps: list = field(default_factory=list)
    type: str = "Real"                  # "Real", "Boolean" or "Integer"


def naming_convention(names) -> str:
    """``structured`` when every name is a Modelica-like dotted name, else ``flat``."""
    return "structured" if all(_STRUCTURED.match(n) for n in names) else "flat"


def _number(x: float) -> str:
    x = float(x)
    if x != x:
        return "NaN"
    if x in (float("inf"), float("-inf")):     # xs:double's spelling
        return "INF" if x > 0 else "-INF"
    return repr(x)


def _typed(x, kind: str) -> str:
    """A start, min or max value as the XML of its type writes it."""
    if kind == "Boolean":
        return "true" if float(x) > 0.5 else "false"
    if kind == "Integer":
        return str(int(round(float(x))))
    return _number(x)


def model_description(*, model_name, identifier, guid, fmi_type, variables, n_indicators,
                      description, default, sources) -> str:
    """The XML text; ``default``: DefaultExperiment attributes, ``sources``: the C files."""
    root = ET.Element("fmiModelDescription", {
        "fmiVersion": "2.0", "modelName": model_name, "guid": guid,
        "description": description, "generationTool": "acausal",
        "variableNamingConvention": naming_convention(v.name for v in variables),
        "numberOfEventIndicators": str(n_indicators)})
    attrs = {"modelIdentifier": identifier, "canGetAndSetFMUstate": "false",
             "canSerializeFMUstate": "false", "providesDirectionalDerivative": "false",
             "canNotUseMemoryManagementFunctions": "true"}
    if fmi_type == "ModelExchange":
        # completedIntegratorStepNotNeeded is false: fmi2CompletedIntegratorStep releases
        # the indicators of items armed at zero (modes.c, ac_release)
        kind = ET.SubElement(root, "ModelExchange", attrs)
    else:
        kind = ET.SubElement(root, "CoSimulation", {
            **attrs, "canHandleVariableCommunicationStepSize": "true",
            "canInterpolateInputs": "false", "maxOutputDerivativeOrder": "0"})
    files = ET.SubElement(kind, "SourceFiles")
    for name in sources:
        ET.SubElement(files, "File", {"name": name})
    units = sorted({v.unit for v in variables if v.unit})
    if units:
        defs = ET.SubElement(root, "UnitDefinitions")
        for u in units:
            ET.SubElement(defs, "Unit", {"name": u})
    ET.SubElement(root, "DefaultExperiment", {k: _number(v) for k, v in default.items()})
    mv = ET.SubElement(root, "ModelVariables")
    counts = {"Real": 0, "Boolean": 0, "Integer": 0}
    for v in variables:
        # value references count per type (FMI 2.0, sec. 2.2.7): the C engine keeps the
        # Real variables first, then the Boolean, then the Integer ones
        vr = counts[v.type]
        counts[v.type] += 1
        a = {"name": v.name, "valueReference": str(vr)}
        if v.description:
            a["description"] = v.description
        a["causality"] = v.causality
        a["variability"] = v.variability
        if v.initial:
            a["initial"] = v.initial
        sv = ET.SubElement(mv, "ScalarVariable", a)
        r = {}
        if v.unit and v.type == "Real":
            r["unit"] = v.unit
        if v.minimum is not None and v.type != "Boolean":
            r["min"] = _typed(v.minimum, v.type)
        if v.maximum is not None and v.type != "Boolean":
            r["max"] = _typed(v.maximum, v.type)
        if v.derivative is not None:
            r["derivative"] = str(v.derivative)
        if v.start is not None:
            r["start"] = _typed(v.start, v.type)
        ET.SubElement(sv, v.type, r)
    ms = ET.SubElement(root, "ModelStructure")
    _unknowns(ms, "Outputs", [(k, v.deps) for k, v in enumerate(variables, 1)
                              if v.causality == "output"])
    _unknowns(ms, "Derivatives", [(k, v.deps) for k, v in enumerate(variables, 1)
                                  if v.derivative is not None])
    states = {v.derivative for v in variables if v.derivative is not None}
    initial = [(k, v.init_deps) for k, v in enumerate(variables, 1)
               if v.causality == "output" or v.derivative is not None
               or (k in states and v.initial != "exact")]
    _unknowns(ms, "InitialUnknowns", initial)
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


def _unknowns(parent, tag, items) -> None:
    if not items:
        return
    el = ET.SubElement(parent, tag)
    for index, deps in items:
        ET.SubElement(el, "Unknown", {"index": str(index),
                                      "dependencies": " ".join(map(str, sorted(deps)))})
