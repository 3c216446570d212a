"""CompiledModel: a compiled model at run time, the DAEProblem the integrator solves.

Formulation (see the README's design section for why).  The generated code returns
``n_res`` residual rows G(t, z) followed, in the causal form, by der(s) of the code-linked
states ``state_z``; in the full form every variable, derivative variables der(x)
included, is part of z and each selected state s has a *linking row*.  So

    F = [ G(t, z);  z'[state_z] - D(t, z);  z'[link_s] - z[link_d] ]

and a dummy derivative (Mattsson & Söderlind 1993) is a derivative variable without a
linking row.  Dynamic state selection (:mod:`acausal.runtime.dynamic`) only changes
which links are active; the generated code and the vector z stay the same.

The discrete state (relation values and frozen floor values, :mod:`.modes`), when-clauses
(:mod:`.events`), exact time events, dynamic state selection and the one initialization
path (:mod:`.initial`) are all reached from here, through the items of the solver
contract (:mod:`acausal.solvers.base`) and the runtime's own, in ``acausal.runtime``.

A CompiledModel pickles as its ModelCode in portable form
(:func:`acausal.compiler.cache.entries.portable`: the generated sources, executed again on
load; the C library loaded again or rebuilt) with its parameter values, discrete state
and current choice of dummy derivatives.
"""
from __future__ import annotations

import types

import numpy as np

from ..solvers.base import DAEProblem, LoopModel, unbounded
from ..solvers.linalg import assemble
from .delays import DelayLines, FilledCode
from .diagnostics import DOMAIN_ERRORS, OutputCheck, failing_statement
from .dynamic import DynamicStateSelection
from .events import WhenClauses, iterate_event
from .initial import InitialConditions, consistent_output, initialize, reinitialize
from .inputs import InputDrivers
from .modes import DiscreteState
from .parameters import no_parameter_message, tuned_parameters
from ..errors import NotInModel

__all__ = ["CompiledModel"]

_MODE_ROUNDS = 10               # relations read through other relations' values, settled in turn
_LISTED_PARAMS = 256            # from this many parameters on, the Python code gets p listed


class CompiledModel(DAEProblem):
    """F(t, z, z') for the solver, with the user's names, parameters and discrete state.

    Built by :func:`acausal.compile` from the compiler's
    :class:`~acausal.compiler.modelcode.ModelCode`.  ``compiled.report`` is the index
    report; ``param_names``/``p`` the tunable parameters; ``derived_parameters`` the
    parameters bound to an expression of others (``m = rho * V``), by name, with their
    values at compile time (their equations use the binding, so they follow the tunable
    parameters they depend on); ``outputs`` maps every variable's name to where its
    value comes from; ``states`` names the states.
    """

    oriented_roots = True

    def __init__(self, mc):
        super().__init__(len(mc.names), mc.names)
        self.model_code = mc
        self.param_names = list(mc.param_names)
        self.derived_parameters = {name: value for name, (_, value)
                                   in mc.meta.get("derived_parameters", {}).items()}
        # delay(): the delayed values follow the tunable parameters in p, written from
        # the history before every call of the generated code (runtime/delays.py)
        self.delays = None
        self.code = code = mc.code
        initial, whens = mc.initial, mc.whens
        if getattr(mc, "delays", None) is not None:
            from dataclasses import replace
            self.delays = DelayLines(mc.delays, len(self.param_names))
            fill = self.delays.fill
            self.code = code = FilledCode(mc.code, fill)
            initial = replace(initial, code=FilledCode(initial.code, fill))
            if whens is not None:
                whens = replace(whens, code=FilledCode(whens.code, fill))
            self._delay_code = FilledCode(mc.delays.code, fill)
        n_delays = self.delays.n if self.delays else 0
        self.p = np.concatenate([np.asarray(mc.param_values, dtype=float),
                                 np.zeros(n_delays)])
        # top-level inputs: after the delays in p, written by their drivers (inputs.py)
        self.inputs = None
        if getattr(mc, "inputs", None) is not None:
            self.inputs = InputDrivers(mc.inputs, len(self.param_names) + n_delays)
            self.p = np.concatenate([self.p, self.inputs.starts])
        self.n_res = int(mc.n_res)
        self.state_z = np.asarray(mc.state_z, dtype=np.int64)
        self.pair_s = np.asarray([a for a, _ in mc.pairs], dtype=np.int64)
        self.pair_d = np.asarray([b for _, b in mc.pairs], dtype=np.int64)
        self.dummies = set(mc.dummies)
        self.nominal = np.asarray(mc.nominal, dtype=float)
        # derivatives solved as unknowns, without a nominal: judged on their own motion
        self.self_scaled = np.asarray(mc.meta.get("self_scaled", [False] * self.n), bool)
        self.start = np.asarray(mc.start, dtype=float)
        self.outputs = mc.outputs
        self.report = mc.report
        self.meta = mc.meta
        self.backend = mc.meta.get("backend", "numpy")   # which code runs: "c" or "numpy"
        self.discrete = DiscreteState(mc.relations, code.roots, code.scales)
        self.n_roots = self.discrete.n_roots
        self.whens = WhenClauses(whens) if whens is not None else None
        self.initial = InitialConditions(initial)
        self._unfilled = None             # the code without the inputs' fill (_fill_inputs)
        self.dynamic = None
        if mc.dynamic is not None:
            self.dynamic = DynamicStateSelection(mc.dynamic, self.nominal)
            self.dynamic.bind(code.jac_rows, code.jac_cols)
        self._res_entries = code.jac_rows < self.n_res
        self._der_entries = ~self._res_entries
        self.evaluation_errors = []        # what failed in the generated code, in words
        # the outputs integrating does not check, checked at every output point (item 11)
        self.check_point = OutputCheck.of(self)
        self.resolution = 0.0             # how precisely the driver locates crossings
        self._z_ref = self.start.copy()    # a point for time-event predictions
        self._list_params = isinstance(code.residual, types.FunctionType) and \
            self.delays is None and len(self.p) >= _LISTED_PARAMS
        self._p_listed = None
        self._next_own = None              # the model's own next time event
        self._loop_model = None            # made when a compiled step loop asks
        self._update_links()

    # -- pickling -----------------------------------------------------------------------
    def __getstate__(self):
        from ..compiler.cache.entries import portable
        return {"model_code": portable(self.model_code), "p": self.p.copy(),
                "m": self.discrete.m.copy(), "dummies": sorted(self.dummies),
                "switches": list(self.dynamic.switches) if self.dynamic is not None else []}

    def __setstate__(self, state):
        from ..compiler.cache.entries import load_notes
        mc = state["model_code"]
        notes = load_notes(mc)
        if notes and mc.report is not None:
            mc.report.notes += [n for n in notes if n not in mc.report.notes]
        self.__init__(mc)
        self.p[:] = state["p"]
        self.discrete.m[:] = state["m"]
        if self.dynamic is not None:
            self.dummies = set(state["dummies"])
            self.dynamic.switches[:] = state["switches"]
            self._update_links()

    # -- top-level inputs (runtime/inputs.py) --------------------------------------------
    @property
    def input_names(self) -> list:
        """The model's top-level inputs (input ports of the model that nothing drives)."""
        return list(self.inputs.names) if self.inputs is not None else []

    @property
    def inputs_vary(self) -> bool:
        """An input is a function of time or a table (the step loop is the Python one)."""
        return self.inputs is not None and self.inputs.varying

    def drive_inputs(self, specs: dict | None) -> None:
        """Drive every top-level input for the next run: {name: number, function of
        time, (times, values) table or CombiTimeTable}; a missing or unknown name is a
        typed error naming it.  ``None`` with no inputs is fine."""
        if self.inputs is None:
            if specs:
                raise NotInModel(f"simulate(inputs=...): the model has no top-level inputs "
                                 f"(given: {', '.join(map(str, specs))})")
            return
        self.inputs.set(specs, self.p)
        self._fill_inputs(self.inputs.varying)

    def release_inputs(self) -> None:
        """After a run: the inputs back at their start values, the code unfilled."""
        if self.inputs is not None:
            self.inputs.reset(self.p)
            self._fill_inputs(False)

    def _fill_inputs(self, on: bool) -> None:
        """Every generated function writes the varying inputs' values at t into p before
        it runs (on), or the functions as compiled (off)."""
        if (self._unfilled is not None) == on:
            return
        if not on:
            code, initial_code, whens_code = self._unfilled
            self._unfilled = None
        else:
            self._unfilled = (self.code, self.initial.code,
                              self.whens.code if self.whens is not None else None)
            fill = self.inputs.write
            code = FilledCode(self.code, fill)
            initial_code = FilledCode(self.initial.code, fill)
            whens_code = FilledCode(self.whens.code, fill) if self.whens is not None else None
        self.code = code
        self.initial.code = initial_code
        if self.whens is not None:
            self.whens.code = whens_code
        self.discrete._roots, self.discrete._scales = code.roots, code.scales

    # -- the discrete state -----------------------------------------------------------
    @property
    def m(self) -> np.ndarray:
        """Relation values (1.0/0.0) then frozen floor values, read by the generated code."""
        return self.discrete.m

    @m.setter
    def m(self, value) -> None:
        self.discrete.m[:] = value

    def discrete_state(self) -> np.ndarray:
        return self.discrete.m.copy()

    def set_discrete_state(self, m) -> None:
        self.discrete.m[:] = m

    def relations(self, t, z) -> np.ndarray:
        """lhs - rhs of every relation (unoriented)."""
        return self.discrete.values(t, z, self.p)[: self.discrete.n_rel]

    def contradicted(self, t, z) -> np.ndarray:
        """Relations (then floor values) whose frozen value the point (t, z) clearly
        contradicts, each judged on its own scale."""
        return self.discrete.contradicted(t, z, self.p)

    def relation_text(self, k) -> str:
        return self.discrete.describe(k)

    def init_modes(self, t, z) -> None:
        """Every relation takes its value at (t, z); one exactly at zero takes the value
        it has there (>= and <= hold).  For analysis at a given point.  Repeated while the
        values change: a relation may read a variable that others' values determine (a
        flow through a valve whose opening is clipped by another relation)."""
        zeros = np.zeros(self.discrete.n_rel + self.discrete.n_disc)
        for _ in range(_MODE_ROUNDS):
            if not self.discrete.set_all(t, z, self.p, lambda: zeros):
                return

    # -- the linking rows --------------------------------------------------------------
    def _update_links(self):
        active = np.array([d not in self.dummies for d in self.pair_d], dtype=bool)
        self.link_s = self.pair_s[active] if len(active) else self.pair_s
        self.link_d = self.pair_d[active] if len(active) else self.pair_d
        self.state_index = np.concatenate([self.state_z, self.link_s]).astype(np.int64)
        self.algebraic = np.ones(self.n, dtype=bool)
        self.algebraic[self.state_index] = False
        self.algebraic_index = np.flatnonzero(self.algebraic)
        # algebraic unknowns the error test leaves out (contract item 6): values at
        # output times between steps are solved for them
        self.uncontrolled = bool(unbounded(self.algebraic, self.self_scaled).any())
        r0 = self.n_res + len(self.state_z)
        rows_link = r0 + np.arange(len(self.link_s))
        c = self.code
        self.jac_pattern = (
            np.concatenate([c.jac_rows, self.n_res + np.arange(len(self.state_z)), rows_link,
                            rows_link]),
            np.concatenate([c.jac_cols, self.state_z, self.link_s, self.link_d]))
        # the CSC structure of the pattern, once per choice of links: each entry's slot
        # (duplicates add up, as in COO), then only the values change from call to call
        rows, cols = self.jac_pattern
        key = cols.astype(np.int64) * max(self.n, 1) + rows
        unique, self._jac_slot = np.unique(key, return_inverse=True)
        self._jac_indices = (unique % max(self.n, 1)).astype(np.int32)
        self._jac_colof = unique // max(self.n, 1)
        self._jac_indptr = np.searchsorted(self._jac_colof,
                                           np.arange(self.n + 1)).astype(np.int32)

    @property
    def states(self) -> list:
        return [self.names[k] for k in self.state_index]

    @property
    def equation_names(self) -> list:
        """A label for every residual row (messages about singular or failing rows)."""
        names = list(self.meta.get("equation_names", []))
        names += [f"der({self.names[k]}) (state derivative)" for k in self.state_z]
        names += [f"der({self.names[s]}) = {self.names[d]}" for s, d in
                  zip(self.link_s, self.link_d)]
        return names

    # -- the compiled step loop (solver contract item 18) ---------------------------------
    def loop_model(self) -> LoopModel | None:
        """The generated functions and their layout, for a compiled step loop; None with
        delays (their history is kept in Python after every step)."""
        if self.delays is not None:
            return None
        if self._loop_model is None:
            self._loop_model = self._make_loop_model()
        return self._loop_model

    def _make_loop_model(self) -> LoopModel:
        from ..compiler.backends.clibrary import CFunction
        code, d = self.code, self.discrete
        names = ("residual", "jacobian") + (("roots", "scales") if self.n_roots else ())
        native = self.backend == "c" and all(isinstance(getattr(code, k), CFunction)
                                             for k in names)

        def function(name):
            fn = getattr(code, name)
            if native:
                import ctypes
                return ctypes.cast(fn.fn, ctypes.c_void_p).value
            return lambda t, z, out: self._call(fn, t, z, len(out), out)

        def links():
            return (self.link_s, self.link_d, self._jac_indptr, self._jac_indices,
                    self._jac_slot)

        def dynamic_test():
            return self.dynamic.watch(self.dummies)

        return LoopModel(
            functions={k: function(k) for k in names},
            n_work=int(code.c_layout["n_work"]) if native else 0,
            n_rows=int(code.n_rows), n_res=self.n_res, state_z=self.state_z,
            jac_rows=code.jac_rows, jac_cols=code.jac_cols,
            jac_sign=np.where(self._der_entries, -1.0, 1.0), n_rel=d.n_rel, n_disc=d.n_disc,
            root_nominal=d.nominal, timed=d._timed.astype(float), p=self.p, m=d.m,
            offset=d.offset, orientation=d.loop_orientation, links=links,
            dynamic_test=dynamic_test if self.dynamic is not None else None)

    # -- evaluation of the generated code ------------------------------------------------
    def _params(self):
        """p as the generated code is best given it: the generated Python converts p to
        a list on every call, and for a large p (thousands of component parameters)
        making and freeing those floats costs more than copying a list made once; the
        list is made again whenever p has changed (it is written in place by analyses
        and sweeps).  Arrays for the C backend, and where delays write into p."""
        p = self.p
        if not self._list_params:
            return p
        if self._p_listed is None or not np.array_equal(p, self._p_listed[0]):
            self._p_listed = (p.copy(), p.tolist())
        return self._p_listed[1]

    def _call(self, fn, t, z, size, out=None):
        """fn(t, z, p, m, out) into ``out`` (a new array when None); NaN where it fails."""
        try:
            return fn(t, z, self._params(), self.m, np.empty(size) if out is None else out)
        except DOMAIN_ERRORS as exc:
            # outside a function's domain (sqrt of a negative, ...): the point is unusable,
            # which Newton treats as a failed iterate; the words are kept for the message
            what = failing_statement(self.code.source, exc, self.equation_names,
                                     self.meta.get("assigned_names", [])) \
                or "evaluating the model"
            note = f"{what} failed at t = {t:.6g}: {type(exc).__name__}: {exc}"
            if note not in self.evaluation_errors:
                self.evaluation_errors.append(note)
            if out is None:
                return np.full(size, np.nan)
            out[:] = np.nan
            return out

    def _rows(self, t, z):
        return self._call(self.code.residual, t, z, self.code.n_rows)

    def state_derivatives(self, t, z) -> np.ndarray:
        """der(s) of every state, in the order of ``state_index``."""
        out = self._rows(t, z)
        return np.concatenate([out[self.n_res:], z[self.link_d]])

    def G(self, t, z):
        return self._rows(t, z)[: self.n_res]

    def residual(self, t, z, zp):
        out = self._rows(t, z)
        F = np.empty(self.n)
        F[: self.n_res] = out[: self.n_res]
        k = self.n_res + len(self.state_z)
        F[self.n_res:k] = zp[self.state_z] - out[self.n_res:]
        F[k:] = zp[self.link_s] - z[self.link_d]
        return F

    def _jac_values(self, t, z):
        return self._call(self.code.jacobian, t, z, len(self.code.jac_rows))

    #: jacobian(..., dense=True) gives an ndarray (see solvers.linalg.iteration_matrix)
    offers_dense_jacobian = True

    def jacobian(self, t, z, zp, cj, dense: bool = False):
        """The iteration matrix dF/dz + cj dF/dz', CSC (with ``dense`` an ndarray of the
        same entries: what the dense LU of a small system factors)."""
        vals = self._jac_values(t, z)
        vals[self._der_entries] *= -1.0
        n_sz, n_l = len(self.state_z), len(self.link_s)
        data = np.concatenate([vals, np.full(n_sz, cj), np.full(n_l, cj), -np.ones(n_l)])
        data = np.bincount(self._jac_slot, weights=data, minlength=len(self._jac_indices))
        if dense:
            A = np.zeros((self.n, self.n))
            A[self._jac_indices, self._jac_colof] = data      # one slot per position
            return A
        import scipy.sparse as sps     # here: a model run by the compiled loop may not need it
        return sps.csc_matrix((data, self._jac_indices, self._jac_indptr),
                              shape=(self.n, self.n))

    def dG_dy(self, t, z, dense: bool = False):
        """dG/dz, CSR (with ``dense`` an ndarray)."""
        c = self.code
        vals = self._jac_values(t, z)
        keep = self._res_entries
        return assemble(vals[keep], c.jac_rows[keep], c.jac_cols[keep],
                        (self.n_res, self.n), dense)

    def expand(self, t, z) -> np.ndarray:
        """All variables of the reduced system (states, assigned and torn) from z."""
        if self.code.expand is None:
            return z
        return self._call(self.code.expand, t, z, self.meta["n_all"])

    # -- events (solver contract item 8) --------------------------------------------------
    def roots(self, t, z, zp):
        return self.discrete.oriented(t, z, self._params())

    def root_label(self, k: int) -> str:
        """The relation (or the floor/integer item: two roots each) behind root k."""
        n_rel = self.discrete.n_rel
        return self.discrete.describe(k if k < n_rel else n_rel + (k - n_rel) // 2)

    def tolerances(self, rtol, atol) -> None:
        """Solver contract item 18: the run's tolerances (the relations' hysteresis
        against chattering is bounded by atol, :mod:`.modes`)."""
        self.discrete.atol = float(np.max(atol)) if np.size(atol) else 0.0

    def arm(self, t, z, zp, resolution: float = 0.0) -> None:
        """The driver (re)arms the zero-crossing functions; ``resolution`` is how
        precisely (in time) it locates a crossing."""
        self._z_ref = np.array(z, dtype=float)
        self.resolution = float(resolution)
        zp = np.zeros(self.n) if zp is None else zp
        self.discrete.arm(t, z, self.p, lambda: self.rates(t, z, zp), self.resolution)

    def rates(self, t, z, zp) -> np.ndarray:
        """d/dt of every relation's g and floor argument along (1, z'), by a forward
        difference on a step small on the solution's own scale."""
        w = np.abs(zp) / (np.abs(z) + self.nominal)
        fastest = float(np.max(w, initial=0.0))
        dt = 1e-8 * (1.0 + abs(t))
        if fastest * dt > 1e-8:
            dt = 1e-8 / fastest
        v0 = self.discrete.values(t, z, self.p)
        v1 = self.discrete.values(t + dt, z + dt * zp, self.p)
        with np.errstate(invalid="ignore"):
            return (v1 - v0) / dt

    def handle_event(self, t, z, zp, crossed):
        """Settle the discrete state at the event and fire when-clauses
        (:func:`acausal.runtime.events.iterate_event`)."""
        if self.delays is not None:
            tol = max(self.resolution, 64 * np.finfo(float).eps * max(1.0, abs(t)))
            own = self._next_own is not None and abs(self._next_own - t) <= tol
            self.delays.event_at(t, self.resolution, fresh=bool(np.any(crossed)) or own)
        return iterate_event(self, t, z, zp, crossed)

    def next_time_event(self, t):
        """The next time a relation or floor value of time alone switches (exact), or a
        discontinuity comes back through a delay."""
        t_min = t + 64 * np.finfo(float).eps * max(1.0, abs(t))
        te = self.discrete.next_time_event(t, self._z_ref, self.p, t_min)
        tick = self.whens.next_tick(t_min) if self.whens is not None else None
        if tick is not None and (te is None or tick < te):
            te = tick          # a clock's tick changes held values: the model's own event
        self._next_own = te
        if self.delays is not None:
            tb = self.delays.next_break(t_min)
            if tb is not None and (te is None or tb < te):
                te = tb
        if self.inputs is not None:
            tb = self.inputs.next_break(t_min)      # a table's time: a kink or a jump
            if tb is not None and (te is None or tb < te):
                te = tb
        return te

    # -- delays (solver contract items 14-16) ---------------------------------------------
    @property
    def max_step(self) -> float:
        """The longest step the model allows: the shortest delay time (a delayed value
        is then always read from the accepted past, runtime/delays.py)."""
        if self.delays is None:
            return np.inf
        return float(np.min(self.delays.times(self.p)))

    def delay_arguments(self, t, z) -> np.ndarray:
        """The delayed expressions (the arguments of every delay()) at (t, z)."""
        return self._call(self._delay_code.residual, t, z, self.delays.n)

    def commit(self, t_lo, t_hi, interpolate, rtol=1e-6) -> None:
        """The solution on [t_lo, t_hi] is accepted: keep the delayed expressions."""
        if self.delays is not None:
            self.delays.commit(self, t_lo, t_hi, interpolate, rtol)

    def point_values(self, t) -> np.ndarray | None:
        """The delayed values and the inputs' values at an output point (recorded with
        it; results are evaluated with them), or None."""
        parts = []
        if self.delays is not None:
            parts.append(self.delays.values_at(t))
        if self.inputs_vary:
            parts.append(self.inputs.values_at(t))
        return np.concatenate(parts) if parts else None

    # -- initialization (runtime contract) ------------------------------------------------
    def initialize(self, t0: float):
        """Consistent (z, z') at t0, discrete state settled (:mod:`.initial`).  The
        discrete variables start from their start values; clocks that tick at t0 fire
        once the initial values are found (:mod:`.events`); with delays, the history
        before t0 agrees with the solution at t0."""
        # a run's values at output times start from a factorization of its own: the
        # same run gives bitwise the same result whatever ran before
        self._output_lu = None
        self.discrete.reset_held()
        self.discrete.set_initial(True)
        if self.whens is not None:
            self.whens.reset_clocks(t0, self.start, self.p, self.m)
        if self.delays is not None:
            z, zp = self.delays.initialize(self, t0, initialize)
        else:
            z, zp = initialize(self, t0)
        # the event that ends the initialization: clocks that tick at t0 and clauses
        # made true by initial() fire, and the Boolean and Integer equations iterate
        # with pre() taking their initial values (Modelica's event iteration at t0)
        ends = self.whens is not None and (self.whens.has_equations or
                                           self.discrete.has_initial)
        if ends or (self.whens is not None and self.whens.due(t0).any()):
            action = iterate_event(self, t0, z, zp, np.zeros(self.n_roots, dtype=bool),
                                   initial=ends)
            if action.changed:
                z, zp = reinitialize(self, t0, z if action.y is None else action.y, zp)
        self.discrete.set_initial(False)
        return z, zp

    def reinitialize(self, t, z, zp, rtol=1e-6, atol=1e-6):
        """After an event: states kept, algebraic unknowns and every z' made consistent."""
        return reinitialize(self, t, z, zp, rtol=rtol, atol=atol)

    def output_point(self, t, z, rtol, every=False):
        """Solver contract item 17: z at an output time between steps, its algebraic
        unknowns solved from the interpolated states where the error test leaves some
        out (:func:`.initial.consistent_output`); None where that fails."""
        if not (self.uncontrolled or every):
            return z
        return consistent_output(self, t, z, rtol)

    # -- dynamic state selection ------------------------------------------------------------
    def reselect_states(self, t, z, hysteresis=0.5) -> bool:
        """Re-choose the dummy derivatives; True when the choice (and so F) changed."""
        if self.dynamic is None:
            return False
        vals = self._jac_values(t, z)
        if not np.all(np.isfinite(vals)):
            return False
        new = self.dynamic.choose(vals, z, self.dummies, hysteresis)
        if new == self.dummies:
            return False
        self.dummies = new
        self.dynamic.switches.append((t, sorted(self.names[d] for d in new)))
        self._update_links()
        return True

    def after_step(self, t, z, zp) -> bool:
        """Called by the driver after each accepted step: offsets of items armed at zero
        are released once they have left it, and states are re-chosen (dynamic state
        selection)."""
        if self.n_roots:
            self.discrete.release(t, z, self.p)
        return self.reselect_states(t, z)

    # -- parameters (runtime/parameters.py) --------------------------------------------------
    def set_parameters(self, values: dict) -> None:
        """Change tunable parameters by name, e.g. ``{"R1.R": 5.0}`` (a parameter array
        by element, ``{"M[0,1]": 0.5}``, or whole, ``{"M": matrix}``): all or none (a value
        outside its bounds, or one that puts a parameter bound to it outside its own,
        changes nothing)."""
        self.p[:] = tuned_parameters(self, values)

    def _no_parameter(self, name) -> str:
        return no_parameter_message(self, name)
