"""Showcase: a DC motor driving a load inertia through an elastic shaft, 24 V step.

Egeland & Gravdahl 3.3 (the DC motor) and 3.5 (motor and load with an elastic
transmission).  Run ``python -m acausal.library.examples.motor_drive --plot out.png``
(``make demo``): it compiles the model, prints the index report, simulates 2 s and
writes a plot.
"""
from __future__ import annotations

import argparse

import acausal as ac
from acausal.library.electrical import Ground, StepVoltage
from acausal.library.electromechanical import DCMotor
from acausal.library.rotational import Damper, Fixed, Inertia, SpringDamper

__all__ = ["MotorDrive", "main"]


class MotorDrive(ac.Component):
    """24 V step on a DC motor; shaft c = 100 N m/rad, d = 0.01 N m s/rad; load J = 0.01,
    with viscous friction b = 1e-2 N m s/rad to the housing."""

    source = StepVoltage(V=24.0, startTime=0.1)
    ground = Ground()
    motor = DCMotor(R=1.0, L=1e-3, k=0.05, J=1e-4)
    shaft = SpringDamper(c=100.0, d=0.01)
    load = Inertia(J=0.01)
    bearing = Damper(d=1e-2)
    housing = Fixed()

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.shaft.flange_a),
                ac.connect(self.shaft.flange_b, self.load.flange_a),
                ac.connect(self.load.flange_b, self.bearing.flange_a),
                ac.connect(self.bearing.flange_b, self.housing.flange)]


def main(argv=None) -> ac.Result:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", default="motor_drive.png", help="PNG file to write")
    parser.add_argument("--t-end", type=float, default=5.0)
    args = parser.parse_args(argv)
    compiled = ac.compile(MotorDrive())
    print(compiled.report)
    res = ac.simulate(compiled, t_end=args.t_end, rtol=1e-6, n_points=1001)
    R, k, b, V = 1.0, 0.05, 1e-2, 24.0
    w_ss = k * V / (k * k + R * b)   # steady state: k i = b w, V = R i + k w
    print(f"\nsimulated {args.t_end} s: {res.stats.get('steps')} steps, "
          f"{res.stats.get('residual_evaluations')} residual evaluations")
    print(f"load speed at t_end: {res['load.w'][-1]:.4f} rad/s "
          f"(steady state k V / (k^2 + R b) = {w_ss:.4f} rad/s)")
    print(f"peak armature current: {abs(res['motor.La.i']).max():.3f} A")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
        res.plot("motor.rotor.w", "load.w", ax=a1)
        a1.set_ylabel("speed [rad/s]")
        res.plot("shaft.tau", ax=a2)
        a2.set_ylabel("shaft torque [N m]")
        fig.suptitle("DC motor driving an elastic load (24 V step)")
        fig.savefig(args.plot, dpi=120, bbox_inches="tight")
        print(f"plot written to {args.plot}")
    except ImportError:
        print("matplotlib is not installed: no plot (pip install 'acausal[plot]')")
    return res


if __name__ == "__main__":
    main()
