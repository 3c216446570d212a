"""The sympy side of the compiler: the symbolic system behind the integer structure,
partial derivatives and linear solves read off the expressions, substitutions built in
sympy's canonical form, and exact rational arithmetic."""
from .derivative import partial, simple_partials, solve_linear
from .exact import coefficient_oracle, exact_rank, exact_value
from .substitution import fast_difference, fast_xreplace
from .symbolic import SymbolicEquation, SymbolicSystem, forget_expressions, symbols_of

__all__ = ["SymbolicSystem", "SymbolicEquation", "symbols_of", "forget_expressions",
           "partial", "simple_partials", "solve_linear", "fast_xreplace", "fast_difference",
           "exact_value", "exact_rank", "coefficient_oracle"]
