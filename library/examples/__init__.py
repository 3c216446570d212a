"""Whole systems: runnable models with a fixed stop time (each doubles as a test)."""
