"""Event records: kind, relations and when-clauses with their component, what changed;
still floats equal to the event times (code that reads times keeps working)."""
import pickle

import numpy as np

import acausal as ac
from acausal.library.translational.examples.mass_with_stop import MassAgainstStop

from .models import E, G, T_STEP, BouncingBall, StepRC, bounce_times


def test_when_clause_records_name_the_clause_and_the_reinit():
    res = ac.simulate(BouncingBall(), t_end=3.0, rtol=1e-8, atol=1e-10)
    exact = bounce_times(6)
    assert np.max(np.abs(np.array(res.events) - exact)) < 1e-8
    assert np.max(np.abs(res.event_times - exact)) < 1e-8
    v_impact = -np.sqrt(2 * G * 1.0)               # free fall from h0 = 1 m
    for k, ev in enumerate(res.events):
        assert ev.kind == "when" and ev.whens == ["when h < 0 [(model) (BouncingBall)]"]
        assert ev.relations == ["h < 0  in a when-clause"]
        ((name, before, after),) = ev.reinits
        assert name == "v"
        # each impact speed is e times the one before; the rebound is -e times it
        assert abs(before - v_impact * E ** k) < 1e-6 * abs(v_impact)
        assert abs(after + E * before) < 1e-12 * abs(before)


def test_relation_records_say_which_relation_of_which_component_changed():
    res = ac.simulate(MassAgainstStop(), t_end=2.0, rtol=1e-10)
    hit = res.events[0]
    assert hit.kind == "when" and hit.components == ["mass"]
    assert any("mass.s_max" in text and (a, b) == (0.0, 1.0) for text, a, b in hit.changes)
    assert dict((v, a) for v, _, a in hit.reinits)["mass.v"] == 0.0
    # the force reverses at t = 1 (F0 sin(pi t)): the contact force's relations switch
    release = [ev for ev in res.events if abs(ev - 1.0) < 1e-9]
    assert release and all(ev.kind == "relation" for ev in release)
    texts = {t for ev in release for t, _, _ in ev.changes}
    assert any("mass.f_app" in t for t in texts)
    assert all(ev.components == ["mass"] for ev in release)


def test_time_event_record():
    res = ac.simulate(StepRC(), t_end=0.5, rtol=1e-8)
    (ev,) = res.events
    assert ev == T_STEP and ev.kind == "time" and ev.components == ["src"]
    ((text, before, after),) = ev.changes
    assert "src.startTime <= time" in text and (before, after) == (0.0, 1.0)
    assert "Event(t=0.1, time" in repr(ev)


def test_records_survive_pickle_and_behave_as_times():
    res = ac.simulate(BouncingBall(), t_end=1.0, rtol=1e-8, atol=1e-10)
    back = pickle.loads(pickle.dumps(res.events))
    assert [e.as_dict() for e in back] == [e.as_dict() for e in res.events]
    assert np.round(res.events, 6).tolist() == np.round(bounce_times(1), 6).tolist()
    assert abs(res.events[0] - bounce_times(1)[0]) < 1e-8
    assert np.asarray(res.events, dtype=float).dtype == np.float64


def test_dynamic_state_switches_are_recorded_apart_from_events():
    from acausal.library.examples.pendulum import Pendulum
    compiled = ac.compile(Pendulum(x={"start": 0.0}, y={"start": -1.0}, vx={"start": 7.0}))
    runs = [ac.simulate(compiled, t_end=3.0, rtol=1e-8, atol=1e-8, n_points=31)
            for _ in range(2)]
    for res in runs:
        assert res.events == []                    # a state switch is no event
        sw = res.state_switches
        assert len(sw) >= 2 and all(s.kind == "state switch" for s in sw)
        assert all(0.0 < s < 3.0 for s in sw) and list(sw) == sorted(sw)
        # each switch's new choice is the next one's old choice, the first's old one
        # the choice the run started from
        assert sw[0].changes[0][1] == ", ".join(sorted(compiled.names[d] for d in
                                                       compiled.model_code.dummies))
        assert all(a.changes[0][2] == b.changes[0][1] for a, b in zip(sw, sw[1:]))
    # every run reports its own switches: the same model, the same switches
    assert [s.as_dict() for s in runs[0].state_switches] == \
        [s.as_dict() for s in runs[1].state_switches]
