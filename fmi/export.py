"""export_fmu: a model as an FMI 2.0 FMU (Model Exchange or Co-Simulation).

What goes into the FMU (FMI 2.0, sec. 2.3 "FMU distribution"):

* ``modelDescription.xml`` (:mod:`.description`), the GUID a hash of the C sources;
* ``sources/``: ``model.c`` (the generated C of the model, :mod:`acausal.compiler.backends.cbackend`,
  and its data: sizes, the Jacobian patterns, the relations, the variables), the engine
  of this package (``acausal_fmu.h``, ``modes.c``, ``engine.c``, ``discrete.c``,
  ``cosim.c``, ``fmu.c``) and the FMI
  headers that fmpy ships;
* ``binaries/<platform>/<modelIdentifier>.so`` compiled from them with the system C
  compiler (``-O2 -fPIC -ffp-contract=off -shared``, every symbol but the FMI functions
  hidden, so that several FMUs load into one process; the generated model above 200 kB
  of source at ``-O0``, as the C backend does).

The FMU presents the compiled model's index-1 form as an ODE in its states
x = z[state_index]; the other solver unknowns are solved inside by Newton (modes.c).
Parameters and inputs are set through FMI at any time (the model is evaluated again);
the start values that are initial conditions (a state's ``start``, a ``fixed=True``
start) are FMI start values of their variables, set before initialization.  A variable
that alias elimination fixed to a parameter (a port's pressure that is the source's
parameter) follows that parameter; one fixed to another expression of parameters keeps
its value at export.  A model with dynamic state selection has no fixed set of states
and is refused.
A model with top-level ``RealInput`` ports is compiled in the harness of
:mod:`acausal.analysis.plant` (each input driven from a parameter, which the FMI input
variable sets): an input enters the equations as a value; a model whose index reduction
differentiates an input (it needs der(u), which FMI 2.0 Model Exchange does not give)
is refused.
"""
from __future__ import annotations

import hashlib
import math
import os
import re
import shutil
import sys
import tempfile
import uuid
import zipfile

import numpy as np

from .description import FmiVariable, model_description
from .ccode import build_binary, model_c
from .structure import Reads, solved_dependencies
from .. import native
from ..errors import BackendError, InvalidArgument, ModelError

__all__ = ["export_fmu", "FMI_TYPES"]

FMI_TYPES = ("ModelExchange", "CoSimulation")
_SHORT = {"me": "ModelExchange", "cs": "CoSimulation", "modelexchange": "ModelExchange",
          "cosimulation": "CoSimulation"}
ENGINE = ("acausal_fmu.h", "modes.c", "engine.c", "discrete.c", "cosim.c", "fmu.c")
HEADERS = ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h")
AC_PARAM, AC_EXPAND, AC_CONST, AC_DERIV, AC_PAFFINE = 0, 1, 2, 3, 4   # acausal_fmu.h
DEFAULT_RTOL = 1e-6


def export_fmu(model, path, fmi_type: str = "ModelExchange", *, model_name: str | None = None,
               t_end: float | None = None, rtol: float | None = None) -> str:
    """Write ``model`` (a Component or a CompiledModel) as an FMI 2.0 FMU to ``path``.

    ``fmi_type``: ``"ModelExchange"`` or ``"CoSimulation"`` (also ``"me"``, ``"cs"``).
    ``model_name``: the FMU's model name and identifier (default: the model's class).
    ``t_end``: the DefaultExperiment's stop time.  ``rtol``: the DefaultExperiment's
    tolerance (default 1e-6), which the Co-Simulation integrator uses unless the
    importer gives another in fmi2SetupExperiment.  Returns ``path``.

    Raises ValueError for an unknown fmi_type, :class:`acausal.BackendError` without a C
    compiler or the FMI headers (fmpy), :class:`acausal.ModelError` for a model whose
    states are selected dynamically or that uses ``delay()``.
    """
    kind = _fmi_type(fmi_type)
    if rtol is not None and not (0 < float(rtol) < 1):
        raise InvalidArgument(f"export_fmu: rtol must be in (0, 1), got {rtol!r}")
    if t_end is not None and not (math.isfinite(float(t_end)) and float(t_end) > 0):
        raise InvalidArgument(f"export_fmu: t_end must be > 0 and finite, got {t_end!r}")
    cc = native.find_compiler()
    if cc is None:
        raise BackendError("exporting an FMU needs a C compiler (set CC, or install "
                           "cc/gcc/clang)")
    headers = _fmi_headers()
    plant, meta, ports = _compiled(model)
    mc = plant.compiled.model_code
    _static_states(plant.compiled)
    _no_delays(plant.compiled)
    _no_free_parameters(plant.compiled)
    _inputs_not_differentiated(plant, ports)
    name = model_name or (getattr(mc.report, "model_name", None) if ports is None
                          else type(model).__name__) or "Model"
    identifier = re.sub(r"\W", "_", name)
    if not re.match(r"[A-Za-z_]", identifier):
        identifier = "_" + identifier
    variables, layout = _variables(plant, meta, ports)
    source = model_c(mc, plant.compiled.p, layout, variables, rtol or DEFAULT_RTOL)
    here = os.path.dirname(os.path.abspath(__file__))
    texts = {"model.c": source}
    for f in ENGINE:
        with open(os.path.join(here, f)) as fh:
            texts[f] = fh.read()
    guid = "{" + str(uuid.UUID(bytes=hashlib.sha256(
        "".join(texts[k] for k in sorted(texts)).encode()).digest()[:16])) + "}"
    texts["model.c"] = source.replace("@GUID@", guid)
    default = {"startTime": 0.0, "tolerance": float(rtol or DEFAULT_RTOL)}
    if t_end is not None:
        default["stopTime"] = float(t_end)
    xml = model_description(
        model_name=name, identifier=identifier, guid=guid, fmi_type=kind,
        variables=variables, n_indicators=layout["n_indicators"],
        description=_summary(model) if ports is not None else "",
        default=default,
        sources=["model.c", "modes.c", "engine.c", "discrete.c", "cosim.c", "fmu.c"])
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "sources")
        os.makedirs(src)
        for f, text in texts.items():
            with open(os.path.join(src, f), "w") as fh:
                fh.write(text)
        for h in HEADERS:
            shutil.copy(os.path.join(headers, h), os.path.join(src, h))
        platform, ext = _platform()
        binary = os.path.join(tmp, "binaries", platform, identifier + ext)
        os.makedirs(os.path.dirname(binary))
        build_binary(cc, src, binary, len(source))
        with open(os.path.join(tmp, "modelDescription.xml"), "w") as fh:
            fh.write(xml)
        path = os.fspath(path)
        with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
            zf.write(os.path.join(tmp, "modelDescription.xml"), "modelDescription.xml")
            zf.write(binary, f"binaries/{platform}/{identifier}{ext}")
            for f in sorted(os.listdir(src)):
                zf.write(os.path.join(src, f), f"sources/{f}")
    return path


def _summary(model) -> str:
    """The first paragraph of the model class's docstring, on one line."""
    return " ".join((type(model).__doc__ or "").strip().split("\n\n")[0].split())


# -- arguments --------------------------------------------------------------------------------
def _fmi_type(fmi_type) -> str:
    if isinstance(fmi_type, str):
        if fmi_type in FMI_TYPES:
            return fmi_type
        if fmi_type.lower() in _SHORT:
            return _SHORT[fmi_type.lower()]
    raise ValueError(f"fmi_type must be 'ModelExchange' or 'CoSimulation' ('me'/'cs'), "
                     f"got {fmi_type!r}")


def _fmi_headers() -> str:
    try:
        import fmpy
    except ImportError as exc:
        raise BackendError("exporting an FMU needs the FMI 2.0 headers that fmpy ships: "
                           "pip install 'acausal[fmi]'") from exc
    where = os.path.join(os.path.dirname(fmpy.__file__), "c-code")
    if not all(os.path.exists(os.path.join(where, h)) for h in HEADERS):
        raise BackendError(f"the FMI 2.0 headers are missing from fmpy's {where}")
    return where


def _platform() -> tuple[str, str]:
    bits = "64" if sys.maxsize > 2**32 else "32"
    if sys.platform.startswith("linux"):
        return f"linux{bits}", ".so"
    if sys.platform == "darwin":
        return f"darwin{bits}", ".dylib"
    return f"win{bits}", ".dll"


def _compiled(model):
    """(Plant, metadata, (inputs, outputs)) for a Component or a CompiledModel."""
    from ..analysis.plant import Plant, compile_plant, top_level_inputs
    from ..components.component import Component
    from ..ports import BooleanOutput, IntegerOutput, RealOutput
    from ..runtime import CompiledModel
    if isinstance(model, CompiledModel):
        if not _has_programs(model.model_code):
            raise ModelError("this compiled model was loaded (from a pickle, or from a "
                             "compile cache entry that lost its side file) with its "
                             "functions but not the program its C is printed from: "
                             "export the Component instead (it is compiled again)")
        return Plant(model), ({}, {}), None
    if not isinstance(model, Component):
        raise ModelError(f"export_fmu takes a Component or a CompiledModel, got {model!r} "
                         f"({type(model).__name__})")
    inputs = top_level_inputs(model)
    outputs = [n for n, c in model.children().items()
               if isinstance(c, (RealOutput, BooleanOutput, IntegerOutput))]

    def build(cache):
        if inputs:
            return compile_plant(model, {}, cache=cache)
        from ..simulation import compile as compile_model
        return Plant(compile_model(model, backend="numpy", cache=cache))

    plant = build(True)
    if not _has_programs(plant.compiled.model_code):
        # loaded from the compile cache, which keeps the functions but not the Program
        # the FMU's C is printed from: compiled again, past the cache
        plant = build(False)
    return plant, _metadata(model), (inputs, outputs)


def _has_programs(mc) -> bool:
    codes = [mc.code, mc.initial.code] + ([mc.whens.code] if mc.whens is not None else [])
    return all(getattr(c, "program", None) is not None for c in codes)


def _metadata(model):
    """Units and descriptions by flat name, from the declarations of a fresh instance."""
    from ..compiler.frontend.flatten import flatten
    args, kwargs = model._init_call
    flat = flatten(type(model)(*args, **kwargs))
    variables = {v.name: (v.attrs.unit or "", getattr(v.attrs, "description", "") or "")
                 for v in flat.variables}
    params = {p.name: (p.unit or "", p.description or "") for p in flat.parameters}
    return variables, params


def _no_delays(compiled) -> None:
    """An FMU's engine keeps no history of the solution, so delay() cannot run in it."""
    from ..runtime.delays import refuse_delays
    refuse_delays(compiled, "an FMU cannot export delay() (its engine keeps no history "
                            "of the solution)", "Replace FixedDelay by PadeDelay to export")


def _no_free_parameters(compiled) -> None:
    """The FMU's engine initializes the states only: a parameter found by
    initialization (fixed=False) would keep its start there, so it is refused."""
    names = (compiled.meta.get("free_parameters") or {}).get("names")
    if names:
        raise ModelError(f"an FMU cannot export parameters found by initialization "
                         f"(fixed=False): {', '.join(names[:5])}; its engine solves for "
                         "the states only.  Simulate once, then give the value found "
                         "(res.parameter_values) as the parameter's value to export")


def _static_states(compiled) -> None:
    mc = compiled.model_code
    if mc.dynamic is None:
        return
    sets = getattr(mc.report, "state_sets", None) or []
    words = "; ".join(
        f"{len(s['candidates']) - s['n_dummies']} of {{{', '.join(s['candidates'])}}}"
        for s in sets if isinstance(s, dict) and "candidates" in s) or "(see the report)"
    raise ModelError("this model selects its states dynamically, at run time (state sets: "
                     f"{words}); an FMU presents a fixed set of states.  Fix the choice "
                     "with state_select='always' on variables that stay valid states over "
                     "the run (and 'avoid' on the others), then export again")


def _inputs_not_differentiated(plant, ports) -> None:
    """The harness drives an input as u = k + rate (t - t_ref) + accel (t - t_ref)^2/2, so
    at t = t_ref, u = k and der(u) = rate, der(u, 2) = accel: the model's rows change
    with rate or accel there exactly when index reduction differentiated the input."""
    if not ports or not ports[0]:
        return
    compiled = plant.compiled
    code, m = compiled.code, compiled.m.copy()
    z = compiled.start.copy()
    for n in ports[0]:
        names = plant.input_rates.get(n, ())
        if len(names) != 3:
            continue
        rate, accel, t_ref = (compiled.param_names.index(q) for q in names)
        p = compiled.p.copy()
        p[t_ref] = 0.0
        rows = []
        for r, a in ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0)):
            p[rate], p[accel] = r, a
            try:
                with np.errstate(all="ignore"):
                    rows.append(code.residual(0.0, z, p, m, np.empty(code.n_rows)))
            except (ArithmeticError, ValueError):
                return          # the start point is outside the model's domain: no verdict
        if not (np.array_equal(rows[0], rows[1], equal_nan=True)
                and np.array_equal(rows[0], rows[2], equal_nan=True)):
            raise ModelError(f"the model differentiates its input '{n}' (index reduction "
                             f"needs der({n})), which an FMU's input does not provide: "
                             "give the derivative as a second input, or filter the input "
                             "in the model (a first-order block before it)")


# -- variables ----------------------------------------------------------------------------
def _variables(plant, meta, ports):
    """The FMI variables (in value-reference order) and the layout the C data needs."""
    compiled = plant.compiled
    mc = compiled.model_code
    var_meta, par_meta = meta
    inputs, outputs = ports or ([], [])
    pre = plant.prefix
    ours = (lambda n: n.startswith(pre) or n.startswith(f"der({pre}")) if pre else (lambda n: True)
    bounds = mc.meta.get("parameter_bounds", {})
    input_params = {plant.input_params[n]: n for n in inputs}
    variables, by_name, typed = [], {}, []
    types = {**mc.meta.get("value_types", {}), **mc.meta.get("parameter_types", {})}

    def add(v, name=None):
        v.type = types.get(name or v.name, "Real")
        if v.type != "Real":       # after the Real ones (their value references)
            typed.append(v)
            return v
        by_name[v.name] = len(variables)
        variables.append(v)
        return v

    param_var = {}
    for k, name in enumerate(compiled.param_names):
        if name in input_params or not ours(name):
            continue
        ext = plant.external(name)
        unit, desc = par_meta.get(ext, ("", ""))
        lo, hi = bounds.get(name, (None, None))
        param_var[k] = add(FmiVariable(ext, AC_PARAM, k, causality="parameter",
                                       variability="tunable", start=float(compiled.p[k]),
                                       unit=unit, description=desc, minimum=lo, maximum=hi),
                           name)
    own = set()
    input_var = {}
    for n in inputs:
        k = compiled.param_names.index(plant.input_params[n])
        input_var[k] = add(FmiVariable(n, AC_PARAM, k, causality="input", start=0.0,
                                       description="input signal"))
    if compiled.inputs is not None:        # compiled with its top-level inputs
        for n, k, typ, start in zip(compiled.inputs.names, compiled.inputs.slots,
                                    compiled.inputs.types, compiled.inputs.starts):
            types.setdefault(n, typ)
            input_var[int(k)] = add(FmiVariable(n, AC_PARAM, int(k), causality="input",
                                                start=start, description="input signal"))
        own = {f"{n}.signal" for n in compiled.inputs.names}
    own = {f"{n}.signal" for n in inputs + outputs} | (own if compiled.inputs is not None
                                                         else set())
    for n in outputs:
        internal = plant.internal(f"{n}.signal")
        add(_from_output(n, mc.outputs[internal], compiled, "output",
                         *var_meta.get(f"{n}.signal", ("", "")), types.get(internal)),
            internal)
    for name, entry in mc.outputs.items():
        ext = plant.external(name)
        if not ours(name) or ext in own or ext in by_name:
            continue
        add(_from_output(ext, entry, compiled, "local", *var_meta.get(ext, ("", "")),
                         types.get(name)), name)
    state_index = [int(k) for k in compiled.state_index]
    n_sz = len(mc.state_z)
    for i, z in enumerate(state_index):
        sname = plant.external(compiled.names[z])
        j = by_name[sname]
        dname = f"der({sname})"
        if dname in by_name:
            d = variables[by_name[dname]]
            # the model's own der(s) variable: its value is the state derivative
            d.kind, d.index, d.sign, d.initial, d.start = AC_DERIV, i, 1.0, "calculated", None
            d.variability = "continuous"
        else:
            d = add(FmiVariable(dname, AC_DERIV, i, initial=None))
        d.derivative = j + 1
    for kind in ("Boolean", "Integer"):
        for v in typed:
            if v.type == kind:
                by_name[v.name] = len(variables)
                variables.append(v)
    starts = _start_rows(mc)
    for slot, (_, k, value) in enumerate(starts):
        v = variables[by_name.get(plant.external(compiled.names[k]), -1)] \
            if plant.external(compiled.names[k]) in by_name else None
        if v is not None and v.kind == AC_EXPAND and v.sign == 1.0 and v.causality == "local":
            v.initial, v.start, v.start_slot = "exact", value, slot
    layout = {"starts": starts, "state_index": state_index, "n_x": len(state_index),
              "n_p": len(compiled.p),
              "link_d": [int(k) for k in compiled.link_d],
              "alg_index": [k for k in range(compiled.n) if k not in set(state_index)],
              "n_indicators": int(compiled.n_roots), "n_state_z": n_sz}
    _dependencies(mc, layout, variables, param_var, input_var, by_name, plant)
    return variables, layout


def _start_rows(mc) -> list:
    """The kept initial rows ``z[k] - value`` (start values of states, fixed starts):
    ``(position among the kept rows, k, value)``; their value is an FMI start value."""
    import sympy as sp
    prog = mc.initial.code.program
    res = prog.functions["residual"]
    out = []
    for j, row in enumerate(mc.initial.rows):
        e = res[row]
        syms = list(e.free_symbols)
        if len(syms) != 1 or prog.refs.get(syms[0], ("",))[0] != "y":
            continue
        rest = sp.expand(e - syms[0])
        if rest.is_Number:
            out.append((j, prog.refs[syms[0]][1], float(-rest)))
    return out


def _from_output(name, entry, compiled, causality, unit, desc, kind=None) -> FmiVariable:
    sign, where = entry
    if sign is not None:
        # a Boolean or Integer changes only at events: variability discrete
        return FmiVariable(name, AC_EXPAND, int(where), float(sign), causality=causality,
                           variability="discrete" if kind else "continuous",
                           initial="calculated" if causality == "output" else None,
                           unit=unit, description=desc)
    if callable(where):
        # a variable fixed to an expression of parameters (a port's pressure that is a
        # source's parameter): followed in the FMU where it is a p[k] + b; otherwise its
        # value for the parameters at export
        affine = _affine_in_one_parameter(where, compiled.p)
        variability = "tunable" if causality == "local" else "continuous"
        if affine is not None:
            k, a, b = affine
            return FmiVariable(name, AC_PAFFINE, k, a, b, causality=causality,
                               variability=variability, initial="calculated", unit=unit,
                               description=desc)
        value = float(where(compiled.p))
        # said where an importer shows it: not updated when the parameters change
        desc = ((desc + "; ") if desc else "") + "value at export: not updated when " \
            "parameters are set"
        return FmiVariable(name, AC_CONST, value=value, causality=causality,
                           variability="fixed" if causality == "local" else "continuous",
                           initial="calculated", unit=unit, description=desc)
    if causality == "output":
        return FmiVariable(name, AC_CONST, value=float(where), causality=causality,
                           initial="calculated", unit=unit, description=desc)
    return FmiVariable(name, AC_CONST, value=float(where), causality=causality,
                       variability="constant", start=float(where), unit=unit,
                       description=desc)


def _affine_in_one_parameter(f, p):
    """(k, a, b) when f(p) = a p[k] + b with only p[k] mattering (probed at three values
    of each parameter, exact in floating point), else None."""
    p = np.asarray(p, dtype=float)
    f0 = float(f(p))
    found = None
    for k in range(len(p)):
        values = []
        for x in (p[k] + 1.0, 2.0 * p[k] + 3.0):
            q = p.copy()
            q[k] = x
            values.append(float(f(q)))
        if values[0] == f0 and values[1] == f0:
            continue
        if found is not None:
            return None
        a = values[0] - f0
        b = f0 - a * p[k]
        if a * (2.0 * p[k] + 3.0) + b != values[1]:
            return None
        found = (k, a, b)
    return found


def _dependencies(mc, layout, variables, param_var, input_var, by_name, plant) -> None:
    """ModelStructure: each output's and derivative's dependencies on the states and
    inputs; each initial unknown's on the parameters and inputs (:mod:`.structure`)."""
    prog = mc.code.program
    reads = Reads(prog)
    res = prog.functions["residual"]
    n_res, n_z = mc.n_res, len(mc.names)
    g_rows = [reads.of(res[r]) for r in range(n_res)]
    state_set = set(layout["state_index"])
    cont = solved_dependencies(g_rows, layout["alg_index"], n_z)
    init_prog = mc.initial.code.program
    init_reads = Reads(init_prog)
    i_res = init_prog.functions["residual"]
    n_p = layout["n_p"]          # the parameters, then the inputs' values
    i_rows = [init_reads.of(i_res[r]) for r in mc.initial.rows]
    start_var = {}
    for slot, (j, k, _) in enumerate(layout["starts"]):
        i_rows[j] = ({k}, {n_p + slot})          # the start value: a pseudo-parameter
        start_var[n_p + slot] = slot
    init = solved_dependencies(g_rows + i_rows, range(n_z), n_z)
    state_var = {z: by_name[plant.external(mc.names[z])] + 1 for z in layout["state_index"]}
    knowns = {k: by_name[v.name] + 1 for k, v in {**param_var, **input_var}.items()}
    for k, v in enumerate(variables, 1):
        if v.start_slot >= 0:
            knowns[n_p + v.start_slot] = k
    inputs = {k: by_name[v.name] + 1 for k, v in input_var.items()}

    def of_z(zs, ps):
        S, P = set(), set(ps)
        for z in zs:
            if z in state_set:
                S.add(z)
            else:
                S |= cont[z][0]
                P |= cont[z][1]
        return ([state_var[z] for z in S if z in state_var]
                + [inputs[p] for p in P if p in inputs])

    roots = prog.functions.get("roots") or []

    def at_init(zs, ps, ms=()):
        # the relation values read are settled at initialization from the roots' values
        P = set(ps)
        for k in ms:
            if k < len(roots):
                rz, rp = reads.of(roots[k])
                zs, P = set(zs) | rz, P | rp
        for z in zs:
            P |= init[z][1]
        return [knowns[p] for p in P if p in knowns]

    expand = prog.functions.get("expand") or []
    n_sz = layout["n_state_z"]
    for v in variables:
        if v.kind == AC_EXPAND:
            expr = expand[v.index]
        elif v.kind == AC_DERIV and v.index < n_sz:
            expr = res[n_res + v.index]
        elif v.kind == AC_DERIV:
            z = layout["link_d"][v.index - n_sz]
            v.deps, v.init_deps = sorted(set(of_z({z}, ()))), sorted(set(at_init({z}, ())))
            continue
        else:
            continue
        zs, ps = reads.of(expr)
        v.deps = sorted(set(of_z(zs, ps)))
        v.init_deps = sorted(set(at_init(zs, ps, reads.modes(expr))))
