"""Every MSL example of the library against the MSL's reference result (see harness.py).

The examples of :data:`~acausal.tests.msl.subset.QUICK` run by default; the others are
marked ``slow`` and run with ``make test-msl`` (``pytest -m "" tests/msl``, all of them).
An example that cannot pass says why in ``msl_known_failure`` (the reference's own error
measured against an independent solution, or a defect named with its cause): its test
then expects the failure, strictly, so that it is noticed when it passes."""
import numpy as np
import pytest

from .harness import (BOUND, Reference, compare, event_window, examples, load_reference,
                      run_example)
from .subset import QUICK

EXAMPLES = examples()


def _param(name):
    marks = () if name in QUICK else (pytest.mark.slow,)
    why = getattr(EXAMPLES[name], "msl_known_failure", None)
    if why:     # measured: the reference's own error, or a defect named with its cause
        marks += (pytest.mark.xfail(strict=True, reason=why),)
    return pytest.param(name, id=name.replace("Modelica.", ""), marks=marks)


@pytest.mark.parametrize("name", [_param(n) for n in EXAMPLES])
def test_example_matches_the_msl_reference(name):
    outcome = run_example(EXAMPLES[name])
    assert outcome.passed, outcome.describe()


def test_every_vendored_reference_has_an_example_and_every_example_a_reference():
    from .harness import REFERENCES
    vendored = {p.stem for p in REFERENCES.glob("*.csv")}
    assert set(EXAMPLES) <= vendored, sorted(set(EXAMPLES) - vendored)
    assert vendored <= set(EXAMPLES), sorted(vendored - set(EXAMPLES))


def test_every_example_runs_the_experiment_of_its_reference():
    for name, cls in EXAMPLES.items():
        ref = load_reference(name)
        assert cls.stop_time == ref.stop_time, name
        assert cls.tolerance == ref.tolerance, name


def _reference(t, **columns) -> Reference:
    return Reference("test", np.asarray(t, float), {k: np.asarray(v, float)
                                                     for k, v in columns.items()},
                     stop_time=float(t[-1]), tolerance=1e-6, interval=0.1)


def test_the_bound_is_relative_to_the_amplitude_and_events_are_left_out():
    t = np.array([0.0, 0.1, 0.2, 0.3, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8])
    ref = _reference(t, x=10.0 + np.where(t < 0.3, 0.0, 2.0))   # a jump at the event 0.3
    times = np.unique(t)
    ours = 10.0 + np.where(times < 0.31, 0.0, 2.0)                # found a little later
    ours[-1] += 0.9 * BOUND * 2.0                                 # within the bound
    (check,) = compare(times, lambda n: ours, ref, events=[0.31])
    assert check.passed and check.scale == 2.0
    assert event_window(ref) == pytest.approx(0.2)
    ours[-1] += 0.2 * BOUND * 2.0                                 # past it
    (check,) = compare(times, lambda n: ours, ref)
    assert not check.passed and check.at == 0.8


def test_a_reference_at_round_off_around_zero_is_judged_as_zero():
    t = np.linspace(0.0, 1.0, 11)
    ref = _reference(t, z=1e-16 * np.sin(7 * t), x=1e-9 * np.sin(7 * t))
    ours = np.full(11, 1e-5)                  # an integration error of a quantity that is 0
    z, x = compare(t, lambda n: ours, ref)
    assert z.passed and z.scale == 1.0
    assert not x.passed                        # 1e-9 is a signal, judged on its amplitude


def test_a_discrete_signal_must_agree_outside_the_events():
    t = np.array([0.0, 0.5, 0.5, 1.0, 1.5, 2.0, 2.5])
    ref = _reference(t, b=[0, 0, 1, 1, 1, 0, 0])                  # 1->0 between 1.5, 2.0
    times = np.unique(t)
    ours = np.array([False, True, True, False, False, False])   # falls too early
    (check,) = compare(times, lambda n: ours, ref)
    assert check.kind == "discrete" and not check.passed and check.at == 1.5
    ours[3] = True                                                # now it agrees
    (check,) = compare(times, lambda n: ours, ref)
    assert check.passed
