"""Parameter records of electric machines' losses (Modelica.Electrical.Machines.Losses,
MSL v4.0.0) and the passing of a record to a component inside a machine.

A record is a component with parameters only.  A machine holds one record per kind of
loss (``frictionParameters``, ``coreParameters``, ``strayLoadParameters``,
``brushParameters``), modified like any sub-component (``DC_PermanentMagnet(
frictionParameters={"PRef": 100.0})``), and passes it to its loss component as the
MSL's ``Friction friction(final frictionParameters=frictionParameters)``: the loss
component's own record has every parameter bound to the machine's (:func:`passed`).

The MSL writes the derived values as ``if PRef <= 0 then 0 else PRef/wRef``; PRef has
the minimum 0, so PRef <= 0 is PRef = 0, where PRef/wRef is 0 too: the records write
the quotient alone.
"""
import acausal as ac

__all__ = ["Record", "FrictionParameters", "CoreParameters", "StrayLoadParameters",
           "BrushParameters", "passed", "SMALL"]

SMALL = 1e-60        # Modelica.Constants.small


class Record(ac.Component):
    """Parameters only (a Modelica record)."""


class FrictionParameters(Record):
    """Friction losses (Modelica.Electrical.Machines.Losses.FrictionParameters):

        tauRef = PRef / wRef,   wLinear = linear wRef,
        tauLinear = tauRef (wLinear / wRef)^power_w
    """

    PRef = ac.Parameter(0.0, unit="W", min=0, description="reference friction losses at "
                                                          "wRef")
    wRef = ac.Parameter(1.0, unit="rad/s", min=SMALL, description="reference angular "
                        "velocity that the PRef refer to")
    power_w = ac.Parameter(2.0, unit="1", min=SMALL, description="exponent of friction "
                           "torque w.r.t. angular velocity")
    linear = ac.Parameter(0.001, unit="1", description="linear angular velocity range "
                          "with respect to reference angular velocity")
    tauRef = ac.Parameter(lambda c: c.PRef / c.wRef, unit="N.m",
                          description="reference friction torque at wRef")
    wLinear = ac.Parameter(lambda c: c.linear * c.wRef, unit="rad/s",
                           description="linear angular velocity range")
    tauLinear = ac.Parameter(lambda c: c.tauRef * (c.wLinear / c.wRef)**c.power_w,
                             unit="N.m", description="torque at wLinear")


class CoreParameters(Record):
    """Core losses (Modelica.Electrical.Machines.Losses.CoreParameters):

        GcRef = PRef / VRef^2 / m

    (hysteresis losses are not implemented in the MSL either: ratioHysteresis = 0).
    """

    m = ac.Parameter(1.0, unit="1", description="number of phases (1 for DC)")
    PRef = ac.Parameter(0.0, unit="W", min=0, description="reference core losses at VRef")
    VRef = ac.Parameter(1.0, unit="V", min=SMALL, description="reference inner RMS "
                        "voltage that PRef refers to")
    wRef = ac.Parameter(1.0, unit="rad/s", min=SMALL, description="reference angular "
                        "velocity that PRef refers to")
    GcRef = ac.Parameter(lambda c: c.PRef / c.VRef**2 / c.m, unit="S",
                         description="reference conductance at VRef and wRef")
    wMin = ac.Parameter(lambda c: 1e-6 * c.wRef, unit="rad/s",
                        description="angular velocity limit")


class StrayLoadParameters(Record):
    """Stray load losses (Modelica.Electrical.Machines.Losses.StrayLoadParameters):

        tauRef = PRef / wRef
    """

    PRef = ac.Parameter(0.0, unit="W", min=0, description="reference stray load losses "
                                                          "at IRef and wRef")
    IRef = ac.Parameter(1.0, unit="A", min=SMALL, description="reference RMS current that "
                                                              "PRef refers to")
    wRef = ac.Parameter(1.0, unit="rad/s", min=SMALL, description="reference angular "
                        "velocity that PRef refers to")
    power_w = ac.Parameter(1.0, unit="1", min=SMALL, description="exponent of stray load "
                           "loss torque w.r.t. angular velocity")
    tauRef = ac.Parameter(lambda c: c.PRef / c.wRef, unit="N.m",
                          description="reference stray load torque at IRef and wRef")


class BrushParameters(Record):
    """Brush losses (Modelica.Electrical.Machines.Losses.BrushParameters)."""

    V = ac.Parameter(0.0, unit="V", description="total voltage drop of brushes for "
                                                "currents > ILinear")
    ILinear = ac.Parameter(0.01, unit="A", description="current indicating linear voltage "
                                                       "region of brush voltage drop")


def passed(owner: ac.Component, name: str) -> dict:
    """The modification that gives a component's record the values of ``owner``'s
    record ``name`` (Modelica's ``final record = record``): each parameter that is not
    derived from the others, bound to the owner's."""
    record_type = type(getattr(owner, name))
    own = {}
    for field, decl in record_type().declarations().items():
        if callable(decl.value):
            continue                       # derived: follows the passed parameters
        own[field] = _reader(owner, name, field)
    return own


def _reader(owner, name, field):
    return lambda _: getattr(getattr(owner, name), field)
