"""On the numpy backend, reading one variable computes that variable only, over every
point at once (:mod:`acausal.runtime.outputs`), and agrees with the model's own ``expand`` evaluated
point by point in the modes each point was integrated in: to 1e-12 of each variable's
size on models with events, if-expressions, sampled parts, friction, delays and
dynamic state selection (the two run the same statements; numpy's functions and math's
agree to rounding).  Behind a C library a result of up to POINTWISE values reads the C
``expand``'s outputs, point by point, however the model was compiled or loaded (bitwise
the same whatever ran before); a larger one is read on arrays as on the numpy backend."""
import numpy as np
import pytest

import acausal as ac
from acausal.library.electromechanical.examples.sampled_speed_control import \
    SampledSpeedLoop
from acausal.library.examples.motor_drive import MotorDrive
from acausal.library.examples.pendulum import Pendulum
from acausal.library.friction.examples.stick_slip import StickSlip
from acausal.library.rotational.examples.coupled_clutches import CoupledClutches
from acausal.ports import RealInput
from acausal.runtime.outputs import expand_points as _expand

from ..library.test_delays import FixedDelayLoop
from .models import BouncingBall

MODELS = [(MotorDrive, 0.5), (Pendulum, 2.0), (BouncingBall, 2.0), (StickSlip, 1.5),
          (CoupledClutches, 1.5), (SampledSpeedLoop, 0.08), (FixedDelayLoop, 3.0)]


@pytest.mark.parametrize("model, t_end", MODELS, ids=[m.__name__ for m, _ in MODELS])
def test_one_variable_at_all_points_equals_expand_point_by_point(model, t_end):
    res = ac.simulate(model(), t_end, rtol=1e-8, backend="numpy")
    assert res.success
    c = res.compiled
    full = _expand(c, res.t, res._z, res.parameters, res._discrete, res._discrete_index,
                   res._delayed)
    if c.code.expand is not None:
        assert res._vectorized()
    for name, (sign, k) in c.outputs.items():
        if sign is None:
            continue
        got, want = res[name], sign * full[:, k]
        scale = max(float(np.max(np.abs(want))), 1e-300)
        assert np.max(np.abs(got - want)) <= 1e-12 * scale, name


def test_reading_one_variable_computes_it_only_and_keeps_it():
    res = ac.simulate(MotorDrive(), 0.5, rtol=1e-8, backend="numpy")
    assert not res._cols
    w = res["load.w"]
    assert len(res._cols) == 1 and res._y is None       # not every output
    again = res["load.w"]
    assert np.array_equal(w, again)
    assert len(res._cols) == 1


def test_behind_a_c_library_the_outputs_are_its_expand_bitwise():
    from acausal.native import find_compiler
    if find_compiler() is None:
        pytest.skip("no C compiler")
    res = ac.simulate(MotorDrive(), 0.5, rtol=1e-8, backend="c")
    c = res.compiled
    assert c.backend == "c" and not res._vectorized()
    full = _expand(c, res.t, res._z, res.parameters, res._discrete, res._discrete_index,
                   res._delayed)
    for name, (sign, k) in c.outputs.items():
        if sign is not None:
            assert np.array_equal(res[name], sign * full[:, k]), name


def test_a_large_result_behind_a_c_library_is_read_on_arrays(monkeypatch):
    from acausal.native import find_compiler
    from acausal.runtime import outputs
    if find_compiler() is None:
        pytest.skip("no C compiler")
    monkeypatch.setattr(outputs, "POINTWISE", 1000)      # this result counts as large
    res = ac.simulate(MotorDrive(), 0.5, rtol=1e-8, backend="c")
    c = res.compiled
    assert res._vectorized()
    full = _expand(c, res.t, res._z, res.parameters, res._discrete, res._discrete_index,
                   res._delayed)
    for name, (sign, k) in c.outputs.items():
        if sign is not None:
            want = sign * full[:, k]
            scale = max(float(np.max(np.abs(want))), 1e-300)
            assert np.max(np.abs(res[name] - want)) <= 1e-12 * scale, name


class Lag(ac.Component):
    """T x' = u - x, w = u x + sqrt(1 + u^2), driven by a top-level input u(t)."""

    u = RealInput()
    x = ac.Variable(start=0.0, fixed=True)
    w = ac.Variable()

    def equations(self):
        return [ac.Eq(0.5 * ac.der(self.x), self.u - self.x),
                ac.Eq(self.w, self.u * self.x + ac.sqrt(1 + self.u**2))]


@pytest.mark.parametrize("store", [False, True])
def test_a_varying_top_level_input_enters_the_outputs_read(tmp_path, store):
    import math
    kw = {"store": tmp_path / "lag.h5"} if store else {}
    res = ac.simulate(Lag(), 2.0, rtol=1e-9, n_points=201,
                      inputs={"u": lambda t: math.sin(2.0 * t)}, **kw)
    u = np.sin(2.0 * res.t)
    x = res["x"]
    # w computed from the recorded input and x at every point, as the model says
    assert np.max(np.abs(res["w"] - (u * x + np.sqrt(1 + u * u)))) <= 1e-12 * 2
    assert np.max(np.abs(res["u.signal"] - u)) <= 1e-12
