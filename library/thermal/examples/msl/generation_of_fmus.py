"""Modelica.Thermal.HeatTransfer.Examples.GenerationOfFMUs (MSL v4.0.0): heat-transfer
components cut into input/output blocks, as they would be exported as FMUs.

Upper part: a heat capacity with its states (``DirectCapacity``, C = 1.1 J/K, heated by
a 1000 W, 2 Hz sine) gives its temperature and its derivative to a capacity driven by
them (``InverseCapacity``, C = 2.2 J/K), which returns the heat flow that takes.  Lower
part: the same two capacities joined by a conduction block (``Conduction``, G = 10
W/K) that needs only their temperatures.  The blocks are the example's
``Utilities`` (Modelica.Thermal.HeatTransfer.Examples.Utilities).
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.thermal import (GeneralHeatFlowToTemperatureAdaptor,
                                     GeneralTemperatureToHeatFlowAdaptor, HeatCapacitor,
                                     PrescribedHeatFlow, ThermalConductor)
from acausal.ports import RealInput, RealOutput

__all__ = ["GenerationOfFMUs", "DirectCapacity", "InverseCapacity", "Conduction"]


class DirectCapacity(ac.Component):
    """Input/output block of a heat capacity with states (Utilities.DirectCapacity):
    heated by Q_flowDrive and drained by Q_flow, it gives T and derT."""

    C = ac.Parameter(1.0, unit="J/K", min=0, description="heat capacity")
    heatCapacitor = HeatCapacitor(C=ac.ref("C"), T={"fixed": True, "start": 293.15})
    forceSource = PrescribedHeatFlow()
    Q_flowDrive = RealInput()
    heatFlowToTemperature = GeneralHeatFlowToTemperatureAdaptor(use_pder=True)
    T = RealOutput()
    derT = RealOutput()
    Q_flow = RealInput()

    def equations(self):
        return [ac.connect(self.heatFlowToTemperature.f, self.Q_flow),
                ac.connect(self.heatFlowToTemperature.p, self.T),
                ac.connect(self.heatFlowToTemperature.pder, self.derT),
                ac.connect(self.heatCapacitor.port, self.heatFlowToTemperature.heatPort),
                ac.connect(self.Q_flowDrive, self.forceSource.Q_flow),
                ac.connect(self.heatCapacitor.port, self.forceSource.port)]


class InverseCapacity(ac.Component):
    """Input/output block of a heat capacity driven by a temperature
    (Utilities.InverseCapacity): the heat flow Q_flow that makes it follow T."""

    C = ac.Parameter(1.0, unit="J/K", min=0, description="heat capacity")
    mass = HeatCapacitor(C=ac.ref("C"), T={"fixed": True, "start": 293.15})
    temperatureToHeatFlow = GeneralTemperatureToHeatFlowAdaptor()
    T = RealInput()
    derT = RealInput()
    Q_flow = RealOutput()

    def equations(self):
        return [ac.connect(self.temperatureToHeatFlow.f, self.Q_flow),
                ac.connect(self.temperatureToHeatFlow.p, self.T),
                ac.connect(self.temperatureToHeatFlow.pder, self.derT),
                ac.connect(self.temperatureToHeatFlow.heatPort, self.mass.port)]


class Conduction(ac.Component):
    """Input/output block of a conduction element (Utilities.Conduction): the heat
    flows at its two ends from the temperatures there."""

    G = ac.Parameter(1.0, unit="W/K", description="thermal conductance")
    temperatureToHeatFlow1 = GeneralTemperatureToHeatFlowAdaptor(use_pder=False)
    T1 = RealInput()
    Q_flow1 = RealOutput()
    thermalConductor = ThermalConductor(G=ac.ref("G"))
    T2 = RealInput()
    Q_flow2 = RealOutput()
    temperatureToHeatFlow2 = GeneralTemperatureToHeatFlowAdaptor(use_pder=False)

    def equations(self):
        return [ac.connect(self.Q_flow1, self.temperatureToHeatFlow1.f),
                ac.connect(self.temperatureToHeatFlow2.f, self.Q_flow2),
                ac.connect(self.temperatureToHeatFlow1.p, self.T1),
                ac.connect(self.temperatureToHeatFlow2.p, self.T2),
                ac.connect(self.temperatureToHeatFlow1.heatPort,
                           self.thermalConductor.port_a),
                ac.connect(self.thermalConductor.port_b,
                           self.temperatureToHeatFlow2.heatPort)]


class GenerationOfFMUs(ac.Component):
    """Sine heat flow 1000 W at 2 Hz; C = 1.1 and 2.2 J/K; G = 10 W/K."""

    msl_name = "Modelica.Thermal.HeatTransfer.Examples.GenerationOfFMUs"
    stop_time = 1.0
    tolerance = 1e-6

    sine1 = Sine(f=2.0, amplitude=1000.0)
    directCapacity = DirectCapacity(C=1.1)
    inverseCapacity = InverseCapacity(C=2.2)
    conductor = Conduction(G=10.0)
    capacitor3a = HeatCapacitor(C=1.1, T={"fixed": True, "start": 293.15})
    heatFlow3 = PrescribedHeatFlow()
    heatFlowToTemperature3a = GeneralHeatFlowToTemperatureAdaptor(use_pder=False)
    capacitor3b = HeatCapacitor(C=2.2, T={"fixed": True, "start": 293.15})
    heatFlowToTemperature3b = GeneralHeatFlowToTemperatureAdaptor(use_pder=False)

    def equations(self):
        return [ac.connect(self.sine1.y, self.directCapacity.Q_flowDrive),
                ac.connect(self.directCapacity.T, self.inverseCapacity.T),
                ac.connect(self.inverseCapacity.Q_flow, self.directCapacity.Q_flow),
                ac.connect(self.heatFlowToTemperature3a.f, self.conductor.Q_flow1),
                ac.connect(self.conductor.Q_flow2, self.heatFlowToTemperature3b.f),
                ac.connect(self.heatFlowToTemperature3a.p, self.conductor.T1),
                ac.connect(self.conductor.T2, self.heatFlowToTemperature3b.p),
                ac.connect(self.sine1.y, self.heatFlow3.Q_flow),
                ac.connect(self.heatFlow3.port, self.capacitor3a.port),
                ac.connect(self.capacitor3a.port, self.heatFlowToTemperature3a.heatPort),
                ac.connect(self.heatFlowToTemperature3b.heatPort, self.capacitor3b.port),
                ac.connect(self.directCapacity.derT, self.inverseCapacity.derT)]


if __name__ == "__main__":
    res = ac.simulate(GenerationOfFMUs(), t_end=GenerationOfFMUs.stop_time,
                      rtol=GenerationOfFMUs.tolerance)
    print(f"capacitor3a.T, capacitor3b.T at {res.t[-1]:g} s: {res['capacitor3a.T'][-1]:.6g},"
          f" {res['capacitor3b.T'][-1]:.6g} K")
