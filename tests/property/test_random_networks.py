"""Property-based tests: random lumped networks (electrical, translational,
rotational) built from the library, simulated by acausal and compared with an exact
independent reference (reference.py); ill-posed ones must be refused with a typed
error that names a culprit.

The strategies draw through ``HypothesisChooser``, so a failure shrinks to a small
netlist; the failure message prints it together with the model's Python source.
Settings are derandomized without a database, so every run draws the same cases.
See harness.py for the categories and the tolerance (1e-5 of each signal's size,
acausal at rtol 1e-8).

Shrinking a failure costs minutes (every step compiles and simulates), so it is off
unless ACAUSAL_SHRINK=1 is set; ``benchmarks/fuzz_networks.py --case N --shrink``
shrinks a benchmark case at the netlist level.
"""
import os

import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

from .harness import AmbiguousCase, make_case, run_case
from .netlists import HypothesisChooser, to_source

LIMIT = 600.0         # seconds per case: only a guard against a hang (cases take ~0.1 s)


PHASES = tuple(Phase) if os.environ.get("ACAUSAL_SHRINK") == "1" else \
    (Phase.explicit, Phase.generate)


def _settings(n):
    return settings(max_examples=n, deadline=None, derandomize=True, database=None,
                    phases=PHASES, report_multiple_bugs=False,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@st.composite
def cases(draw, strategy):
    try:
        return make_case(HypothesisChooser(draw), strategy)
    except AmbiguousCase:
        # acausal's answer would depend on its choice of states (see reference.py)
        assume(False)


def _explain(case, out):
    return (f"{out.category}: {out.detail}\n{case.net.describe()}\n\n{to_source(case.net)}")


def _check_regular(case):
    out = run_case(case, LIMIT)
    if case.net.expect != "regular":      # a singular network drawn by chance
        assert out.category == "rejected", _explain(case, out)
    else:
        assert out.category == "ok", _explain(case, out)


@_settings(80)
@given(cases("electrical"))
def test_random_electrical_networks_match_the_reference(case):
    _check_regular(case)


@_settings(40)
@given(cases("translational"))
def test_random_translational_networks_match_the_reference(case):
    _check_regular(case)


@_settings(40)
@given(cases("rotational"))
def test_random_rotational_networks_match_the_reference(case):
    _check_regular(case)


@pytest.mark.parametrize("domain", ["electrical", "translational", "rotational"])
def test_ill_posed_networks_are_refused_naming_a_culprit(domain):
    @_settings(40)
    @given(cases(f"ill-posed {domain}"))
    def check(case):
        out = run_case(case, LIMIT)
        assert out.category == "rejected", _explain(case, out)
    check()
