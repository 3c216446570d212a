"""Numeric checks of the structural decisions: balance, Pryce's success test and the LC
conversion, index reduction joined to the symbolic system, exact and modular ranks."""
