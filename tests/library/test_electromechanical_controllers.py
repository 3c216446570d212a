"""The controllers of the DC machine examples: LimPID's initialization choices (the MSL's
table of I.initType and D.initType per initType) against the closed forms of a PI
controller with constant inputs, and the current-controlled machine's loop."""
import numpy as np
import pytest

import acausal as ac
from acausal.library.blocks import Constant, LimPID


def _loop(**pid):
    class Loop(ac.Component):
        setpoint = Constant(k=1.0)
        measured = Constant(k=0.0)
        feedForward = Constant(k=0.5)
        controller = LimPID(controllerType="PI", k=2.0, Ti=0.5, kFF=3.0,
                            withFeedForward=True, **pid)

        def equations(self):
            return [ac.connect(self.setpoint.y, self.controller.u_s),
                    ac.connect(self.measured.y, self.controller.u_m),
                    ac.connect(self.feedForward.y, self.controller.u_ff)]
    return Loop()


T = np.linspace(0.0, 1.0, 11)


def _run(**pid):
    return ac.simulate(_loop(**pid), t_end=1.0, t_eval=T, rtol=1e-10, atol=1e-10)


def test_initial_output_starts_the_pid_part_at_y_start():
    """InitialOutput: gainPID.y = k (e + I) = y_start at t0, so I(0) = y_start/k - e,
    then I = I(0) + e t/Ti; the output adds the feed-forward kFF u_ff."""
    res = _run(initType="InitialOutput", y_start=5.0, yMax=100.0)
    I = 5.0 / 2.0 - 1.0 + T / 0.5
    np.testing.assert_allclose(res["controller.I.y"], I, rtol=1e-9)
    np.testing.assert_allclose(res["controller.y"], 2.0 * (1.0 + I) + 3.0 * 0.5, rtol=1e-9)


def test_initial_state_and_the_default_start_the_integrator():
    res = _run(initType="InitialState", xi_start=0.7, yMax=100.0)
    np.testing.assert_allclose(res["controller.I.y"], 0.7 + T / 0.5, rtol=1e-9)
    res = _run(yMax=100.0)                   # NoInit: from its start value 0
    np.testing.assert_allclose(res["controller.I.y"], T / 0.5, rtol=1e-9, atol=1e-12)


def test_steady_state_settles_the_anti_windup():
    """Held at yMax, the integrator's input e - (k (e + I) + kFF u_ff - yMax)/(k Ni)
    vanishes at I = (e k Ni + yMax - kFF u_ff)/k - e, where SteadyState starts it."""
    res = _run(initType="SteadyState", yMax=3.0, Ni=0.9)
    I_inf = (1.0 * 2.0 * 0.9 + 3.0 - 1.5) / 2.0 - 1.0
    np.testing.assert_allclose(res["controller.I.y"], I_inf, rtol=1e-9)
    assert res["controller.y"] == pytest.approx(3.0)


def test_current_controller_follows_its_reference():
    """DCPM_CurrentControlled: the armature current settles at the 100 A reference
    (the controller's integral removes the error), the speed rises while it does."""
    from acausal.library.electromechanical.examples.msl.dcpm_current_controlled import \
        DCPM_CurrentControlled
    res = ac.simulate(DCPM_CurrentControlled(), t_end=0.5, rtol=1e-8,
                      t_eval=np.linspace(0.0, 0.5, 51))
    assert res["dcpm.ia"][res.t < 0.1] == pytest.approx(0.0, abs=1e-6)
    assert res["dcpm.ia"][-1] == pytest.approx(100.0, rel=1e-3)
    assert np.all(np.diff(res["loadInertia.w"][res.t > 0.12]) > 0)
