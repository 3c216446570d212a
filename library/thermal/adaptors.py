"""Signal adaptors of a heat port, for models cut into input/output blocks (FMUs)
(Modelica.Thermal.HeatTransfer.Components.GeneralHeatFlowToTemperatureAdaptor and
GeneralTemperatureToHeatFlowAdaptor, MSL v4.0.0, after Modelica.Blocks.Interfaces.
Adaptors.FlowToPotentialAdaptor / PotentialToFlowAdaptor).

The MSL's optional derivative connectors are chosen where the adaptor is made, as
other ports that exist or not (``useSupport``): ``use_pder=True`` (the MSL's default)
adds ``pder``, the time derivative of the temperature.  The second derivatives and the
derivatives of the heat flow (``use_pder2``, ``use_fder``, ``use_fder2``) are final
false in the MSL's heat-port adaptors and are not here either.
"""
import acausal as ac
from acausal.ports import HeatPort, RealInput, RealOutput

__all__ = ["GeneralHeatFlowToTemperatureAdaptor", "GeneralTemperatureToHeatFlowAdaptor"]


class _Adaptor(ac.Component):
    """The heat port and the ``use_pder`` choice shared by both adaptors."""

    heatPort = HeatPort()

    energy_role = "source"   # the heat port's power comes from outside through signals

    def __init__(self, *, use_pder=True, **modifications):
        super().__init__(**modifications)
        if not isinstance(use_pder, bool):
            raise ac.ModelError(f"{type(self).__name__}: use_pder must be True or False, "
                                f"not {use_pder!r}")
        object.__setattr__(self, "use_pder", use_pder)
        if use_pder:
            self.pder = self._pder_port()


class GeneralHeatFlowToTemperatureAdaptor(_Adaptor):
    """Heat flow in, temperature out (the side of a block that holds the capacity):

        p = heatPort.T,   pder = der(p)  (with use_pder),   heatPort.Q_flow = f

    f [W] is the heat flow leaving the connected capacity through the adaptor.
    """

    p = RealOutput()
    f = RealInput()

    @staticmethod
    def _pder_port():
        return RealOutput()

    def equations(self):
        eqs = [ac.Eq(self.p, self.heatPort.T), ac.Eq(self.heatPort.Q_flow, self.f)]
        if self.use_pder:
            eqs.append(ac.Eq(self.pder, ac.der(self.p)))
        return eqs


class GeneralTemperatureToHeatFlowAdaptor(_Adaptor):
    """Temperature in, heat flow out (the side of a block driven by a temperature):

        heatPort.T = p,   f = -heatPort.Q_flow

    f [W] is the heat flow that the adaptor delivers into what it is connected to.
    With use_pder the input ``pder`` is the derivative of p, which the MSL attaches to
    p (Modelica.Blocks.Types functions ``state1``) for a tool that must differentiate p
    without seeing where it comes from.  Here index reduction differentiates p through
    the model that produces it, which gives der(p) itself; ``pder`` is an input of the
    block (it must be connected, as in the MSL) and enters no equation.
    """

    p = RealInput()
    f = RealOutput()

    @staticmethod
    def _pder_port():
        return RealInput()

    def equations(self):
        return [ac.Eq(self.heatPort.T, self.p), ac.Eq(self.f, -self.heatPort.Q_flow)]
