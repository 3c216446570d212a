"""Parameters found by initialization (``Parameter(fixed=False)``, Modelica's
``parameter Real c(fixed=false)``): a mass hanging on a spring, at rest at
s = s0 + d under gravity, has the spring constant c = m g / d (closed form)."""
import numpy as np
import pytest

import acausal as ac

M, G, S0, D = 2.0, 9.81, 0.5, 0.1


class Hanging(ac.Component):
    """A mass on a spring, s measured downwards: m der(v) = m g - c_total (s - s0)."""
    m = ac.Parameter(M, unit="kg")
    g = ac.Parameter(G, unit="m/s2")
    s0 = ac.Parameter(S0, unit="m")
    c = ac.Parameter(100.0, unit="N/m", min=0)
    s = ac.Variable(start=S0 + D, fixed=True, unit="m")
    v = ac.Variable(start=0.0, fixed=True, unit="m/s")

    def stiffness(self):
        return self.c

    def equations(self):
        return [ac.Eq(ac.der(self.s), self.v),
                ac.Eq(self.m * ac.der(self.v),
                      self.m * self.g - self.stiffness() * (self.s - self.s0))]


class AtRest(Hanging):
    """c declared found by initialization; the initial equation der(v) = 0 finds it."""
    c = ac.Parameter(100.0, unit="N/m", min=0, fixed=False)

    def initial_equations(self):
        return [ac.Eq(ac.der(self.v), 0)]


class TwoSprings(AtRest):
    """A second spring in parallel, its constant bound to c: c2 = 2 c."""
    c2 = ac.Parameter(lambda h: 2 * h.c, unit="N/m")

    def stiffness(self):
        return self.c + self.c2


@pytest.mark.parametrize("backend", ["numpy", "auto"])
def test_spring_constant_found_so_that_the_mass_rests(backend):
    res = ac.simulate(AtRest(), 2.0, backend=backend)
    assert res.parameter_values["c"] == pytest.approx(M * G / D, rel=1e-9)
    # at rest for the whole run: the found value is the one the run used
    assert np.max(np.abs(res["s"] - (S0 + D))) < 1e-9 * (S0 + D)
    assert np.max(np.abs(res["v"])) < 1e-9
    assert res.compiled.report.initial_parameters == {"c": 100.0}
    assert "parameters found by initialization" in str(res.compiled.report)


def test_a_binding_to_a_found_parameter_follows_it():
    # c + 2 c = m g / d: c2 is evaluated with the c initialization finds, not its start
    res = ac.simulate(TwoSprings(), 1.0)
    assert res.parameter_values["c"] == pytest.approx(M * G / D / 3, rel=1e-9)
    assert np.max(np.abs(res["v"])) < 1e-9
    assert res.compiled.derived_parameters["c2"] is None   # no stale compile-time value
    assert res.parameter_values["c2"] == 2 * res.parameter_values["c"]


def test_modification_makes_a_parameter_free_and_each_run_starts_from_its_start():
    class Top(ac.Component):
        h = Hanging(c={"fixed": False, "start": 10.0}, v={"steady": True})
    compiled = ac.compile(Top())
    first = ac.simulate(compiled, 1.0).parameter_values["h.c"]
    again = ac.simulate(compiled, 1.0).parameter_values["h.c"]
    assert first == pytest.approx(M * G / D, rel=1e-9)
    assert again == first                                   # bitwise: same start, same run
    assert compiled.p[compiled.param_names.index("h.c")] == 10.0   # the model keeps its start


def test_a_free_parameter_without_an_equation_is_refused_by_name():
    class Top(ac.Component):
        h = Hanging(c={"fixed": False, "start": 10.0})
    with pytest.raises(ac.UnderdeterminedInitialization,
                       match=r"'h' \(Hanging\): parameter c .*needs an initial equation") as e:
        ac.compile(Top())
    assert e.value.variables == ["h.c"]


def test_a_found_parameter_is_not_tunable():
    compiled = ac.compile(AtRest())
    with pytest.raises(ac.InvalidValue, match="found by initialization"):
        ac.simulate(compiled, 1.0, parameters={"c": 3.0})
    with pytest.raises(ac.InvalidValue, match="found by initialization"):
        ac.sweep(compiled, {"c": [1.0, 2.0]}, t_end=1.0, n_points=3)


def test_bad_attributes_are_refused_where_the_instance_is_made():
    with pytest.raises(ac.InvalidValue, match="no attribute 'fixd'"):
        Hanging(c={"fixd": False})
    with pytest.raises(ac.InvalidValue, match="fixed = 'no' must be True or False"):
        Hanging(c={"fixed": "no"})
    with pytest.raises(ac.InvalidValue, match="scalar Real"):
        class Flag(ac.Component):
            on = ac.Parameter(True)
        Flag(on={"fixed": False})


def test_msl_init_spring_constant_closed_form():
    """MSL InitSpringConstant: the pendulum rests at phi = 0 when the spring, stretched
    by 0.1 m at the 1 m tip, carries the moment of the weight at 0.5 m: c = 5 g_n."""
    from acausal.library.multibody3d.examples.msl.init_spring_constant import (
        InitSpringConstant)
    res = ac.simulate(InitSpringConstant(), 0.5)
    assert res.parameter_values["spring.c"] == pytest.approx(5 * 9.80665, rel=1e-9)
    assert np.max(np.abs(res["rev.phi"])) < 1e-9


def test_fmu_export_refuses_a_found_parameter(tmp_path):
    pytest.importorskip("fmpy")
    import shutil
    if shutil.which("cc") is None and shutil.which("gcc") is None:
        pytest.skip("no C compiler")
    with pytest.raises(ac.ModelError, match="found by initialization"):
        ac.export_fmu(AtRest(), str(tmp_path / "at_rest.fmu"))


def test_a_found_value_outside_its_range_fails_initialization():
    # the mass held above the spring's rest length: the spring would have to pull
    # upwards with c < 0, below the declared minimum 0
    with pytest.raises(ac.InitializationFailed, match=r"parameter 'c' .* outside its range"):
        ac.simulate(AtRest(s={"start": S0 - D}), 1.0)


def test_a_parameter_found_from_an_algebraic_condition():
    class Algebraic(ac.Component):     # no state: the initial condition is the only one
        c = ac.Parameter(1.0, fixed=False)
        x = ac.Variable()

        def equations(self):
            return [ac.Eq(self.x, 2 * self.c)]

        def initial_equations(self):
            return [ac.Eq(self.x, 4.0)]
    res = ac.simulate(Algebraic(), 1.0)
    assert res.parameter_values["c"] == pytest.approx(2.0, rel=1e-12)
    assert np.all(res["x"] == pytest.approx(4.0, rel=1e-12))


def test_a_found_parameter_starting_at_zero_is_no_structural_zero():
    # a parameter of exactly 0 is a structural zero, evaluated away before compiling;
    # one found by initialization is not (its 0 is a guess), and the spring stays
    class Top(ac.Component):
        h = Hanging(c={"fixed": False, "start": 0.0}, v={"steady": True})
    compiled = ac.compile(Top())
    assert "h.c" not in compiled.meta["structural_zeros"]
    res = ac.simulate(compiled, 1.0)
    assert res.parameter_values["h.c"] == pytest.approx(M * G / D, rel=1e-9)
    assert repr(AtRest.c) == "Parameter(100.0, unit='N/m', min=0, fixed=False)"
