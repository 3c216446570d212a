"""Examples of Modelica.Mechanics.Translational (MSL v4.0.0), each checked against the MSL's
reference result (``tests/msl``).

Written but not yet compared (no ``msl_name``): ``Brake`` and ``Friction``, whose
references compare the Integer ``mode`` and the Boolean ``startForward`` /
``startBackward`` of their friction elements, which the language cannot declare yet.
"""
