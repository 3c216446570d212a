"""The sympy side of the compiler: the symbolic system, partial derivatives,
substitutions, exact arithmetic."""
