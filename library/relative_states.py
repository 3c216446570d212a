"""Relative states of compliant elements: the MSL's ``stateSelect`` parameter of
``PartialCompliantWithRelativeStates``.

A stiff shaft between two inertias turning far from their start moves its ends by large
absolute angles while it twists by a tiny relative one.  Integrated as the difference
of two absolute states, the twist keeps only the digits the absolute angles leave it
(and their error tolerance, rtol |phi|, can exceed the twist itself).  Made a state of
its own, phi_rel is integrated to its own tolerance:
``SpringDamper(stateSelect="prefer")`` makes phi_rel and w_rel preferred states (the
MSL's default), and phi_rel has a small nominal value (the MSL's
``phi_nominal = 1e-4``, translational ``s_nominal``; a constructor argument as
stateSelect) so that its absolute tolerance is on its own scale.

The default here is ``stateSelect="default"``, which keeps the states a model had with
the plain ``PartialCompliant``.  The relative speed can only be a state if its
derivative appears in the model, so the relative acceleration ``acc.a_rel`` =
der(w_rel) exists only with "prefer" or "always" (a sub-component created in
``__init__``): otherwise it would make index reduction differentiate the element's law
wherever it ends on a massless flange or a gear, for a variable nobody asked for.
Keeping the states matters beyond accuracy: a start value given without ``fixed=True``
is used only when its variable is a state, so a change of states would start a model
from w_rel = 0 instead of from its inertias' starts.  ``stateSelect`` is an argument
of the constructor (a priority, not a number); an explicit ``state_select`` in a
modification of phi_rel or w_rel takes precedence.
"""
from dataclasses import replace

import acausal as ac

__all__ = ["RelativeStatesMixin", "AngularAcceleration", "LinearAcceleration"]

_CHOICES = ("never", "avoid", "default", "prefer", "always")


class AngularAcceleration(ac.Component):
    """The relative acceleration of a rotational element with relative states."""

    a_rel = ac.Variable(unit="rad/s2", description="relative angular acceleration der(w_rel)")


class LinearAcceleration(ac.Component):
    """The relative acceleration of a translational element with relative states."""

    a_rel = ac.Variable(unit="m/s2", description="relative acceleration der(v_rel)")


class RelativeStatesMixin:
    """Applies ``stateSelect`` to the (position, speed) pair named in
    ``_relative_states`` and, for "prefer" and "always", creates ``acc`` (an
    ``_acceleration`` cell) whose a_rel = der(speed) makes the speed a candidate state."""

    _relative_states: tuple = ()
    _acceleration: type = AngularAcceleration
    _nominal_name: str = "phi_nominal"

    def _select(self, stateSelect, nominal: float = 1e-4) -> None:
        """``stateSelect`` as described above; ``nominal`` (the MSL's ``phi_nominal`` /
        ``s_nominal``, >= 0) the nominal value of the relative position, 1 where it is
        below machine epsilon (as the MSL)."""
        if stateSelect not in _CHOICES:
            raise ac.ModelError(f"{type(self).__name__}: stateSelect must be one of "
                                f"{', '.join(_CHOICES)}, not {stateSelect!r}")
        if isinstance(nominal, bool) or not isinstance(nominal, (int, float)) \
                or not nominal >= 0 or nominal == float("inf"):
            raise ac.InvalidValue(f"{type(self).__name__}: {self._nominal_name} must be a "
                                  f"finite number >= 0, not {nominal!r}")
        object.__setattr__(self, "stateSelect", stateSelect)
        object.__setattr__(self, self._nominal_name, float(nominal))
        if stateSelect in ("prefer", "always"):
            self.acc = self._acceleration()

    def acceleration_equations(self) -> list:
        """a_rel = der(speed) when the relative speed may be a state, else nothing."""
        if "acc" not in self.__dict__:
            return []
        speed = getattr(self, self._relative_states[1])
        return [ac.Eq(self.acc.a_rel, ac.der(speed))]

    def variable_attributes(self, name: str):
        attrs = super().variable_attributes(name)
        mod = self._mods.get(name)
        given = mod if isinstance(mod, dict) else {}
        if name in self._relative_states and "state_select" not in given:
            attrs = replace(attrs, state_select=self.stateSelect)
        if name == self._relative_states[0] and "nominal" not in given:
            nominal = getattr(self, self._nominal_name)
            attrs = replace(attrs, nominal=nominal if nominal >= 2.220446049250313e-16
                            else 1.0)
        return attrs
