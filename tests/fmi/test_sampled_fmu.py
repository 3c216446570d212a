"""Sampled models exported as FMUs (discrete variables and sample() clocks in the FMU's
engine, fmi/discrete.c) against acausal's own simulation, run by fmpy: the DC motor
speed loop under a 1 ms discrete PI through Model Exchange (fmpy's CVode lands on the
clock ticks, which the FMU announces as time events), the sampler/hold/delay chain
without states through Co-Simulation.  Points at the ticks are left out (there the
values before and after are both right; tests/fmi/models.py, fmu_errors)."""
import pytest

import acausal as ac
from acausal.compiler.backends.cbackend import compiler_available

fmpy = pytest.importorskip("fmpy", reason="fmpy (the 'fmi' extra) is not installed")
if compiler_available() is None:
    pytest.skip("no C compiler: FMUs cannot be built", allow_module_level=True)

from fmpy.validation import validate_fmu  # noqa: E402

from acausal.library.electromechanical.examples.sampled_speed_control import (  # noqa: E402
    SampledSpeedLoop)
from acausal.tests.library.test_discrete import HoldChain  # noqa: E402

from .models import fmu_errors  # noqa: E402


def test_sampled_speed_loop_model_exchange_agrees_with_simulate(tmp_path):
    path = ac.export_fmu(SampledSpeedLoop(), tmp_path / "loop.fmu", "ModelExchange",
                         t_end=0.03)
    assert validate_fmu(path) == []
    names = ["motor.rotor.w", "zoh.y.signal", "pi.I"]
    errors, res = fmu_errors(path, SampledSpeedLoop, 0.03, names, rtol=1e-10)
    assert max(errors.values()) < 1e-6, errors
    assert len(set(res["time"])) < len(res["time"])    # the ticks were events in fmpy


def test_sampled_chain_without_states_co_simulation_agrees_with_simulate(tmp_path):
    path = ac.export_fmu(HoldChain(), tmp_path / "chain.fmu", "CoSimulation", t_end=1.0)
    assert validate_fmu(path) == []
    names = ["smp.y.signal", "hold.y.signal", "delay.y.signal", "slow.y.signal"]
    errors, _ = fmu_errors(path, HoldChain, 1.0, names, rtol=1e-6)
    assert max(errors.values()) <= 1e-12, errors
