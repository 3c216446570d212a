"""Boolean and Integer variables in an exported FMU (FMI 2.0 Boolean and Integer
ScalarVariables, fmi2GetBoolean/fmi2GetInteger, the event iteration of fmi/discrete.c),
validated by fmpy and run by it against acausal's own simulation: a thermostat whose
heater a Boolean with hysteresis switches (state events), an Integer counting the
switchings, a Boolean parameter and an Integer parameter, through Model Exchange and
Co-Simulation, and the MSL's BooleanNetwork1 (no states: Boolean pulses, edges, a
flip-flop, a counter) through Co-Simulation."""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.backends.cbackend import compiler_available
from acausal.ports import BooleanOutput, IntegerOutput, RealOutput

fmpy = pytest.importorskip("fmpy", reason="fmpy (the 'fmi' extra) is not installed")
if compiler_available() is None:
    pytest.skip("no C compiler: FMUs cannot be built", allow_module_level=True)

from fmpy import read_model_description, simulate_fmu  # noqa: E402
from fmpy.validation import validate_fmu  # noqa: E402


class Thermostat(ac.Component):
    """der(T) = P on - k (T - Ta); on: on below Tlow, off above Thigh (pre(on) the memory);
    count: the number of times the heater switched on; ``boost`` doubles P."""

    T_out = RealOutput()
    on = BooleanOutput()
    count = IntegerOutput()
    T = ac.Variable(start=20.0, fixed=True, unit="K")
    P = ac.Parameter(4.0, unit="K/s")
    k = ac.Parameter(0.1, unit="1/s")
    Ta = ac.Parameter(10.0, unit="K")
    Tlow = ac.Parameter(20.0, unit="K")
    Thigh = ac.Parameter(25.0, unit="K")
    boost = ac.Parameter(False, description="double the heating power")
    first = ac.Parameter(0, type=int, description="count before the start")

    def __init__(self, **mods):
        mods.setdefault("on", {"signal": {"start": True}})
        super().__init__(**mods)

    def equations(self):
        was = ac.pre(self.on)
        power = ac.if_else(self.boost, 2 * self.P, self.P)
        return [ac.Eq(ac.der(self.T), ac.if_else(self.on, power, 0.0) - self.k * (self.T - self.Ta)),
                ac.Eq(self.on, (was & (self.T < self.Thigh)) | (~was & (self.T <= self.Tlow))),
                ac.when(ac.edge(self.on.signal),
                        ac.assign(self.count, ac.pre(self.count) + 1)),
                ac.Eq(self.T_out, self.T)]


def _compare(path, t_end, rtol, start_values=None):
    names = ["T_out", "on", "count"]
    res = simulate_fmu(path, stop_time=t_end, relative_tolerance=rtol,
                       output_interval=t_end / 500, output=names,
                       start_values=start_values or {})
    t, first = np.unique(res["time"], return_index=True)
    params = {"boost": True} if start_values and start_values.get("boost") else None
    ref = ac.simulate(Thermostat(), t_end=t_end, rtol=1e-10, t_eval=t, parameters=params)
    events = np.asarray(ref.events, dtype=float)
    # outside a band around each switching time (where the two runs' events, located
    # to their tolerances, may put a point on either side)
    keep = np.array([np.min(np.abs(events - x)) > 1e-3 for x in t])
    T_err = np.max(np.abs(res["T_out"][first][keep] - ref["T_out"][keep])) / np.max(ref["T_out"])
    on_bad = int(np.count_nonzero(res["on"][first][keep] != ref["on"][keep]))
    count_bad = int(np.count_nonzero(res["count"][first][keep] != ref["count"][keep]))
    return T_err, on_bad, count_bad, res, ref


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_boolean_and_integer_variables_of_an_fmu_agree_with_simulate(tmp_path, kind):
    path = ac.export_fmu(Thermostat(), tmp_path / "thermostat.fmu", kind, t_end=30.0)
    assert validate_fmu(path) == []
    md = read_model_description(path)
    types = {v.name: (v.type, v.causality, v.variability) for v in md.modelVariables}
    assert types["on"] == ("Boolean", "output", "discrete")
    assert types["count"] == ("Integer", "output", "discrete")
    assert types["boost"][:2] == ("Boolean", "parameter")
    assert types["first"][:2] == ("Integer", "parameter")
    T_err, on_bad, count_bad, res, ref = _compare(path, 30.0, 1e-8)
    assert T_err < 1e-5 and on_bad == 0 and count_bad == 0, (T_err, on_bad, count_bad)
    assert res["on"].dtype == bool and ref["count"][-1] >= 3
    assert res["count"][-1] == ref["count"][-1]


def test_a_boolean_parameter_set_through_fmi_changes_the_run(tmp_path):
    path = ac.export_fmu(Thermostat(), tmp_path / "boost.fmu", "CoSimulation", t_end=30.0)
    T_err, on_bad, count_bad, res, ref = _compare(path, 30.0, 1e-8, {"boost": True})
    assert T_err < 1e-5 and on_bad == 0 and count_bad == 0, (T_err, on_bad, count_bad)
    plain = ac.simulate(Thermostat(), t_end=30.0)
    assert ref["count"][-1] != plain["count"][-1]     # the boost heats faster


def test_msl_boolean_network_as_a_co_simulation_fmu(tmp_path):
    from acausal.library.blocks.examples.msl.networks import BooleanNetwork1
    path = ac.export_fmu(BooleanNetwork1(), tmp_path / "network.fmu", "CoSimulation",
                         t_end=10.0)
    assert validate_fmu(path) == []
    names = ["rSFlipFlop.pre.u.signal", "triggeredAdd.y.signal", "set1.y.signal",
             "onDelay.y.signal", "xor1.y.signal"]
    res = simulate_fmu(path, stop_time=10.0, output_interval=0.01, output=names)
    t, first = np.unique(res["time"], return_index=True)
    ref = ac.simulate(BooleanNetwork1(), t_end=10.0, t_eval=t)
    events = np.asarray(ref.events, dtype=float)
    keep = np.array([np.min(np.abs(events - x)) > 1e-9 for x in t])
    for n in names:
        assert np.array_equal(res[n][first][keep], ref[n][keep]), n
