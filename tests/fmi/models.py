"""Models for the FMI tests, and the comparison of an FMU's run with acausal's own."""
import numpy as np

import acausal as ac
from acausal.library import electrical as el
from acausal.ports import RealInput, RealOutput


class BouncingBall(ac.Component):
    """h'' = -g; when h < 0: v := -e pre(v)."""

    g = ac.Parameter(9.81, unit="m/s2")
    e = ac.Parameter(0.8, description="coefficient of restitution")
    h = ac.Variable(start=1.0, fixed=True, unit="m")
    v = ac.Variable(start=0.0, fixed=True, unit="m/s")

    def equations(self):
        return [ac.Eq(ac.der(self.h), self.v), ac.Eq(ac.der(self.v), -self.g),
                ac.when(self.h < 0, ac.reinit(self.v, -self.e * ac.pre(self.v)))]


class IdealRectifier(ac.Component):
    """5 V, 50 Hz (phase -0.3 rad) through 1 Ohm and an ideal diode into 100 uF || 100 Ohm:
    the diode's relation switches at state events."""

    source = el.SineVoltage(V=5.0, f=50.0, phase=-0.3)
    Rs = el.Resistor(R=1.0)
    diode = el.IdealDiode()
    C = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    load = el.Resistor(R=100.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.Rs.p), ac.connect(self.Rs.n, self.diode.p),
                ac.connect(self.diode.n, self.C.p, self.load.p),
                ac.connect(self.source.n, self.C.n, self.load.n, self.ground.p)]


class DiodeClamp(ac.Component):
    """5 V, 50 Hz through 10 Ohm and an exponential diode into 100 uF || 100 Ohm: a
    nonlinear torn loop (the resistor's voltage), solved by Newton inside the FMU."""

    source = el.SineVoltage(V=5.0, f=50.0)
    Rs = el.Resistor(R=10.0)
    diode = el.Diode()
    C = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    load = el.Resistor(R=100.0)
    ground = el.Ground()

    def equations(self):
        return [ac.connect(self.source.p, self.Rs.p), ac.connect(self.Rs.n, self.diode.p),
                ac.connect(self.diode.n, self.C.p, self.load.p),
                ac.connect(self.source.n, self.C.n, self.load.n, self.ground.p)]


class PulsedRC(ac.Component):
    """A 500 Hz pulse train (30 % high) into 10 Ohm and 10 uF: time events, of a relation
    and of a frozen floor value of time."""

    src = el.PulseVoltage(V=1.0, width=30.0, period=0.002)
    R = el.Resistor(R=10.0)
    C = el.Capacitor(C=1e-5, v={"start": 0.0, "fixed": True})
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.C.p),
                ac.connect(self.C.n, self.src.n, self.gnd.p)]


class Lag(ac.Component):
    """A first-order lag driven by a top-level input: T x' = u - x, y = 2 x."""

    u = RealInput()
    y = RealOutput()
    T = ac.Parameter(0.5, unit="s", description="time constant")
    x = ac.Variable(start=0.0, fixed=True, unit="m")

    def equations(self):
        return [ac.Eq(self.T * ac.der(self.x), self.u.signal - self.x),
                ac.Eq(self.y.signal, 2 * self.x)]


class Ship(ac.Component):
    """Nomoto's model with the rudder's rate: T r' + r = K (T_a delta' + delta); index
    reduction differentiates the input delta."""

    delta = RealInput()
    r = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(10.0 * ac.der(self.r) + self.r,
                      0.5 * (2.0 * ac.der(self.delta.signal) + self.delta.signal))]


def cases():
    """(id, model class, t_end, signals compared)."""
    from acausal.library.electromechanical.examples.elastic_transmission import \
        ElasticTransmission
    from acausal.library.examples.motor_drive import MotorDrive
    from acausal.library.hydraulics.examples.valve_motor import ValveControlledMotor
    return [("motor_drive", MotorDrive, 1.0, ["load.w", "motor.La.i", "shaft.tau"]),
            ("elastic_transmission", ElasticTransmission, 40.0,
             ["load.phi", "motor.w", "shaft.tau"]),
            ("bouncing_ball", BouncingBall, 2.5, ["h", "v"]),
            ("ideal_rectifier", IdealRectifier, 0.04, ["C.v", "diode.i"]),
            ("diode_clamp", DiodeClamp, 0.04, ["C.v", "diode.i"]),
            ("pulsed_rc", PulsedRC, 0.009, ["C.v", "R.i"]),
            ("valve_motor", ValveControlledMotor, 0.5, ["load.phi", "load.w", "line_1.p"])]


def fmu_errors(fmu, cls, t_end, names, rtol, parameters=None, **kwargs):
    """Max over ``names`` of max |FMU - acausal| / max |acausal| (acausal at rtol 1e-10),
    the FMU run by fmpy at ``rtol``; points at acausal's events are left out (there the
    value before and after the event are both right).  Returns (errors, fmpy result)."""
    from fmpy import simulate_fmu
    res = simulate_fmu(fmu, stop_time=t_end, relative_tolerance=rtol,
                       output_interval=t_end / 400, output=names,
                       start_values=parameters or {}, **kwargs)
    t, first = np.unique(res["time"], return_index=True)
    ref = ac.simulate(cls(), t_end=t_end, rtol=1e-10, t_eval=t, parameters=parameters)
    events = np.asarray(ref.events, dtype=float)
    keep = np.array([not events.size or np.min(np.abs(events - x)) > 1e-6 * t_end for x in t])
    errors = {}
    for n in names:
        scale = np.max(np.abs(ref[n]))
        errors[n] = float(np.max(np.abs(res[n][first][keep] - ref[n][keep])) / scale)
    return errors, res
