"""Sweeps never lose finished work: a worker killed mid-sweep costs only its own run
(returned failed with the reason; ``retries`` runs it again), repeated sweeps on one
dask Client never fail, and local worker processes work after dask's threads have run
in the same process.  Each result is compared with the serial run of the same values,
which itself follows the closed form of the RC step (test_ensemble.py)."""
import threading

import numpy as np
import pytest

import acausal as ac
from acausal import sweeps

from .models import StepRC, rc_voltage
from .sweep_tasks import kill_at

GRID = np.linspace(0.0, 1.0, 11)
R_VALUES = [0.25, 0.5, 0.75, 1.0, 1.25, 1.5]
KW = {"rtol": 1e-10, "atol": 1e-12}


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(StepRC())


def _job(**extra):
    return {"task": kill_at, "kill": 0.5, "t_end": 1.0, "t_start": 0.0, "t_eval": GRID,
            "names": ["C1.v"], "kwargs": KW, **extra}


def _check(outcomes, killed=()):
    """Every run but ``killed`` whole and on the closed form; the killed ones failed
    with the reason."""
    for k, (values, ok, message, _) in enumerate(outcomes):
        if k in killed:
            assert not ok and message.startswith("WorkerDied: the worker process running "
                                                 "it was killed (SIGKILL)"), message
            continue
        assert ok, message
        exact = rc_voltage(GRID, R=R_VALUES[k])
        assert np.max(np.abs(values[0] - exact)) <= 1e-7 * 2.0


def test_a_killed_worker_costs_only_its_own_run(compiled):
    runs = [{"R1.R": r} for r in R_VALUES]
    outcomes = sweeps._execute(compiled, runs, _job(), "processes", False, 2)
    _check(outcomes, killed=(1,))


def test_retries_run_a_lost_run_again(compiled, tmp_path):
    runs = [{"R1.R": r} for r in R_VALUES]
    job = _job(marker=str(tmp_path / "killed-once"))
    outcomes = sweeps._execute(compiled, runs, job, "processes", False, 2, retries=1)
    assert (tmp_path / "killed-once").exists()        # it was killed, then ran again
    _check(outcomes)


def test_a_run_that_always_kills_its_worker_fails_after_its_retries(compiled):
    runs = [{"R1.R": r} for r in R_VALUES]
    outcomes = sweeps._execute(compiled, runs, _job(), "processes", False, 2, retries=2)
    _check(outcomes, killed=(1,))
    assert "(in 3 attempts)" in outcomes[1][2]


def test_a_broken_executor_keeps_the_chunks_that_finished(compiled):
    from concurrent.futures import ProcessPoolExecutor
    runs = [{"R1.R": r} for r in R_VALUES]
    with ProcessPoolExecutor(max_workers=1) as pool:
        # one worker, one run a chunk: the runs before the killed one are done
        outcomes = sweeps._execute(compiled, runs, _job(), pool, False, None)
    assert outcomes[0][1] and not outcomes[1][1]
    assert "BrokenProcessPool" in outcomes[1][2]
    exact = rc_voltage(GRID, R=R_VALUES[0])
    assert np.max(np.abs(outcomes[0][0][0] - exact)) <= 1e-7 * 2.0


def test_processes_work_after_dask_has_run_in_this_process(compiled):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        ds = ac.sweep(compiled, {"R1.R": R_VALUES}, t_end=1.0, t_eval=GRID,
                      executor=client, **KW)
        assert ds["success"].values.all()
        assert any(t is not threading.main_thread() for t in threading.enumerate())
        # dask's threads are alive: the workers must not be forked copies of them
        runs = [{"R1.R": r} for r in R_VALUES]
        outcomes = sweeps._execute(compiled, runs, _job(), "processes", False, 2)
    _check(outcomes, killed=(1,))
    assert np.array_equal(np.array([o[0][0] for o in outcomes if o[1]]),
                          ds["C1.v"].values[[0, 2, 3, 4, 5]])


def test_twenty_sweeps_in_a_row_on_one_dask_client(compiled):
    distributed = pytest.importorskip("distributed")
    serial = ac.sweep(compiled, {"R1.R": R_VALUES}, t_end=1.0, t_eval=GRID, **KW)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        for _ in range(20):
            ds = ac.sweep(compiled, {"R1.R": R_VALUES}, t_end=1.0, t_eval=GRID,
                          executor=client, **KW)
            assert ds["success"].values.all()
            assert np.array_equal(ds["C1.v"].values, serial["C1.v"].values)


def test_a_killed_dask_worker_costs_only_its_own_runs(compiled):
    distributed = pytest.importorskip("distributed")
    import dask
    runs = [{"R1.R": r} for r in R_VALUES]
    # the scheduler gives up on a task at the first worker it kills (default: 3)
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        outcomes = sweeps._execute(compiled, runs, _job(), client, False, None, retries=1)
    assert not outcomes[1][1] and "KilledWorker" in outcomes[1][2]
    for k in (0, 2, 3, 4, 5):          # run again one by one when their chunk was lost
        assert outcomes[k][1], outcomes[k][2]
        exact = rc_voltage(GRID, R=R_VALUES[k])
        assert np.max(np.abs(outcomes[k][0][0] - exact)) <= 1e-7 * 2.0


def test_retries_and_workers_are_checked(compiled):
    with pytest.raises(ValueError, match="retries"):
        ac.sweep(compiled, {"R1.R": [1.0]}, t_end=1.0, n_points=3, retries=-1)
    with pytest.raises(ValueError, match="max_workers"):
        ac.sweep(compiled, {"R1.R": [1.0]}, t_end=1.0, n_points=3, executor="processes",
                 max_workers=0)


def test_a_mistake_in_the_call_is_said_once_not_by_every_run(compiled):
    with pytest.raises(ac.InvalidArgument, match="rtol"):
        ac.sweep(compiled, {"R1.R": [1.0, 2.0]}, t_end=1.0, n_points=3, rtol=5.0)
    with pytest.raises(KeyError, match=r"no variable 'C1.vv' in the model \(did you mean "
                                       r"'C1.v'\?\)"):
        ac.sweep(compiled, {"R1.R": [1.0]}, t_end=1.0, n_points=3, names=["C1.vv"])
