"""Electrical examples: each module is runnable (``python -m``) and each model has a
``stop_time``."""
