"""The integer structure that the structural passes read and return.

Matching, Pantelides, state selection, BLT and tearing work only on this: integers and
small flags, never sympy expressions (the symbolic layer before and after them is
:mod:`acausal.compiler.frontend.flatten`, :mod:`acausal.compiler.algebra.symbolic` and
:mod:`acausal.compiler.backends.codegen`).  The layout follows the contract of the
StateSelection package of ModelingToolkit (``var_to_diff``, ``eq_to_diff``, a bipartite
graph), written again here for our own passes.

Conventions
-----------
* Variables ``0 .. n_vars-1`` include derivative variables: ``var_to_diff[v]`` is the
  variable that stands for der(v), or ``UNASSIGNED``; ``diff_to_var`` is its inverse.
* Equations ``0 .. n_eqs-1``: ``eq_to_diff[e]`` is the equation d/dt(e) once it has been
  created by index reduction, or ``UNASSIGNED``; ``diff_to_eq`` is its inverse.
* ``graph[e]`` is the sorted list of variables that occur in equation e.
* ``coeff[e][v]`` says how v enters e, for state selection and tearing:
  ``LINEAR_CONST`` (linear with a non-zero constant coefficient: always solvable),
  ``LINEAR_PARAM`` (linear, coefficient depends on parameters only),
  ``LINEAR_VAR`` (linear, coefficient depends on other variables or time: solvable only
  where that coefficient is non-zero), ``NONLINEAR``.
* ``var_names`` / ``eq_names`` are for messages only; no algorithm may branch on them.
  ``eq_names`` may be a :class:`Names`, whose entries are printed when first read.
* ``state_priority[v]``: the user's hint, one of the STATE_SELECT values below
  (higher = more wanted as a state).
* ``tie_break[v]``: among variables of equal ``state_priority``, higher = more wanted
  as a state: what the user said of v's initial value and scale, as Modelica tools
  read it (:func:`state_tie_break`).
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

__all__ = [
    "UNASSIGNED", "LINEAR_CONST", "LINEAR_PARAM", "LINEAR_VAR", "NONLINEAR",
    "NEVER", "AVOID", "DEFAULT", "PREFER", "ALWAYS", "STATE_SELECT", "Structure", "Names",
    "state_tie_break",
]


def state_tie_break(fixed, nominal) -> int:
    """The rank of a declared variable among candidates of equal StateSelect: one with a
    fixed start value first (its initial condition then applies to a state, as written,
    rather than to an algebraic function of other states), then one with a nominal value
    of its own (its error is then judged on the scale the user gave)."""
    return 2 * bool(fixed) + (nominal is not None)


class _Unassigned:
    """Typed sentinel for 'no partner' in matchings and derivative maps."""

    _instance = None

    def __new__(cls):
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self):
        return "UNASSIGNED"

    def __bool__(self):
        return False

    def __reduce__(self):
        return (_Unassigned, ())


UNASSIGNED = _Unassigned()

LINEAR_CONST, LINEAR_PARAM, LINEAR_VAR, NONLINEAR = 0, 1, 2, 3

NEVER, AVOID, DEFAULT, PREFER, ALWAYS = 0, 1, 2, 3, 4
STATE_SELECT = {"never": NEVER, "avoid": AVOID, "default": DEFAULT,
                "prefer": PREFER, "always": ALWAYS}


class Names(Sequence):
    """A list of names for messages whose entries may be made when first read.

    An entry is a string or a function of no arguments that returns one (kept once
    called).  Equation texts are slow to print and most are never shown, so the
    structures of large models name their equations this way.  Reads like a list of
    strings (indexing, slices, iteration, ``==`` with a list) and grows by ``append``.
    """

    __slots__ = ("_items",)

    def __init__(self, items=()):
        self._items = list(items._items) if isinstance(items, Names) else list(items)

    def __len__(self) -> int:
        return len(self._items)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return [self[i] for i in range(*k.indices(len(self._items)))]
        item = self._items[k]
        if not isinstance(item, str):
            item = self._items[k] = item()
        return item

    def append(self, item) -> None:
        self._items.append(item)

    def __eq__(self, other):
        if isinstance(other, (Names, list, tuple)):
            return list(self) == list(other)
        return NotImplemented

    __hash__ = None

    def __repr__(self) -> str:
        return repr(list(self))

    def __reduce__(self):
        return (Names, (list(self),))     # copies and pickles hold the texts themselves


@dataclass
class Structure:
    graph: list                      # eq -> sorted list of vars
    var_to_diff: list                # var -> var of its derivative, or UNASSIGNED
    eq_to_diff: list                 # eq -> eq of its derivative, or UNASSIGNED
    coeff: list = None               # eq -> {var: LINEAR_CONST | ... | NONLINEAR}
    var_names: list = None
    eq_names: list = None
    state_priority: list = None
    diff_to_var: list = field(default=None)
    tie_break: list = None           # var -> rank among equal priorities (STATE_TIE_BREAK)
    diff_to_eq: list = field(default=None)

    def __post_init__(self):
        if self.coeff is None:
            self.coeff = [{v: NONLINEAR for v in vs} for vs in self.graph]
        if self.var_names is None:
            self.var_names = [f"v{i}" for i in range(len(self.var_to_diff))]
        if self.eq_names is None:
            self.eq_names = [f"e{i}" for i in range(len(self.graph))]
        if self.state_priority is None:
            self.state_priority = [DEFAULT] * len(self.var_to_diff)
        if self.tie_break is None:
            self.tie_break = [0] * len(self.var_to_diff)
        if self.diff_to_var is None:
            self.diff_to_var = _invert(self.var_to_diff)
        if self.diff_to_eq is None:
            self.diff_to_eq = _invert(self.eq_to_diff)

    @property
    def n_vars(self) -> int:
        return len(self.var_to_diff)

    @property
    def n_eqs(self) -> int:
        return len(self.graph)

    def var_eqs(self) -> list:
        """The transposed graph: var -> sorted list of equations it occurs in."""
        out = [[] for _ in range(self.n_vars)]
        for e, vs in enumerate(self.graph):
            for v in vs:
                out[v].append(e)
        return out

    def order(self, v: int) -> int:
        """How many times v is differentiated from its base variable."""
        k = 0
        while self.diff_to_var[v] is not UNASSIGNED:
            v = self.diff_to_var[v]
            k += 1
        return k


def _invert(to_diff: list) -> list:
    inv = [UNASSIGNED] * len(to_diff)
    for a, b in enumerate(to_diff):
        if b is not UNASSIGNED:
            inv[b] = a
    return inv
