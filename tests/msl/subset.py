"""The MSL examples that ``make test`` compares with their references: one or a few of
each package, chosen to reach every kind of component and event handling the examples
use; ``make test-msl`` (and CI) compares all of them."""

QUICK = {
    "Modelica.Mechanics.Rotational.Examples.First",
    "Modelica.Mechanics.Rotational.Examples.Backlash",
    "Modelica.Mechanics.Translational.Examples.ElastoGap",
    "Modelica.Mechanics.Translational.Examples.Vehicle",
    "Modelica.Blocks.Examples.BooleanNetwork1",
    "Modelica.Blocks.Examples.IntegerNetwork1",
    "Modelica.Mechanics.MultiBody.Examples.Elementary.Pendulum",
    "Modelica.Mechanics.MultiBody.Examples.Elementary.SpringWithMass",
    "Modelica.Blocks.Examples.Filter",
    "Modelica.Blocks.Examples.PID_Controller",
    "Modelica.Thermal.HeatTransfer.Examples.TwoMasses",
    "Modelica.Thermal.FluidHeatFlow.Examples.SimpleCooling",
    "Modelica.Thermal.FluidHeatFlow.Examples.OneMass",
    "Modelica.Electrical.Machines.Examples.DCMachines.DCPM_Start",
    "Modelica.Electrical.Machines.Examples.DCMachines.DCEE_Start",
    "Modelica.Electrical.Analog.Examples.CauerLowPassOPV",
    "Modelica.Electrical.Analog.Examples.OpAmps.InvertingAmplifier",
    "Modelica.Electrical.Analog.Examples.NandGate",
}
