"""Boolean and Integer variables in results and their exports: bool and int64 arrays,
pandas and xarray columns of those types, the MAT file's 0/1 and whole-number columns
with Dymola's type marks (read back as a Dymola reader does, tests/results/test_export),
HDF5 saved and loaded with their types."""
import numpy as np
import pytest

import acausal as ac
from acausal.library.blocks import BooleanPulse
from acausal.library.blocks.math_integer import TriggeredAdd
from acausal.library.blocks import IntegerConstant

from .test_export import _read_mat


class Counted(ac.Component):
    """A pulse train (period 0.4 s, 50 %) whose rising edges an Integer counts, and a
    state integrating the pulse (its time high)."""

    pulse = BooleanPulse(period=0.4, width=50.0)
    one = IntegerConstant(k=1)
    count = TriggeredAdd()
    x = ac.Variable(start=0.0, fixed=True, unit="s")

    def equations(self):
        return [ac.connect(self.pulse.y, self.count.trigger),
                ac.connect(self.one.y, self.count.u),
                ac.Eq(ac.der(self.x), ac.if_else(self.pulse.y, 1.0, 0.0))]


@pytest.fixture(scope="module")
def res():
    return ac.simulate(Counted(), t_end=1.1, t_eval=np.linspace(0.05, 1.05, 11), rtol=1e-9)


def _exact(t):
    high = (t % 0.4) < 0.2 - 1e-12
    # rising edges at 0.4, 0.8 (the pulse is high from the start: a when-clause does not
    # fire at the initialization)
    edges = np.floor(t / 0.4 + 1e-12)
    time_high = np.floor(t / 0.4) * 0.2 + np.minimum(t % 0.4, 0.2)
    return high, edges.astype(np.int64), time_high


def test_boolean_and_integer_results_are_bool_and_int_arrays(res):
    high, edges, time_high = _exact(res.t)
    assert res["pulse.y"].dtype == bool and list(res["pulse.y"]) == list(high)
    assert res["count.y"].dtype == np.int64 and list(res["count.y"]) == list(edges)
    assert np.max(np.abs(res["x"] - time_high)) < 1e-9
    assert res.value_types["count.y.signal"] == "Integer"


def test_pandas_and_xarray_keep_the_types(res):
    pytest.importorskip("pandas")
    pytest.importorskip("xarray")
    df = res.to_pandas()
    assert df["pulse.y.signal"].dtype == bool and df["count.y.signal"].dtype == np.int64
    assert df.attrs["types"]["count.y.signal"] == "Integer"
    assert df.attrs["types"]["x"] == "Real"
    ds = res.to_xarray()
    assert ds["pulse.y.signal"].dtype == bool
    assert ds["count.y.signal"].attrs["type"] == "Integer"
    assert np.array_equal(ds["count.y.signal"].values, res["count.y"])


def test_mat_file_holds_booleans_and_integers_as_numbers_with_their_types(res, tmp_path):
    res.to_mat(tmp_path / "counted.mat")
    names, descriptions, info, signals, m = _read_mat(tmp_path / "counted.mat")
    desc = dict(zip(names, descriptions))
    assert desc["pulse.y.signal"].endswith("[:#(type=Boolean)]")
    assert desc["count.y.signal"].endswith("[:#(type=Integer)]")
    assert np.array_equal(signals["pulse.y.signal"], res["pulse.y"].astype(float))
    assert np.array_equal(signals["count.y.signal"], res["count.y"].astype(float))


def test_hdf5_saves_and_loads_the_types(res, tmp_path):
    pytest.importorskip("h5py")
    res.save(tmp_path / "counted.h5")
    back = ac.load_result(tmp_path / "counted.h5")
    assert back["pulse.y"].dtype == bool and back["count.y"].dtype == np.int64
    assert np.array_equal(back["count.y"], res["count.y"])
    assert np.array_equal(back["x"], res["x"])
