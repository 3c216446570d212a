"""The exceptions a simulation can end with, shared by the runtime and the solvers.

They live here, outside both packages, so that the compiler can name them without
importing the solvers (the compiler emits code; only the runtime runs it).
"""
from __future__ import annotations

from typing import Sequence

__all__ = ["SimulationError", "InitializationFailed", "BackendError", "CacheError",
           "CacheWarning", "InvalidArgument"]


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
