"""Relative states of compliant elements: the MSL's ``stateSelect`` parameter of
``PartialCompliantWithRelativeStates``.

A stiff shaft between two inertias turning far from their start moves its ends by large
absolute angles while it twists by a tiny relative one.  Integrated as the difference
of two absolute states, the twist keeps only the digits the absolute angles leave it
(and their error tolerance, rtol |phi|, can exceed the twist itself).  Made a state of
its own, phi_rel is integrated to its own tolerance:
``SpringDamper(stateSelect="prefer")`` makes phi_rel and w_rel preferred states (the
MSL's default), and phi_rel has a small nominal value (the MSL's
``phi_nominal = 1e-4``) so that its absolute tolerance is on its own scale.

The default here is ``stateSelect="default"``, which keeps the states a model had with
the plain ``PartialCompliant``: phi_rel competes with the inertias' angles by the
compiler's usual rule, and w_rel -- a candidate at all only through a_rel = der(w_rel)
-- is kept below the inertias' speeds ("avoid").  This matters beyond accuracy: a start
value given without ``fixed=True`` is used only when its variable is a state, so a
change of states would start a model from w_rel = 0 instead of from its inertias'
starts.  ``stateSelect`` is an argument of the constructor (a priority, not a number);
an explicit ``state_select`` in a modification of phi_rel or w_rel takes precedence.
"""
from dataclasses import replace

import acausal as ac

__all__ = ["RelativeStatesMixin"]

_CHOICES = ("never", "avoid", "default", "prefer", "always")


class RelativeStatesMixin:
    """Applies ``stateSelect`` to the (position, speed) pair named in
    ``_relative_states``; with "default" the speed is "avoid" (module docstring)."""

    _relative_states: tuple = ()

    def _select(self, stateSelect) -> None:
        if stateSelect not in _CHOICES:
            raise ac.ModelError(f"{type(self).__name__}: stateSelect must be one of "
                                f"{', '.join(_CHOICES)}, not {stateSelect!r}")
        object.__setattr__(self, "stateSelect", stateSelect)

    def variable_attributes(self, name: str):
        attrs = super().variable_attributes(name)
        mod = self._mods.get(name)
        if name in self._relative_states and not (isinstance(mod, dict)
                                                  and "state_select" in mod):
            choice = self.stateSelect
            if choice == "default" and name == self._relative_states[1]:
                choice = "avoid"
            attrs = replace(attrs, state_select=choice)
        return attrs
