"""Examples of the coolant-flow library."""
