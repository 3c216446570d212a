"""How a block's states start: the MSL's ``Modelica.Blocks.Types.Init``.

``initType = ac.Init.parameter(ac.Init.NoInit)`` declares the choice on a block (a
structural parameter, given where the block is made: ``FirstOrder(initType="SteadyState")``),
and ``ac.Init.equations`` gives the initial equations it means:

============== ==============================================================
NoInit          none: the states start from their start values where nothing else
                fixes them (Modelica's rule for a free state), else from the model
SteadyState     der(x) = 0 for every state x
InitialState    x = x_start for every state
InitialOutput   y = y_start, and der(x) = 0 for the states the output leaves free
============== ==============================================================

A steady state of one variable of any component (an inertia's speed, a capacitor's
temperature) is the variable attribute ``steady``: ``Inertia(w={"steady": True})``
adds the initial equation der(w) = 0.
"""
from __future__ import annotations

from .declarations import Parameter

__all__ = ["Init"]


class Init:
    """The initialization choices of the MSL's blocks (module docstring)."""

    NoInit = "NoInit"
    SteadyState = "SteadyState"
    InitialState = "InitialState"
    InitialOutput = "InitialOutput"
    CHOICES = (NoInit, SteadyState, InitialState, InitialOutput)

    @staticmethod
    def parameter(default: str = "NoInit", description: str = "type of initialization"):
        """The block's ``initType``: a structural parameter, one of :attr:`CHOICES`."""
        return Parameter(default, choices=Init.CHOICES, description=description)

    @staticmethod
    def equations(init: str, states, x_start=(), output=None, y_start=None,
                  free_at_output=None) -> list:
        """The initial equations of the choice ``init`` for the block whose ``states``
        start at ``x_start`` (InitialState) and whose ``output`` starts at ``y_start``
        (InitialOutput; ``free_at_output``: the states then held at der(x) = 0, by
        default all of them but the first, as the MSL's transfer functions write it)."""
        from .symbols import Eq, der    # sympy: when a block's equations are written
        states = list(states)
        if init == Init.NoInit:
            return []
        if init == Init.SteadyState:
            return [Eq(der(x), 0) for x in states]
        if init == Init.InitialState:
            return [Eq(x, x0) for x, x0 in zip(states, x_start)]
        if init == Init.InitialOutput:
            rest = states[1:] if free_at_output is None else list(free_at_output)
            return [Eq(output, y_start)] + [Eq(der(x), 0) for x in rest]
        raise ValueError(f"initType = {init!r} is not one of {', '.join(Init.CHOICES)}")
