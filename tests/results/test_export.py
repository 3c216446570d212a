"""Result export: DataFrame, Dataset, CSV, the Dymola/OpenModelica MAT file and HDF5,
against the RC circuit's closed form and by read-back equality."""
import numpy as np
import pandas as pd
import pytest
import scipy.io

import acausal as ac

from .models import T_STEP, StepRC, rc_voltage

T_EVAL = np.linspace(0.0, 1.0, 41)


@pytest.fixture(scope="module")
def res():
    return ac.simulate(StepRC(), t_end=1.0, t_eval=T_EVAL, rtol=1e-10, atol=1e-12)


def test_dataframe_has_time_index_values_and_declared_units(res):
    df = res.to_pandas()
    assert df.index.name == "time" and np.array_equal(df.index.to_numpy(), T_EVAL)
    assert sorted(df.columns) == res.names
    v = rc_voltage(T_EVAL)
    assert np.max(np.abs(df["C1.v"].to_numpy() - v)) < 1e-7 * 2.0      # of V = 2
    # Kirchhoff: the resistor's current is the capacitor's, i = (V_src - v_C) / R
    i = (np.where(T_EVAL >= T_STEP, 2.0, 0.0) - v) / 0.5
    assert np.max(np.abs(df["R1.i"].to_numpy() - i)) < 1e-6 * 4.0      # of V/R = 4
    units = df.attrs["units"]
    assert units["C1.v"] == "V" and units["R1.i"] == "A" and units["C1.p.v"] == "V"
    assert units["der(C1.v)"] == "V/s"
    assert res.units["R1.R"] == "Ohm" and res.units["C1.C"] == "F"
    assert df.attrs["descriptions"]["C1.v"] == res.descriptions["C1.v"] != ""
    assert res.descriptions["R1.R"] == "resistance at temperature T_ref"


def test_dataframe_of_chosen_names_in_their_order(res):
    df = res.to_pandas(["R1.i", "C1.v"])
    assert list(df.columns) == ["R1.i", "C1.v"]
    assert set(df.attrs["units"]) == {"R1.i", "C1.v"}


def test_dataset_has_time_dimension_and_units(res):
    ds = res.to_xarray(["C1.v", "R1.i"])
    assert ds["C1.v"].dims == ("time",) and ds["C1.v"].attrs["units"] == "V"
    assert ds["R1.i"].attrs["units"] == "A"
    assert np.array_equal(ds["time"].values, T_EVAL)
    assert np.array_equal(ds["C1.v"].values, res["C1.v"])
    assert ds.attrs["parameter R1.R"] == 0.5 and ds.attrs["success"] == 1


def test_csv_reads_back_equal(res, tmp_path):
    res.to_csv(tmp_path / "rc.csv")                       # the old signature
    back = pd.read_csv(tmp_path / "rc.csv")
    assert list(back.columns) == ["time"] + res.names
    assert np.allclose(back["C1.v"], res["C1.v"], rtol=1e-15, atol=0)
    res.to_csv(tmp_path / "two.csv", names=["C1.v"])
    assert list(pd.read_csv(tmp_path / "two.csv").columns) == ["time", "C1.v"]


def _read_mat(path):
    """Each signal rebuilt as a Dymola/OpenModelica reader does (binTrans: every matrix
    transposed; dataInfo columns (matrix, signed 1-based column)) — written here from
    the format's description, independently of the writer."""
    m = scipy.io.loadmat(path, chars_as_strings=False)
    aclass = ["".join(r).rstrip() for r in m["Aclass"]]
    assert aclass == ["Atrajectory", "1.1", "", "binTrans"]
    names = ["".join(c).rstrip() for c in m["name"].T]
    descriptions = ["".join(c).rstrip() for c in m["description"].T]
    info = m["dataInfo"].T
    assert info.shape == (len(names), 4)
    signals = {}
    for name, (matrix, column, _, _) in zip(names, info):
        if matrix == 0:                         # time: the first row of every block
            signals[name] = m["data_2"][0]
            continue
        data = m[f"data_{matrix}"]
        signals[name] = np.sign(column) * data[abs(column) - 1]
    return names, descriptions, info, signals, m


def test_mat_file_rebuilds_every_signal_and_alias_with_its_sign(res, tmp_path):
    res.to_mat(tmp_path / "rc.mat")
    names, descriptions, info, signals, m = _read_mat(tmp_path / "rc.mat")
    assert names[0] == "time" and np.array_equal(signals["time"], res.t)
    assert set(names) == {"time"} | set(res.names) | set(res.parameter_names)
    for n in res.names:
        got = signals[n]
        if got.size == 2:                       # data_1: a constant, at t0 and t_end
            assert np.all(got == res[n][0]) and np.all(res[n] == res[n][0]), n
        else:
            assert np.array_equal(got, res[n]), n
    assert np.array_equal(signals["R1.R"], [0.5, 0.5])
    # aliases share columns: i of the capacitor is stored once, n.i as its negative
    by_name = dict(zip(names, info))
    assert abs(by_name["C1.n.i"][1]) == abs(by_name["C1.p.i"][1])
    assert by_name["C1.n.i"][1] == -by_name["C1.p.i"][1]
    assert m["data_2"].shape[0] < len(res.names)     # fewer columns than names
    desc = dict(zip(names, descriptions))
    assert desc["R1.R"] == "resistance at temperature T_ref [Ohm]" and desc["C1.v"].endswith("[V]")


def test_saved_result_loads_without_the_model(res, tmp_path):
    res.save(tmp_path / "rc.h5")
    back = ac.load_result(tmp_path / "rc.h5")
    assert back.compiled is None and back.names == res.names
    assert np.array_equal(back.t, res.t)
    for n in res.names:
        assert np.array_equal(back[n], res[n]), n
    assert back.units == res.units and back.descriptions == res.descriptions
    assert back.parameter_values == res.parameter_values
    assert back.success and back.message == res.message and back.stats == res.stats
    assert back.states == res.states == ["C1.v"]
    assert [e.as_dict() for e in back.events] == [e.as_dict() for e in res.events]
    assert np.array_equal(back.event_times, [T_STEP])
    df = back.to_pandas(["C1.v"])
    assert df.attrs["units"]["C1.v"] == "V"
    with pytest.raises(KeyError, match="no variable"):
        back["C9.v"]
    # a loaded result writes the other formats too
    back.to_mat(tmp_path / "again.mat")
    assert np.array_equal(_read_mat(tmp_path / "again.mat")[3]["C1.v"], res["C1.v"])


def test_load_rejects_a_foreign_file(tmp_path):
    import h5py
    with h5py.File(tmp_path / "other.h5", "w") as fh:
        fh.create_dataset("x", data=[1.0])
    with pytest.raises(ValueError, match="not a result saved by acausal"):
        ac.load_result(tmp_path / "other.h5")


def test_plot_labels_units_one_axis_per_unit_and_marks_events(res, tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    axes = res.plot("C1.v", "src.v", "R1.i", path=tmp_path / "rc.png")
    assert len(axes) == 2                                   # V and A
    assert axes[0].get_ylabel() == "C1.v, src.v [V]" and axes[1].get_ylabel() == "R1.i [A]"
    assert axes[0].get_xlabel() == "time [s]"
    marks = [ln for ln in axes[0].get_lines() if ln.get_linestyle() == "--"]
    assert [ln.get_xdata()[0] for ln in marks] == [T_STEP]
    assert (tmp_path / "rc.png").stat().st_size > 0
    ax = res.plot()                                         # default: the states
    assert [ln.get_label() for ln in ax.get_lines() if ln.get_linestyle() != "--"] == ["C1.v"]
    sub = res.plot("C1.v", "R1.i", subplots=True)
    assert len(sub) == 2 and sub[1].get_ylabel() == "R1.i [A]"
    import matplotlib.pyplot as plt
    plt.close("all")


def test_units_of_library_variables_reach_the_result():
    from acausal.library.examples.motor_drive import MotorDrive
    res = ac.simulate(MotorDrive(), t_end=0.2, n_points=5)
    units = res.to_pandas(["load.w", "load.phi", "motor.La.i", "shaft.tau"]).attrs["units"]
    assert units == {"load.w": "rad/s", "load.phi": "rad", "motor.La.i": "A",
                     "shaft.tau": "N.m"}
    assert res.units["der(load.w)"] == "rad/s2" and res.units["shaft.c"] == "N.m/rad"
    assert res.units["source.V"] == "V" and res.units["load.J"] == "kg.m2"


def test_a_pickled_result_keeps_units_and_events(res):
    import pickle
    back = pickle.loads(pickle.dumps(res))
    assert back.units == res.units and back.descriptions == res.descriptions
    assert [e.as_dict() for e in back.events] == [e.as_dict() for e in res.events]
    assert np.array_equal(back["C1.v"], res["C1.v"])


def test_mat_file_stores_text_as_utf8_bytes(tmp_path):
    class Cooling(ac.Component):
        """Newton's cooling, T' = -(T - T_a) / tau."""
        tau = ac.Parameter(2.0, unit="s", description="Zeitkonstante τ")
        T = ac.Variable(start=80.0, fixed=True, unit="degC", description="température")

        def equations(self):
            return [ac.Eq(ac.der(self.T), -(self.T - 20.0) / self.tau)]

    res = ac.simulate(Cooling(), t_end=1.0, n_points=5, rtol=1e-10)
    assert np.max(np.abs(res["T"] - (20.0 + 60.0 * np.exp(-res.t / 2.0)))) < 1e-7 * 80
    res.to_mat(tmp_path / "cool.mat")
    names, descriptions, _, signals, _ = _read_mat(tmp_path / "cool.mat")
    text = dict(zip(names, (d.encode("latin-1").decode("utf-8") for d in descriptions)))
    assert text["T"] == "température [degC]" and text["tau"] == "Zeitkonstante τ [s]"
    assert np.array_equal(signals["T"], res["T"])


def test_event_times_twice_or_once():
    res = ac.simulate(StepRC(), t_end=0.5, rtol=1e-9)        # every step: event points
    assert np.count_nonzero(res.t == T_STEP) == 2
    df = res.to_pandas(["C1.v", "src.v"])
    assert df.loc[T_STEP, "src.v"].tolist() == [0.0, 2.0]     # before and after the step
    once = res.to_pandas(["src.v"], unique=True)
    assert once.index.is_unique and once.loc[T_STEP, "src.v"] == 2.0
    ds = res.to_xarray(["src.v"], unique=True)
    assert float(ds["src.v"].sel(time=T_STEP, method="nearest")) == 2.0
    assert len(ds["time"]) == len(res.t) - 1
