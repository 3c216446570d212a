"""Examples of Modelica.Electrical.Analog (MSL v4.0.0), each checked against the MSL's
reference result (``tests/msl``)."""
