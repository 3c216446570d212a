"""Examples of Modelica.Thermal.HeatTransfer (MSL v4.0.0), each checked against the MSL's
reference result (``tests/msl``)."""
