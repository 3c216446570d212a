"""Examples of Modelica.Mechanics.Rotational (MSL v4.0.0), each checked against the MSL's
reference result (``tests/msl``).

Written but not yet compared (no ``msl_name``): ``Friction``, ``CoupledClutches``,
``SimpleGearShift``, ``LossyGearDemo1``, ``LossyGearDemo2`` and ``LossyGearDemo3``, whose
references compare the Integer ``mode`` and the Boolean ``startForward`` /
``startBackward`` of their friction elements, which the language cannot declare yet.
"""
