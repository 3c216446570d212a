"""Every exception and warning acausal raises to its user, in one place.

Each is exported as ``acausal.<Name>``.  They live here, outside the packages that raise
them, so that the language, the compiler, the runtime, the solvers and the analyses
can all name them without importing each other.

    ModelError (ValueError)            the model as written cannot be compiled
        InvalidValue                   a value, attribute or parameter binding
        InvalidEquation                something that is not a valid equation
            DiscreteVariableError      a discrete variable used against its rules
        InvalidConnection              a connect() that is not valid
        InvalidHierarchy               a component inside itself, or held twice
        InvalidInheritance             equations() calling its base's, a bad @replaces
        InvalidIndex (also IndexError) an array index outside its shape
        NotInModel                     a name that is not part of the model
        AbsentComponent (also AttributeError)  a conditional part that is not there
        MissingInput                   a top-level input simulate was not given
        UnitError                      dimensions that do not agree
        StructuralError                a structural pass could not proceed
            IndexReductionFailed       Pantelides could not make the system matchable
                StructurallySingular   square, but no perfect matching exists
                    OverdeterminedModel    more equations than unknowns somewhere
                    UnderdeterminedModel   fewer equations than unknowns somewhere
    SimulationError (RuntimeError)     a simulation stopped before its end
    InitializationFailed (RuntimeError)    no consistent initial values
    BackendError (RuntimeError)        the C backend was asked for and cannot build
    CacheError (ValueError)            the compile cache configured wrongly
    InvalidArgument (ValueError)       an argument of a call that cannot mean anything
    OperatingPointError (ValueError)   no consistent operating point
        SteadyStateError               no isolated equilibrium
    ModeConflict (ValueError)          no mode of the relations that a point satisfies
    UnitWarning (UserWarning)          a dimensional inconsistency, check_units="warn"
    ModeWarning (UserWarning)          a linearization at a switching point
    InitialConditionWarning (UserWarning)  redundant initial conditions dropped
    TransferFunctionWarning (RuntimeWarning)   a transfer function recomputed
    CacheWarning (UserWarning)         the compile cache skipped or repaired
"""
from __future__ import annotations

from typing import Sequence

__all__ = ["ModelError", "InvalidValue", "InvalidEquation", "DiscreteVariableError",
           "InvalidConnection", "InvalidHierarchy", "InvalidInheritance", "InvalidIndex",
           "NotInModel", "AbsentComponent", "MissingInput", "UnitError", "StructuralError",
           "IndexReductionFailed", "StructurallySingular", "OverdeterminedModel", "UnderdeterminedModel",
           "UnderdeterminedInitialization", "SimulationError", "InitializationFailed",
           "BackendError", "CacheError",
           "CacheWarning", "InvalidArgument",
           "OperatingPointError", "SteadyStateError", "ModeConflict", "UnitWarning",
           "ModeWarning", "TransferFunctionWarning", "InitialConditionWarning"]


# -- the model as written ------------------------------------------------------------------
class ModelError(ValueError):
    """The model as written is not valid (unknown modification, bad connect, ...)."""


class InvalidValue(ModelError):
    """A parameter value or variable attribute that is not valid: not a real number,
    NaN, outside [min, max], infinite where an equation needs it finite, or a parameter
    binding that depends on a variable or on itself."""


class InvalidEquation(ModelError):
    """Something returned as an equation that is not one, an equation that determines
    nothing or can never hold, or der() of a constant."""


class DiscreteVariableError(InvalidEquation):
    """A discrete-time variable or a when-assignment used against its rules."""


class InvalidConnection(ModelError):
    """A connect() that is not valid: not ports, ports of different types, the same port
    twice, or a port that is not the writing component's or its sub-components'."""


class InvalidHierarchy(ModelError):
    """A component that contains itself, or one instance held at two places."""


class InvalidInheritance(ModelError):
    """An ``equations()`` (or ``initial_equations()``) that calls its base's, which the
    framework already includes, or an ``@ac.replaces`` naming a class that is not a base
    with equations of its own."""


class InvalidIndex(ModelError, IndexError):
    """An index outside an array's shape (indices count from 0, as in Python)."""


class NotInModel(ModelError):
    """An equation or connection uses a component, port, variable or symbol that is not
    part of the model being compiled."""


class AbsentComponent(ModelError, AttributeError):
    """A conditional port or sub-component (``ac.Conditional``) read or connected while
    the structural flag that makes it is False."""


class MissingInput(ModelError):
    """A top-level input of the model (an input port of the model itself that nothing in
    it drives) that ``simulate`` was not told how to drive (``inputs=``)."""


class UnitError(ModelError):
    """An equation whose sides or terms have different dimensions, a function of a
    quantity with a dimension, or a unit string that cannot be read."""


# -- the structure of the equations --------------------------------------------------------
class StructuralError(ModelError):
    """Base class: a structural pass could not proceed.

    Attributes
    ----------
    equations, variables : list of str
        User names of the equations / variables involved.
    diagnosis : StructuralDiagnosis or None
        The full diagnosis (indices, counts) when one was computed.
    """

    def __init__(self, message: str, equations: Sequence[str] = (),
                 variables: Sequence[str] = (), diagnosis=None):
        super().__init__(message)
        self.equations = list(equations)
        self.variables = list(variables)
        self.diagnosis = diagnosis


class IndexReductionFailed(StructuralError):
    """Index reduction (Pantelides) could not make the system matchable."""


class StructurallySingular(IndexReductionFailed):
    """Square, but no perfect matching of equations onto unknowns exists."""


class OverdeterminedModel(StructurallySingular):
    """More (independent) equations than unknowns in some part of the model."""


class UnderdeterminedModel(StructurallySingular):
    """Fewer equations than unknowns in some part of the model."""


class UnderdeterminedInitialization(StructuralError):
    """The initial system leaves an unknown without an equation: a parameter found by
    initialization (``fixed=False``) that no initial condition determines."""


# -- running it ----------------------------------------------------------------------------
class SimulationError(RuntimeError):
    """A simulation stopped before t_end.

    Carries ``t`` (where it stopped), ``reason``, ``variables`` (the names that dominated
    the error or the singular block, a best guess when so said) and ``partial`` (what
    was computed so far: a SolverOutput, or a Result once the model layer wraps it).
    """

    def __init__(self, message: str, t: float | None = None,
                 variables: Sequence[str] = (), partial=None):
        super().__init__(message)
        self.t = t
        self.reason = message
        self.variables = list(variables)
        self.partial = partial


class InitializationFailed(RuntimeError):
    """No consistent initial values could be computed.

    Carries ``t``, ``variables`` (names of the unknowns whose Newton corrections stayed
    largest; derivatives are written ``der(x)``), ``equations`` (labels of the largest
    remaining residuals, from ``problem.equation_names`` or ``"residual i"``) and
    ``residual`` (the final residual vector).
    """

    def __init__(self, message: str, t: float | None = None,
                 variables: Sequence[str] = (), equations: Sequence[str] = (),
                 residual=None):
        super().__init__(message)
        self.t = t
        self.variables = list(variables)
        self.equations = list(equations)
        self.residual = residual


class BackendError(RuntimeError):
    """``backend="c"`` was asked for and the generated C cannot be built (no C compiler,
    or the compiler failed); ``backend="auto"`` falls back to numpy instead."""


# -- the analyses --------------------------------------------------------------------------
class CacheError(ValueError):
    """The compile cache is configured wrongly (a malformed ``ACAUSAL_CACHE_SIZE``)."""


class CacheWarning(UserWarning):
    """The compile cache was skipped or repaired: a directory that cannot be created,
    written or trusted (compiling and running go on without it), or an entry or library
    that failed its checksum (removed, and compiled or built again)."""


class InvalidArgument(ValueError):
    """An argument of a call that cannot mean anything (``simulate(..., rtol=5)``,
    ``atol=0``, ``t_end`` before ``t_start``, ``n_points=1``), named with the value
    given; raised before any work is done."""


class OperatingPointError(ValueError):
    """No consistent operating point: the algebraic equations have no solution, or no
    mode of the relations is consistent with its own solution (``relations`` names
    them, in the user's words)."""

    def __init__(self, message: str, relations=()):
        super().__init__(message)
        self.relations = list(relations)


class SteadyStateError(OperatingPointError):
    """No isolated equilibrium: none found, a singular Jacobian (names the states), or
    no mode of the relations that the equilibrium satisfies (names the relations)."""


class ModeConflict(ValueError):
    """No mode assignment the point satisfies was found: ``relations`` lists the texts of
    the relations (and floor values) that the solutions contradicted."""

    def __init__(self, message: str, relations=(), tried: int = 0):
        super().__init__(message)
        self.relations, self.tried = list(relations), tried


# -- warnings ------------------------------------------------------------------------------
class UnitWarning(UserWarning):
    """A dimensional inconsistency found with ``check_units="warn"``."""


class ModeWarning(UserWarning):
    """The operating point sits where a relation switches (a kink of the model): the
    linearization is that of the mode named in the message (``StateSpace.modes``)."""


class InitialConditionWarning(UserWarning):
    """Redundant initial conditions (more than the states, or several fixing the same
    unknowns) held at the initial point with the others and were dropped."""


class TransferFunctionWarning(RuntimeWarning):
    """A transfer function's polynomials did not reproduce the state-space model and
    were recomputed by a slower, robust route."""
