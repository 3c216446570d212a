"""User-defined functions with a derivative (``ac.function``, Modelica's derivative
annotation, Language Specification 3.5 sec. 12.7.1): index reduction differentiates a
call by the derivative function, checked against closed forms."""
import numpy as np
import pytest

import acausal as ac
from acausal.library import rotational as rot
from acausal.library.blocks import Constant, Sine
from acausal.library.rotational.move import Move


@ac.function
def square_der2(x, x_der, der_x, der_x_der):
    return 2 * der_x * x_der + 2 * x * der_x_der


@ac.function(derivative=square_der2)
def square_der(x, x_der):
    return 2 * x * x_der


@ac.function(derivative=square_der)
def square(x):
    return x**2


def test_called_with_numbers_it_is_its_body():
    assert square(3.0) == 9.0
    assert square_der(3.0, 0.5) == 3.0


class _Imposing(rot.PartialElementaryOneFlangeAndSupport):
    """Imposes the flange's angle phi = f(y), y = sin(t) a variable of the model."""

    y = ac.Variable(unit="rad")
    omega = ac.Parameter(1.0, unit="1/s")

    def __init__(self, f, **mods):
        super().__init__(**mods)
        object.__setattr__(self, "f", f)

    def equations(self):
        return [ac.Eq(self.y, ac.sin(self.omega * ac.time)),
                ac.Eq(self.flange.phi, self.f(self.y))]


def _imposed(f):
    class Model(ac.Component):
        inertia = rot.Inertia(J=3.0)
        imposing = _Imposing(f)

        def equations(self):
            return [ac.connect(self.imposing.flange, self.inertia.flange_a)]
    return Model()


def test_index_reduction_uses_the_derivative_functions():
    """phi = square(sin t) is differentiated twice, by square_der and square_der2:
    phi = sin^2 t, w = sin 2t, a = 2 cos 2t, and the torque on the flange J a."""
    t = np.linspace(0.0, 2.0, 21)
    res = ac.simulate(_imposed(square), t_end=2.0, rtol=1e-9, t_eval=t)
    assert res.success
    np.testing.assert_allclose(res["inertia.phi"], np.sin(t)**2, atol=1e-12)
    np.testing.assert_allclose(res["inertia.w"], np.sin(2 * t), atol=1e-9)
    np.testing.assert_allclose(res["inertia.flange_a.tau"], 3.0 * 2 * np.cos(2 * t),
                               atol=1e-8)


class _Moved(ac.Component):
    """Move with signals that are not each other's derivatives: u = [sin t, 2 cos t,
    0.5]; the flange's speed is u[1] and its acceleration u[2] (the derivative
    annotation), not the derivatives of u[0]."""

    inertia = rot.Inertia(J=2.0)
    move = Move()
    angle = Sine(amplitude=1.0, f=1 / (2 * np.pi))
    speed = Sine(amplitude=2.0, f=1 / (2 * np.pi), phase=np.pi / 2)
    acceleration = Constant(k=0.5)

    def equations(self):
        return [ac.connect(self.move.flange, self.inertia.flange_a),
                ac.connect(self.angle.y, self.move.u[0]),
                ac.connect(self.speed.y, self.move.u[1]),
                ac.connect(self.acceleration.y, self.move.u[2])]


def test_move_reads_speed_and_acceleration_from_its_inputs():
    t = np.linspace(0.0, 1.0, 11)
    res = ac.simulate(_Moved(), t_end=1.0, rtol=1e-8, t_eval=t)
    assert res.success
    np.testing.assert_allclose(res["inertia.phi"], np.sin(t), atol=1e-12)
    np.testing.assert_allclose(res["inertia.w"], 2 * np.cos(t), atol=1e-12)
    np.testing.assert_allclose(res["inertia.a"], 0.5, atol=1e-12)
    np.testing.assert_allclose(res["move.flange.tau"], -2.0 * 0.5, atol=1e-10)


@ac.function
def _no_derivative(x):
    return 2 * x


def test_a_function_without_derivative_that_must_be_differentiated_is_refused():
    with pytest.raises(ac.ModelError, match="_no_derivative.*no derivative"):
        ac.compile(_imposed(_no_derivative), cache=False)


def test_bad_declarations_are_typed_errors():
    with pytest.raises(ac.InvalidValue, match="did you mean 'q_qd'"):
        ac.function(lambda q_qd, dummy: q_qd[0], no_derivative=("q_qdd",))
    with pytest.raises(ac.InvalidValue, match="must take 3"):
        ac.function(lambda x, t: x, derivative=lambda x, t, dt, extra: 0,
                    no_derivative="x")
    with pytest.raises(ac.InvalidValue, match="takes 1 arguments"):
        square(1.0, 2.0)


def test_a_changed_body_is_another_function_for_the_compile_cache():
    first = ac.function(lambda x: 2 * x, name="f")
    second = ac.function(lambda x: 3 * x, name="f")
    assert first.digest != second.digest


def test_translational_move_reads_velocity_and_acceleration_from_its_inputs():
    from acausal.library import translational as tr

    class Moved(ac.Component):
        mass = tr.Mass(m=2.0)
        move = tr.Move()
        position = Sine(amplitude=1.0, f=1 / (2 * np.pi))
        velocity = Sine(amplitude=2.0, f=1 / (2 * np.pi), phase=np.pi / 2)
        acceleration = Constant(k=0.5)

        def equations(self):
            return [ac.connect(self.move.flange, self.mass.flange_a),
                    ac.connect(self.position.y, self.move.u[0]),
                    ac.connect(self.velocity.y, self.move.u[1]),
                    ac.connect(self.acceleration.y, self.move.u[2])]

    t = np.linspace(0.0, 1.0, 11)
    res = ac.simulate(Moved(), t_end=1.0, rtol=1e-8, t_eval=t)
    assert res.success
    np.testing.assert_allclose(res["mass.s"], np.sin(t), atol=1e-12)
    np.testing.assert_allclose(res["mass.v"], 2 * np.cos(t), atol=1e-12)
    np.testing.assert_allclose(res["move.flange.f"], -2.0 * 0.5, atol=1e-10)


def test_der_of_a_call_is_its_derivative_function():
    """ac.der(square(y)) written in an equation: 2 y der(y), by square_der."""
    class Model(ac.Component):
        y = ac.Variable(start=1.0, fixed=True)
        z = ac.Variable()

        def equations(self):
            return [ac.Eq(ac.der(self.y), -self.y), ac.Eq(self.z, ac.der(square(self.y)))]

    t = np.linspace(0.0, 1.0, 11)
    res = ac.simulate(Model(), t_end=1.0, rtol=1e-10, t_eval=t)
    np.testing.assert_allclose(res["z"], -2 * np.exp(-2 * t), rtol=1e-7)
