"""Electromechanical examples, DC motor drives of Egeland & Gravdahl ch. 3: each module is
runnable (``python -m``) and each model has a ``stop_time``."""
