"""Sweeps and ensembles: one compile, runs on a common grid gathered in one Dataset,
against the RC closed form and equal to serial runs (processes, dask LocalCluster)."""
import numpy as np
import pytest

import acausal as ac

from .models import BouncingBall, StepRC, bounce_times, rc_voltage

GRID = np.linspace(0.0, 1.0, 21)
R_VALUES, C_VALUES = [0.25, 0.5, 1.0], [0.5, 2.0]
KW = {"rtol": 1e-10, "atol": 1e-12}


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(StepRC())


@pytest.fixture(scope="module")
def serial(compiled):
    return ac.sweep(compiled, {"R1.R": R_VALUES, "C1.C": C_VALUES}, t_end=1.0,
                    t_eval=GRID, **KW)


def _relative(a, b) -> float:
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def test_product_sweep_matches_the_closed_form(serial):
    ds = serial
    assert ds["C1.v"].dims == ("run", "time") and ds.sizes == {"run": 6, "time": 21}
    assert np.array_equal(ds["time"].values, GRID)
    # the last name varies fastest, as itertools.product
    assert ds["R1.R"].values.tolist() == [0.25, 0.25, 0.5, 0.5, 1.0, 1.0]
    assert ds["C1.C"].values.tolist() == [0.5, 2.0] * 3
    assert ds["success"].values.all() and ds.attrs["n_failed"] == 0
    assert ds["C1.v"].attrs["units"] == "V" and ds["R1.R"].attrs["units"] == "Ohm"
    for k in range(6):
        exact = rc_voltage(GRID, R=ds["R1.R"].values[k], C=ds["C1.C"].values[k])
        assert np.max(np.abs(ds["C1.v"].values[k] - exact)) < 1e-7 * 2.0   # of V = 2


def test_each_run_equals_its_own_simulation(serial):
    fresh = ac.compile(StepRC())
    for k in (0, 3, 5):
        values = {"R1.R": float(serial["R1.R"][k]), "C1.C": float(serial["C1.C"][k])}
        one = ac.simulate(fresh, 1.0, t_eval=GRID, parameters=values, **KW)
        for name in ("C1.v", "R1.i"):
            assert _relative(serial[name].values[k], one[name]) < 1e-12


def test_a_sweep_leaves_the_model_as_it_was():
    model = ac.compile(StepRC())
    before = model.p.copy()
    ac.sweep(model, {"R1.R": [2.0, 3.0]}, t_end=0.5, n_points=3)
    assert np.array_equal(model.p, before)


def test_zip_grid_and_ensemble_of_dicts(compiled):
    ds = ac.sweep(compiled, {"R1.R": R_VALUES, "C1.C": [0.5, 1.0, 2.0]}, grid="zip",
                  t_end=1.0, n_points=11, names=["C1.v"], **KW)
    assert ds.sizes["run"] == 3 and list(ds.data_vars) == ["C1.v", "success", "message",
                                                            "steps"]
    assert ds["C1.C"].values.tolist() == [0.5, 1.0, 2.0]
    same = ac.ensemble(compiled, [{"R1.R": r, "C1.C": c} for r, c in
                                  zip(R_VALUES, [0.5, 1.0, 2.0])],
                       t_end=1.0, n_points=11, names=["C1.v"], **KW)
    assert np.array_equal(same["C1.v"].values, ds["C1.v"].values)
    # a run that does not set a swept parameter shows the model's value for it
    mixed = ac.ensemble(ac.compile(StepRC()), [{"R1.R": 1.0}, {"C1.C": 3.0}], t_end=1.0,
                        n_points=3)
    assert mixed["R1.R"].values.tolist() == [1.0, 0.5]
    assert mixed["C1.C"].values.tolist() == [2.0, 3.0]


def test_mistakes_in_the_call_are_errors(compiled):
    with pytest.raises(ValueError, match="t_eval or n_points"):
        ac.sweep(compiled, {"R1.R": [1.0]}, t_end=1.0)
    with pytest.raises(ValueError, match="equal length"):
        ac.sweep(compiled, {"R1.R": [1.0, 2.0], "C1.C": [1.0]}, grid="zip", t_end=1.0,
                 n_points=3)
    with pytest.raises(ValueError, match="grid"):
        ac.sweep(compiled, {"R1.R": [1.0]}, grid="cartesian", t_end=1.0, n_points=3)
    with pytest.raises(ac.NotInModel, match="R9.R"):
        ac.sweep(compiled, {"R9.R": [1.0]}, t_end=1.0, n_points=3)


def test_failed_runs_never_lose_the_others():
    # e = 0.5: the bounces accumulate at t1 (1 + 2e/(1-e)) = 3 t1 < 2 s: chattering;
    # e = 0.8 at 9 t1 > 2 s: the run completes
    t1 = bounce_times(1)[0]
    grid = np.linspace(0.0, 2.0, 41)
    ds = ac.ensemble(BouncingBall(), [{"e": 0.8}, {"e": 0.5}, {"e": -1.0}, {"e": 0.7}],
                     t_end=2.0, t_eval=grid, rtol=1e-8, atol=1e-10)
    assert ds["success"].values.tolist() == [True, False, False, True]
    assert "chattering" in str(ds["message"].values[1])
    assert str(ds["message"].values[2]).startswith("InvalidValue: parameter 'e'")
    assert np.isnan(ds["h"].values[2]).all()
    h = ds["h"].values
    assert np.isfinite(h[0]).all() and np.isfinite(h[3]).all()
    # the chattering run keeps its points up to the failure, NaN after it
    reached = np.isfinite(h[1])
    assert reached[0] and not reached[-1]
    assert t1 < grid[reached].max() < 3 * t1
    before = grid < t1
    assert np.max(np.abs(h[1][before] - (1.0 - 0.5 * 9.81 * grid[before] ** 2))) < 1e-7


def test_local_processes_equal_serial(compiled, serial):
    ds = ac.sweep(compiled, {"R1.R": R_VALUES, "C1.C": C_VALUES}, t_end=1.0,
                  t_eval=GRID, executor="processes", max_workers=2, **KW)
    for name in ("C1.v", "R1.i", "der(C1.v)"):
        assert _relative(ds[name].values, serial[name].values) < 1e-12
    assert ds["R1.R"].values.tolist() == serial["R1.R"].values.tolist()


def test_dask_local_cluster_equals_serial(compiled, serial):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        ds = ac.sweep(compiled, {"R1.R": R_VALUES, "C1.C": C_VALUES}, t_end=1.0,
                      t_eval=GRID, executor=client, **KW)
    for name in ("C1.v", "R1.i"):
        assert _relative(ds[name].values, serial[name].values) < 1e-12
    assert ds["success"].values.all()


def test_a_thread_pool_gives_each_task_its_own_model(compiled, serial):
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(max_workers=3) as pool:
        ds = ac.sweep(compiled, {"R1.R": R_VALUES, "C1.C": C_VALUES}, t_end=1.0,
                      t_eval=GRID, executor=pool, **KW)
    assert _relative(ds["C1.v"].values, serial["C1.v"].values) < 1e-12
