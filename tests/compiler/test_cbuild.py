"""A generated source compiled in several translation units against one unit.

The cut marks fall between whole functions (the pieces of a generated function and the
function that calls them in order), so a split build compiles the same statements as
the single unit: its functions return bitwise the same outputs, and a simulation on it
gives bitwise the same result.  A compiler that fails on one unit is a BackendError
with the compiler's message; ``backend="auto"`` then runs the numpy backend and says
why in the report.  Small unit sizes and pieces force the split on small models.
"""
import functools
import os

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.backends import cbackend
from acausal.native import build as cbuild
from acausal.library.hydraulics.examples.valve_motor import ValveControlledMotor
from acausal.tests.heater import LimitedHeater

pytestmark = pytest.mark.skipif(cbackend.compiler_available() is None,
                                reason="no C compiler on this machine")

BROKEN = cbuild.UNIT + "void broken_piece(ARGS) { w[0] = undeclared_name; }\n"


@pytest.fixture
def small_pieces(monkeypatch):
    """Pieces of about 3 lines: every generated function is several C functions."""
    monkeypatch.setattr(cbackend, "PIECE", 3)


def _functions(compiled):
    """Every generated function of the model (and of its when-clauses) at a few points
    near the start values, in a fixed order."""
    z0 = ac.initial_values(compiled)
    rng = np.random.default_rng(7)
    code = compiled.code
    sizes = {"residual": code.n_rows, "jacobian": len(code.jac_rows),
             "roots": code.n_roots, "scales": len(compiled.model_code.relations.ops),
             "expand": compiled.meta["n_all"]}
    out = []
    for _ in range(3):
        z = z0 * (1 + 0.1 * rng.standard_normal(z0.size)) \
            + 0.01 * rng.standard_normal(z0.size)
        p, m = compiled.p, compiled.m
        for name, n in sizes.items():
            out.append(getattr(code, name)(0.3, z, p, m.copy(), np.empty(n)))
        if compiled.whens is not None:
            w = compiled.whens.code
            out.append(w.residual(0.3, z, p, m.copy(), np.empty(w.n_rows)))
    return out


@pytest.mark.parametrize("model_class, t_end", [(ValveControlledMotor, 0.1),
                                                (LimitedHeater, 600.0)],
                         ids=["ValveControlledMotor", "LimitedHeater"])
def test_a_split_build_computes_bitwise_what_one_unit_does(model_class, t_end, tmp_path,
                                                           monkeypatch, small_pieces):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path / "one"))
    one = ac.compile(model_class(), backend="c", cache=False)
    assert cbuild.last_build["units"] == 1
    # the same source in units of about 600 characters, in a cache of its own (the
    # library's name does not depend on the split)
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path / "split"))
    monkeypatch.setattr(cbackend, "start_build",
                        functools.partial(cbackend.start_build, unit_size=600))
    split = ac.compile(model_class(), backend="c", cache=False)
    assert cbuild.last_build["units"] >= 4
    assert split.code.c_source == one.code.c_source
    assert split.code.library != one.code.library
    for a, b in zip(_functions(one), _functions(split), strict=True):
        np.testing.assert_array_equal(a, b)
    ra = ac.simulate(one, t_end=t_end, rtol=1e-6)
    rb = ac.simulate(split, t_end=t_end, rtol=1e-6)
    assert ra.success and rb.success
    np.testing.assert_array_equal(ra.t, rb.t)
    for name in one.states + list(one.names):
        np.testing.assert_array_equal(ra[name], rb[name], err_msg=name)


def test_units_are_whole_segments_with_the_header():
    source, _ = _source_of(ValveControlledMotor)
    header, *segments = source.split(cbuild.UNIT)
    for size, n_jobs in ((2000, 1), (2000, 2), (3000, 3), (10 ** 9, 2)):
        units = cbuild.split(source, size, n_jobs)
        assert all(u.startswith(header) for u in units)
        # consecutive whole segments, each exactly once, in order
        text = "".join(u[len(header):] for u in units).replace(cbuild.UNIT, "")
        assert text == "".join(segments)
        if size < len(source):
            assert len(units) % n_jobs == 0 or len(units) == len(segments)
            assert max(map(len, units)) <= len(header) + size + max(map(len, segments))
        else:
            assert units == [source]


def test_one_failing_compiler_is_a_backend_error_with_its_message(tmp_path, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    source, _ = _source_of(ValveControlledMotor)
    with pytest.raises(cbackend.BackendError) as err:
        cbackend.build(source + BROKEN, unit_size=600)
    text = str(err.value)
    assert "failed on the generated model (translation unit" in text
    assert "undeclared_name" in text and "error" in text
    # nothing is left behind: no library under the source's name, no build directory
    assert cbackend.build(source + BROKEN, cached_only=True) is None
    assert not [f for f in os.listdir(tmp_path) if f.startswith("build_")]


def test_auto_falls_back_to_numpy_when_a_unit_fails_and_c_raises(tmp_path, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    real = cbackend.c_source

    def broken_source(programs, index=None):
        source, sizes = real(programs, index)
        return source + BROKEN, sizes

    monkeypatch.setattr(cbackend, "c_source", broken_source)
    monkeypatch.setattr(cbackend, "start_build",
                        functools.partial(cbackend.start_build, unit_size=600))
    compiled = ac.compile(LimitedHeater(), backend="auto", cache=False)
    assert compiled.backend == "numpy"
    note = [n for n in compiled.report.notes if "C backend is not available" in n]
    assert note and "failed on the generated model" in note[0]
    res = ac.simulate(compiled, t_end=600.0, rtol=1e-6)
    assert res.success
    with pytest.raises(cbackend.BackendError, match="undeclared_name"):
        ac.compile(LimitedHeater(), backend="c", cache=False)


def _source_of(model_class):
    compiled = ac.compile(model_class(), backend="numpy", cache=False)
    mc = compiled.model_code
    codes = {"f_": mc.code, "i_": mc.initial.code}
    if mc.whens is not None:
        codes["w_"] = mc.whens.code
    return cbackend.c_source({k: c.program for k, c in codes.items()})
