"""The runtime layer: a compiled model running, between the generated code and the solvers.

The compiler (:mod:`acausal.compiler`) emits code and name maps
(:class:`~acausal.compiler.modelcode.ModelCode`) and never imports the solvers; the
solvers (:mod:`acausal.solvers`) integrate a :class:`~acausal.solvers.base.DAEProblem`
and never see names.  Everything a model needs while it runs lives here, in one place:

What the runtime provides (numbered, so the code can cite it)
--------------------------------------------------------------
1. ``CompiledModel`` (:mod:`.model`): the DAEProblem of the solver contract (residual,
   iteration matrix, pattern, algebraic mask, nominal values, names), built from the
   ModelCode, with the user's parameter values ``p`` (``set_parameters`` by name).
2. The discrete state (:mod:`.modes`): relation values and frozen floor values, changed
   only at events.  Each relation is judged on its own scale.  The zero-crossing
   functions given to the integrator are *oriented* (``oriented_roots = True``): they
   are >= 0 while the discrete state agrees with the solution, up to a tolerance in the
   relation's own units evaluated where the function is; at a (re)start ``arm`` raises
   the functions of items settled at zero by their rate until a step leaves them on
   their own side.
3. Events (``handle_event``): what crossed takes its value just after the event (the
   side the dynamics choose where a relation sits at zero); contradicted relations are
   settled (event iteration); when-clauses (:mod:`.events`) fire on their false -> true
   edge and re-initialize states.
4. Time events (``next_time_event``): relations and floor values of time alone that are
   linear in time between events (steps, ramps, pulses, samplers) switch at times known
   in advance; the integrator lands on them exactly.  They also stay in the
   zero-crossing functions: no relation is ever left out of the search.
5. Dynamic state selection (:mod:`.dynamic`, ``after_step``): dummy derivatives re-chosen
   by scaled pivoting where the structural choice is only locally valid.
6. Initialization, one path (:mod:`.initial`): ``initialize(t0)`` gives consistent
   (z, z') -- initial equations, fixed starts, start values of the free states, relations
   settled by a fixed point, and z' of *every* unknown; ``reinitialize`` does the same
   after an event with the states kept.  ``simulate``, the analyses and exports all use
   it.
7. The discrete state of every output point (``discrete_state``/``set_discrete_state``):
   results are evaluated in the modes the integrator used there, not recomputed (the
   exceptions: a model without states, whose modes are settled at each output point,
   and a ``Result`` built without recorded modes).
8. Failures in the generated code (a ``sqrt`` of a negative, a division by zero) make
   the point unusable (NaN, which Newton and the integrator treat as a failed iterate)
   and are kept in words in ``evaluation_errors``, naming the equation.
9. Delays (:mod:`.delays`): ``delay(expr, T)`` is read from a history of expr kept on
   the accepted solution (``commit``), written into ``p`` before every call of the
   generated code; the step is limited to the shortest T (``max_step``), jumps come
   back as time events at t_e + T, and the delayed values are recorded at every
   output point (``point_values``).
10. Values at output times between steps (``output_point``, solver contract item 17):
   where the error test leaves algebraic unknowns out (self-scaled derivatives), they
   are solved from G(t, z) = 0 at the interpolated states instead of interpolated
   (:func:`.initial.consistent_output`); a failed solve is counted and said.
11. Outputs the integrator does not see (computed only for the results, through an
   operation that can leave the finite numbers: ``sqrt``, ``log``, a division) are
   checked at every output point (``check_point``, solver contract item 19,
   :mod:`.diagnostics`): one that is NaN or inf ends the run, naming the variable, its
   equation and the time.
"""
from .. import _lazy_exports

__all__ = ["CompiledModel"]

# CompiledModel brings scipy.sparse; the other runtime modules can be imported without it
__getattr__, __dir__ = _lazy_exports(globals(), {".model": ("CompiledModel",)})
