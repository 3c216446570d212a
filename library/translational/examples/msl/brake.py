"""Modelica.Mechanics.Translational.Examples.Brake (MSL v4.0.0): braking a moving mass.

Two masses at 1 m/s are braked from 0.1 s on (f_normalized = 2, so the normal force is
twice fn_max): one by a brake whose housing is fixed implicitly, the other by a brake
on a support flange fixed explicitly.  Both stop in the same way.

Not yet compared with its reference: MAP-LIB compares the brakes' ``mode`` (Integer) and
``startForward``/``startBackward`` (Boolean) besides their Real signals, and the
language has no Integer or Boolean variables yet.
"""
import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Step

__all__ = ["Brake"]


class Brake(ac.Component):
    """m = 1 kg at 1 m/s; fn_max = 1 N, mu = 0.5; the step of height 2 at 0.1 s."""

    stop_time = 2.0
    tolerance = 1e-6

    brake = tr.Brake(fn_max=1.0, useSupport=False)
    mass1 = tr.Mass(m=1.0, s={"fixed": True}, v={"start": 1.0, "fixed": True})
    step = Step(startTime=0.1, height=2.0)
    brake1 = tr.Brake(fn_max=1.0, useSupport=True)
    mass2 = tr.Mass(m=1.0, s={"fixed": True}, v={"start": 1.0, "fixed": True})
    fixed = tr.Fixed()

    def equations(self):
        return [ac.connect(self.mass1.flange_b, self.brake.flange_a),
                ac.connect(self.step.y, self.brake.f_normalized),
                ac.connect(self.mass2.flange_b, self.brake1.flange_a),
                ac.connect(self.step.y, self.brake1.f_normalized),
                ac.connect(self.fixed.flange, self.brake1.support)]


if __name__ == "__main__":
    res = ac.simulate(Brake(), t_end=Brake.stop_time, rtol=Brake.tolerance)
    print(f"mass1.s at {res.t[-1]:g} s: {res['mass1.s'][-1]:.6g} m")
