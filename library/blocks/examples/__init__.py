"""Examples of the signal blocks."""
