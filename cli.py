"""The command line: ``acausal run | report | fmu | list`` (also ``python -m acausal``).

::

    acausal run SCRIPT[:MODEL] --t-end T [--rtol R] [--atol A] [--n-points N]
                [--set R1.R=5 ...] [--input u=1.5 w=drive.csv ...]
                [--backend auto|c|numpy] [--csv out.csv]
                [--plot out.png [VAR ...]] [--print VAR ...]
    acausal report SCRIPT[:MODEL] [--json] [--dot out.dot]
    acausal fmu SCRIPT[:MODEL] [-o model.fmu] [--type me|cs]
    acausal list [DOMAIN] [--json]

``SCRIPT`` is a Python file (``models/rlc.py``) or a dotted module
(``acausal.library.examples.motor_drive``); ``MODEL`` names the Component subclass to
use, and may be omitted when the module defines exactly one.  A file is loaded as a
module (its ``if __name__ == "__main__":`` block does not run), with its directory on
``sys.path`` so that it can import its neighbours.

Exit status: 0 on success, 2 for a usage error (bad arguments, a file or module that
does not exist, a ``SCRIPT:MODEL`` that names no model), 1 when the model or the run
fails (the typed errors: ``ModelError`` and its subclasses, ``SimulationError``,
``InitializationFailed``, ``BackendError``, or a script that raises while loading).
Errors are printed to stderr as ``acausal <command>: error: <Type>: <message>``; the
traceback only with ``--debug``.
"""
from __future__ import annotations

import argparse
import importlib
import importlib.util
import json
import math
import os
import sys
import traceback
import warnings

__all__ = ["main", "build_parser", "load_model", "report_dict", "UsageError"]

_FMI_TYPES = {"me": "ModelExchange", "cs": "CoSimulation"}
_STATS = (("steps", "steps"), ("residual_evaluations", "residual evaluations"),
          ("jacobian_evaluations", "Jacobian evaluations"),
          ("lu_factorizations", "LU factorizations"),
          ("error_test_failures", "error test failures"),
          ("newton_failures", "Newton failures"))


class UsageError(Exception):
    """The command line itself is wrong (exit status 2)."""


class _Failed(Exception):
    """The model or the run failed in a way that has no typed error (exit status 1)."""


# -- loading SCRIPT[:MODEL] ------------------------------------------------------------------
def load_model(spec: str):
    """``(model, module)`` for ``SCRIPT[:MODEL]``: a Component instance and the module
    that defines it.

    ``MODEL`` may name a Component subclass (instantiated without arguments) or a
    Component instance in the module; without it, the module must define exactly one
    Component subclass itself (classes it imports do not count).  UsageError if the
    script, the module or the model does not exist.
    """
    script, name = _split_spec(spec)
    module = _load_module(script)
    return _select_model(module, script, name), module


def _split_spec(spec: str):
    head, sep, tail = spec.rpartition(":")
    if sep and head and tail.isidentifier():
        return head, tail
    if sep and head and not tail:
        raise UsageError(f"'{spec}': nothing after ':' (write SCRIPT or SCRIPT:MODEL)")
    return spec, None


def _looks_like_file(script: str) -> bool:
    return script.endswith(".py") or os.sep in script or os.path.exists(script)


def _load_module(script: str):
    if _looks_like_file(script):
        return _load_file(script)
    if not all(part.isidentifier() for part in script.split(".")):
        raise UsageError(f"'{script}' is neither a Python file nor a dotted module name")
    try:
        return importlib.import_module(script)
    except ModuleNotFoundError as err:
        # only a missing module *named by the user* is a usage error; a module that is
        # found but fails to import one of its own dependencies is the script's failure
        if err.name and (script == err.name or script.startswith(err.name + ".")):
            raise UsageError(f"no module named '{err.name}' (SCRIPT is a .py file or a "
                             "dotted module such as acausal.library.examples.motor_drive)"
                             ) from None
        raise _Failed(f"importing {script}: {type(err).__name__}: {err}") from err
    except Exception as err:
        raise _Failed(f"importing {script}: {type(err).__name__}: {err}") from err


def _load_file(path: str):
    if not os.path.isfile(path):
        what = "is a directory, not a file" if os.path.isdir(path) else "does not exist"
        raise UsageError(f"script '{path}' {what}")
    path = os.path.abspath(path)
    stem = os.path.splitext(os.path.basename(path))[0]
    # the file's own name when free, so that its classes report a plain module name; a
    # private name when that would shadow a module already imported (a script json.py)
    name = stem if stem.isidentifier() and stem not in sys.modules else f"_acausal_script_{stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise UsageError(f"'{path}' cannot be loaded as a Python module")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module          # before running it: dataclasses and pickle look here
    folder = os.path.dirname(path)
    if folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        spec.loader.exec_module(module)
    except Exception as err:
        del sys.modules[name]
        raise _Failed(f"running {path}: {type(err).__name__}: {err}") from err
    return module


def _models_defined_in(module) -> list:
    from .components import Component, Port
    return [v for v in vars(module).values()
            if isinstance(v, type) and issubclass(v, Component) and not issubclass(v, Port)
            and v.__module__ == module.__name__]


def _select_model(module, script: str, name: str | None):
    from .components import Component, Port
    defined = _models_defined_in(module)
    listing = ", ".join(c.__name__ for c in defined) or "none"
    if name is None:
        if len(defined) != 1:
            why = "defines no Component subclass" if not defined else \
                f"defines {len(defined)} models ({listing}); choose one with {script}:MODEL"
            raise UsageError(f"{script} {why}")
        target = defined[0]
    else:
        if not hasattr(module, name):
            raise UsageError(f"{script} has no '{name}' (models defined there: {listing})")
        target = getattr(module, name)
    if isinstance(target, Component) and not isinstance(target, Port):
        return target
    if not (isinstance(target, type) and issubclass(target, Component)) \
            or issubclass(target, Port):
        raise UsageError(f"{script}:{name} is not a model (a Component subclass or "
                         f"instance) but {target!r}; models defined there: {listing}")
    try:
        return target()
    except TypeError as err:
        raise _Failed(f"{target.__name__}() cannot be made without arguments ({err}); "
                      f"define an instance in the script and name it as {script}:NAME"
                      ) from err


# -- argument types ------------------------------------------------------------------------
def _number(text: str, allow_zero: bool) -> float:
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not (math.isfinite(x) and (x > 0 or (allow_zero and x == 0))):
        raise argparse.ArgumentTypeError(f"{text} must be {'>= 0' if allow_zero else '> 0'} "
                                         "and finite")
    return x


def _positive(text: str) -> float:
    return _number(text, allow_zero=False)


def _nonnegative(text: str) -> float:
    return _number(text, allow_zero=True)


def _points(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not an integer") from None
    if n < 2:
        raise argparse.ArgumentTypeError(f"{n}: at least 2 output points")
    return n


def parse_assignments(items) -> dict:
    """``["R1.R=5", "C1.C=1e-6"]`` -> ``{"R1.R": 5.0, "C1.C": 1e-06}`` (UsageError for a
    malformed item).  Whether a name is a tunable parameter is the model's to say."""
    out = {}
    for item in items or ():
        name, sep, value = item.partition("=")
        name, value = name.strip(), value.strip()
        if not sep or not name or not value:
            raise UsageError(f"--set {item}: expected NAME=VALUE, e.g. --set R1.R=5")
        try:
            out[name] = float(value)
        except ValueError:
            raise UsageError(f"--set {item}: '{value}' is not a number") from None
    return out


def parse_inputs(items) -> dict:
    """``["u=2.5", "w=drive.csv", "v=data.csv:3"]`` -> the drivers of the model's
    top-level inputs: a number, or a table read from a CSV file (its first column the
    time, the value from column 2, or the column after ``:``, numbered from 1 as a
    CombiTimeTable's; the file is read as numbers only, never executed)."""
    out = {}
    for item in items or ():
        name, sep, value = item.partition("=")
        name, value = name.strip(), value.strip()
        if not sep or not name or not value:
            raise UsageError(f"--input {item}: expected NAME=VALUE or NAME=FILE.csv, e.g. "
                             "--input u=1.5")
        try:
            out[name] = float(value)
            continue
        except ValueError:
            pass
        path, column = value, 2
        head, colon, tail = value.rpartition(":")
        if colon and tail.isdigit():
            path, column = head, int(tail)
        from .library.blocks.tables import read_table
        try:
            data = read_table(path, f"--input {name}")
        except OSError as err:
            raise UsageError(f"--input {item}: cannot read {path}: {err.strerror}") from None
        if not 2 <= column <= data.shape[1]:
            raise UsageError(f"--input {item}: {path} has columns 1 to {data.shape[1]} (1 "
                             f"is time), not {column}")
        out[name] = (data[:, 0], data[:, column - 1])
    return out


# -- the commands ------------------------------------------------------------------------
def _compile(model, backend: str, check_units: str = "warn"):
    from . import compile as compile_model
    return compile_model(model, backend=backend, check_units=check_units)


def _cmd_run(args) -> int:
    values = parse_assignments(args.set)
    inputs = parse_inputs(getattr(args, "input", None))
    for option, path in (("--csv", args.csv), ("--plot", args.plot[0] if args.plot else None)):
        _check_writable(option, path)          # before the run, not after it
    model, module = load_model(args.script)
    t_end = args.t_end if args.t_end is not None else getattr(model, "stop_time", None)
    if t_end is None:
        raise UsageError(f"--t-end is required: {type(model).__name__} has no stop_time")
    compiled = _compile(model, args.backend, args.check_units)
    defaults = {n: float(compiled.p[compiled.param_names.index(n)])
                for n in values if n in compiled.param_names}
    compiled.set_parameters(values)            # unknown names: NotInModel, from the model
    shown = list(args.print or compiled.states)
    plotted = (args.plot[1:] or shown) if args.plot else []
    _check_names(compiled, shown + plotted)
    from . import simulate
    with warnings.catch_warnings():
        # a failed run is reported below, with its numbers: not twice
        warnings.simplefilter("ignore", RuntimeWarning)
        res = simulate(compiled, t_end=t_end, rtol=args.rtol, atol=args.atol,
                       n_points=args.n_points, inputs=inputs or None)
    print(f"{type(model).__name__} ({module.__name__}), backend {compiled.backend}, "
          f"{len(compiled.states)} states, {len(compiled.param_names)} parameters")
    for n, x in values.items():
        print(f"  set {n} = {x:.12g} (default {defaults[n]:.12g})")
    _print_summary(res, t_end, args, shown)
    if args.csv:
        res.to_csv(args.csv)
        print(f"wrote {args.csv} ({len(res.t)} points, {len(res.names)} variables)")
    if args.plot:
        try:
            res.plot(*plotted, path=args.plot[0])
        except ImportError as err:
            raise _Failed(str(err)) from err
        print(f"wrote {args.plot[0]} ({', '.join(plotted)})")
    if not res.success:
        raise _Failed(f"the simulation stopped at t = {res.t[-1]:.12g}: {res.message}")
    return 0


def _print_summary(res, t_end, args, shown) -> None:
    """Outcome, solver counts and events, and the last value of each ``shown`` variable
    (12 significant digits: what a CSV of the result would hold, to its round-off)."""
    tol = f"rtol {args.rtol:g}" + ("" if args.atol is None else f", atol {args.atol:g}")
    print(f"simulated t = 0 .. {res.t[-1]:.12g} of {float(t_end):.12g} ({tol}): "
          + ("success" if res.success else "FAILED") + f", {res.message}")
    stats = [f"{label} {res.stats[k]}" for k, label in _STATS if k in res.stats]
    times = ", ".join(f"{e:.6g}" for e in res.events[:5]) + (" ..." if len(res.events) > 5
                                                             else "")
    stats.append(f"events {len(res.events)}" + (f" (at {times})" if res.events else ""))
    print("  " + ", ".join(stats))
    if not shown:
        print("the model has no states: name variables to print with --print VAR ...")
        return
    print(f"{'final values' if res.success else 'last values'} at t = {res.t[-1]:.12g}:")
    width = max(len(n) for n in shown)
    for n in shown:
        print(f"  {n:<{width}}  {res[n][-1]: .12g}")


def _check_writable(option: str, path) -> None:
    if path is None:
        return
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise UsageError(f"{option} {path}: the directory {folder} does not exist")


def _check_names(compiled, names) -> None:
    from .components import NotInModel
    for n in names:
        if n not in compiled.outputs:
            leaf = n.split(".")[-1]
            close = sorted(k for k in compiled.outputs if k.split(".")[-1] == leaf)[:8]
            raise NotInModel(f"the model has no variable '{n}'"
                             + (f"; variables with that name: {', '.join(close)}" if close
                                else ""))


def _cmd_report(args) -> int:
    _check_writable("--dot", args.dot)
    model, _ = load_model(args.script)
    compiled = _compile(model, args.backend, args.check_units)
    report = compiled.report
    if args.dot:
        with open(args.dot, "w") as fh:
            fh.write(report.to_dot() + "\n")
    if args.json:
        print(json.dumps(report_dict(compiled), indent=2, default=str))
    else:
        print(report)
        if args.dot:
            print(f"wrote {args.dot} (the BLT blocks, and which blocks each one needs)")
    return 0


def report_dict(compiled) -> dict:
    """The index report as JSON-ready data: ``report.as_dict()`` with the BLT blocks in
    names (each block's equations by their text, its variables and torn iteration
    variables by name), plus the backend and the solver's state vector."""
    report = compiled.report
    data = report.as_dict()
    texts = [e["text"] for e in report.equations]
    names = getattr(report, "_names", None)

    def var(k):
        return names[k] if names is not None and 0 <= k < len(names) else k

    data["blocks"] = [{**b,
                       "equations": [texts[e] if 0 <= e < len(texts) else e
                                     for e in b["equations"]],
                       "variables": [var(v) for v in b["variables"]],
                       **({"iteration_variables": [var(v) for v in b["iteration_variables"]]}
                          if "iteration_variables" in b else {})}
                      for b in report.blocks]
    data["backend"] = compiled.backend
    data["solver_states"] = list(compiled.states)
    data["parameters"] = {n: float(x) for n, x in zip(compiled.param_names, compiled.p)}
    return data


def _cmd_fmu(args) -> int:
    _check_writable("-o", args.output)
    model, _ = load_model(args.script)
    path = args.output or f"{type(model).__name__}.fmu"
    fmi_type = _FMI_TYPES[args.type]
    try:
        from . import export_fmu
        t_end = args.t_end if args.t_end is not None else getattr(model, "stop_time", None)
        export_fmu(model, path, fmi_type=fmi_type, t_end=t_end, rtol=args.rtol)
    except ImportError as err:
        raise _Failed(f"FMU export is not available here ({err}); it needs the fmi extra: "
                      "pip install 'acausal[fmi]'") from err
    print(f"wrote {path} (FMI 2.0 {fmi_type}, {os.path.getsize(path)} bytes)")
    return 0


def _cmd_list(args) -> int:
    from .library.catalogue import describe_domain, library_domains
    found = library_domains()
    if args.domain is not None and args.domain not in found:
        raise UsageError(f"no library domain '{args.domain}' (domains: {', '.join(found)})")
    chosen = [args.domain] if args.domain else found
    data = {d: describe_domain(d) for d in chosen}
    if args.json:
        print(json.dumps(data, indent=2))
        return 0
    for d in chosen:
        print(f"{d}: {data[d]['doc']}")
        width = max((len(n) for n in data[d]["components"]), default=0)
        for cname, c in data[d]["components"].items():
            ports = _port_summary(c["ports"])
            if args.domain is None:
                params = " ".join(p["name"] for p in c["parameters"])
                print(f"  {cname:<{width}}  {ports}" + (f"  | {params}" if params else ""))
                continue
            print(f"  {cname}: {c['doc']}")
            print("    ports: " + (", ".join(f"{p['name']} ({p['type']}, {p['domain']})"
                                         for p in c["ports"]) or "-"))
            for p in c["parameters"]:
                value = p["default"] if isinstance(p["default"], str) else f"{p['default']:g}"
                unit = f" [{p['unit']}]" if p["unit"] else ""
                desc = f"  {p['description']}" if p["description"] else ""
                print(f"    {p['name']} = {value}{unit}{desc}")
        print()
    return 0


def _port_summary(ports) -> str:
    """``p n [electrical], heatPort [thermal]``: the ports grouped by domain."""
    groups = {}
    for p in ports:
        groups.setdefault(p["domain"], []).append(p["name"])
    return ", ".join(f"{' '.join(names)} [{d}]" for d, names in groups.items()) or "-"


# -- the parser and the entry point ---------------------------------------------------------
def _version() -> str:
    try:
        from importlib.metadata import version
        return version("acausal")
    except Exception:          # not installed (run from a checkout): say so, do not fail
        return "unknown (not installed)"


def build_parser() -> argparse.ArgumentParser:
    common = argparse.ArgumentParser(add_help=False)
    # SUPPRESS: a subcommand's --debug must not reset one given before the subcommand
    common.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                        help="print the traceback of an error")
    model_arg = argparse.ArgumentParser(add_help=False)
    # optional to argparse, so that a SCRIPT swallowed by an option taking several
    # values (--set, --print, --plot) gets a message saying so (_require_script)
    model_arg.add_argument("script", metavar="SCRIPT[:MODEL]", nargs="?",
                           help="a .py file or a dotted module, and the Component class "
                                "in it (optional when it defines only one)")
    parser = argparse.ArgumentParser(
        prog="acausal", description="Compile, simulate and export acausal models.",
        epilog="'acausal COMMAND --help' describes each command.")
    parser.add_argument("--version", action="version", version=f"acausal {_version()}")
    parser.add_argument("--debug", action="store_true", default=False,
                        help="print the traceback of an error")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    run = sub.add_parser("run", parents=[model_arg, common],
                         usage="%(prog)s SCRIPT[:MODEL] [options]", help="simulate a model",
                         description="Compile and simulate a model; print a summary and "
                                     "the final values of its states (or of --print).")
    run.add_argument("--t-end", type=_positive, metavar="T",
                     help="end time (default: the model's stop_time, if it has one)")
    run.add_argument("--rtol", type=_positive, default=1e-6, metavar="R",
                     help="relative tolerance (default 1e-6)")
    run.add_argument("--atol", type=_nonnegative, metavar="A",
                     help="absolute tolerance, scaled by each variable's nominal value "
                          "(default: rtol)")
    run.add_argument("--n-points", type=_points, metavar="N",
                     help="N evenly spaced output points (default: every step)")
    run.add_argument("--set", nargs="+", action="extend", metavar="NAME=VALUE",
                     help="change tunable parameters, e.g. --set motor.R=2 load.J=0.02")
    run.add_argument("--input", nargs="+", action="extend", metavar="NAME=VALUE|FILE",
                     help="drive a top-level input: a number, or a CSV file of rows "
                          "(time, value), e.g. --input u=1.5 w=drive.csv")
    run.add_argument("--backend", choices=("auto", "c", "numpy"), default="auto",
                     help="generated code: C (compiled), numpy, or C when a compiler works")
    run.add_argument("--csv", metavar="FILE", help="write every variable to a CSV file")
    run.add_argument("--plot", nargs="+", metavar=("FILE", "VAR"),
                     help="plot variables (default: the printed ones) to an image file")
    run.add_argument("--print", nargs="+", metavar="VAR",
                     help="print the final values of these variables instead of the states")
    run.add_argument("--check-units", choices=("warn", "error", "off"), default="warn",
                     help="dimensional check of every equation: warn (default), error, off")
    run.set_defaults(handler=_cmd_run)

    rep = sub.add_parser("report", parents=[model_arg, common],
                         usage="%(prog)s SCRIPT[:MODEL] [options]",
                         help="print the index report",
                         description="Compile a model and print its index report: index, "
                                     "differentiated equations, states, dummy derivatives, "
                                     "BLT blocks and tearing.")
    rep.add_argument("--json", action="store_true", help="print the report as JSON")
    rep.add_argument("--dot", metavar="FILE",
                     help="write the BLT block graph (Graphviz DOT: one node per block, an "
                          "edge from each block to the blocks that use its variables)")
    rep.add_argument("--backend", choices=("auto", "c", "numpy"), default="auto",
                     help="generated code (the report is the same for both)")
    rep.add_argument("--check-units", choices=("warn", "error", "off"), default="warn",
                     help="dimensional check of every equation: warn (default), error, off")
    rep.set_defaults(handler=_cmd_report)

    fmu = sub.add_parser("fmu", parents=[model_arg, common],
                         usage="%(prog)s SCRIPT[:MODEL] [options]", help="export an FMI 2.0 FMU",
                         description="Export a model as an FMI 2.0 FMU.")
    fmu.add_argument("-o", "--output", metavar="FILE",
                     help="the .fmu file to write (default: MODEL.fmu)")
    fmu.add_argument("--type", choices=tuple(_FMI_TYPES), default="me",
                     help="me: Model Exchange (default), cs: Co-Simulation")
    fmu.add_argument("--t-end", type=_positive, metavar="T",
                     help="the default experiment's stop time (default: the model's "
                          "stop_time, if it has one)")
    fmu.add_argument("--rtol", type=_positive, metavar="R",
                     help="the default experiment's tolerance (Co-Simulation integrates "
                          "with it unless the importer sets another)")
    fmu.set_defaults(handler=_cmd_fmu)

    lst = sub.add_parser("list", parents=[common], help="list the component library",
                         description="The component library: domains, components, their "
                                     "ports and parameters (in detail for one DOMAIN).")
    lst.add_argument("domain", nargs="?", metavar="DOMAIN", help="e.g. electrical")
    lst.add_argument("--json", action="store_true", help="print the listing as JSON")
    lst.set_defaults(handler=_cmd_list)
    return parser


def _exit_status(err) -> int | None:
    """1 for the typed failures of a model or a run, 2 for usage; None: not expected."""
    from .components import ModelError
    from .errors import BackendError, InitializationFailed, SimulationError
    if isinstance(err, UsageError):
        return 2
    if isinstance(err, (_Failed, ModelError, SimulationError, InitializationFailed,
                        BackendError, OSError)):
        return 1
    return None


def main(argv=None) -> int:
    """Run the command line on ``argv`` (default ``sys.argv[1:]``); the exit status."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as stop:           # --help, --version, or argparse's usage error
        return stop.code if isinstance(stop.code, int) else (0 if stop.code is None else 2)
    try:
        if args.command != "list" and args.script is None:
            raise UsageError("SCRIPT[:MODEL] is missing (give it first: options such as "
                             "--set, --print and --plot take all the values after them)")
        return args.handler(args)
    except BrokenPipeError:
        # the reader went away (| head): nothing more to say, and nowhere to say it
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 1
    except Exception as err:            # noqa: BLE001 - every error becomes one message
        status = _exit_status(err)
        kind = "" if isinstance(err, (UsageError, _Failed)) else f"{type(err).__name__}: "
        if args.debug:
            traceback.print_exc()
        hint = "" if status is not None or args.debug else \
            " (an unexpected error: run with --debug for the traceback)"
        print(f"acausal {args.command}: error: {kind}{err}{hint}", file=sys.stderr)
        return 1 if status is None else status
