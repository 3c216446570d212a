"""Regularized sign functions of the MSL's speed-dependent sources and resistances
(Modelica.Blocks.Types.Regularization: Exp, Sine, Linear, CoSine), as used by
Rotational.Sources.SignTorque, Translational.Sources.SignForce and
Translational.Components.RollingResistance."""
from __future__ import annotations

import acausal as ac

__all__ = ["REGULARIZATIONS", "regularized_sign", "check_regularization"]

REGULARIZATIONS = ("Exp", "Sine", "Linear", "CoSine")


def check_regularization(reg, owner: str) -> str:
    if reg not in REGULARIZATIONS:
        raise ac.ModelError(f"{owner}: reg must be one of {', '.join(REGULARIZATIONS)}, "
                            f"not {reg!r}")
    return reg


def regularized_sign(x, x0, reg: str):
    """sign(x) made continuous below |x| = x0:

        Exp      2 / (1 + exp(-x / (0.01 x0))) - 1   (= tanh(x / (0.02 x0)), which does
                                                      not overflow)
        Sine     sign(x) for |x| >= x0, else sin(pi/2 x/x0)
        Linear   sign(x) for |x| >= x0, else x/x0
        CoSine   sign(x) for |x| >= x0, else sign(x) (1 - cos(pi/2 x/x0))

    The corners |x| = x0 are events; inside, the CoSine branch's sign is evaluated
    without events (the branch is continuous with its derivative at 0)."""
    if reg == "Exp":
        return ac.tanh(x / (0.02 * x0))
    inner = {"Sine": lambda: ac.sin(ac.pi / 2 * x / x0),
             "Linear": lambda: x / x0,
             "CoSine": lambda: ac.no_event(ac.sign(x)) * (1 - ac.cos(ac.pi / 2 * x / x0))}
    return ac.if_else(x >= x0, 1, ac.if_else(x <= -x0, -1, inner[reg]()))
