"""The language to the flat model: flattening (arrays, der() of expressions, connection
sets), the unit check, integer functions frozen between events, discrete variables held
between events, delays read from a history, and alias elimination.  Flattening itself
is ``frontend.flatten.flatten`` (the module has the pass's name)."""
from .alias import AliasTable, eliminate_aliases, resolve_aliases_in
from .delays import DelayValue, extract_delays
from .discrete import DiscreteValue, freeze_integer_functions
from .sampled import (HeldValue, declare_discrete_variables, explain_overdetermined,
                      pre_after_aliases, reinit_targets_are_states, when_rows)
from .unitcheck import UnitCheck, check_units

__all__ = ["check_units", "UnitCheck", "freeze_integer_functions",
           "DiscreteValue", "declare_discrete_variables", "HeldValue", "pre_after_aliases",
           "explain_overdetermined", "reinit_targets_are_states", "when_rows",
           "extract_delays", "DelayValue", "eliminate_aliases", "resolve_aliases_in",
           "AliasTable"]
