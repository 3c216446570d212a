"""Andrews' squeezing mechanism (Hairer & Wanner II, section VII.7) in array form
(``library/multibody/examples/squeezer.py``) against the same mechanism written with one
declaration per scalar (``squeezer_scalar.py``).

* Both forms start from the same consistent initial values, the published ones (beta'',
  Theta'' and the two non-zero multipliers of the Test Set's problem "andrews").
* Both forms give the same trajectory: every angle, rate and multiplier to about 1e-9 of
  its largest value over the run, at rtol 1e-10.  The array form's trajectory is checked
  against an independent index-1 solution in ``test_array_models.py``.
* Lines of code (neither blank lines, comments nor docstrings): the array form takes 88,
  the scalar form 133, two thirds, where the n-link pendulum's array form takes under
  half.  Arrays turn the 40 declarations of the masses, inertias, fixed points, angles,
  rates and multipliers into 10 lines and the products M v' and G^T lam into one
  equation each; the 22 named lengths, torque and spring constants are scalars in both
  forms, and the sparse M(q) and G(q) are written entry by entry in both.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library.multibody.examples.squeezer import AndrewsSqueezer

from .squeezer_scalar import ANGLES, MULTIPLIERS, RATES, AndrewsSqueezerScalars
from .test_array_models import PUBLISHED_ACCEL, PUBLISHED_LAM, _code_lines

ARRAYS = {"q": ANGLES, "v": RATES, "lam": MULTIPLIERS}


@pytest.fixture(scope="module")
def both_forms():
    kw = dict(t_end=AndrewsSqueezer.stop_time, rtol=1e-10, n_points=31,
              raise_on_failure=True)
    arrays = ac.simulate(ac.compile(AndrewsSqueezer(), check_units="error"), **kw)
    scalars = ac.simulate(ac.compile(AndrewsSqueezerScalars(), check_units="error"), **kw)
    return arrays, scalars


def _columns(res, names):
    return np.column_stack([res[name] for name in names])


def test_both_forms_start_from_the_published_consistent_values(both_forms):
    arrays, scalars = both_forms
    accel = _columns(scalars, [f"der({name})" for name in RATES])[0]
    lam = _columns(scalars, MULTIPLIERS)[0]
    for computed in (accel[:2], arrays["der(v)"][0, :2]):
        np.testing.assert_allclose(computed, PUBLISHED_ACCEL, rtol=1e-9)
    for computed in (lam[:2], arrays["lam"][0, :2]):
        np.testing.assert_allclose(computed, PUBLISHED_LAM, rtol=1e-9)
    # all seven angles, accelerations and the six multipliers, not only the published ones
    for array_form, scalar_form in ((arrays["q"][0], _columns(scalars, ANGLES)[0]),
                                    (arrays["der(v)"][0], accel), (arrays["lam"][0], lam)):
        scale = np.max(np.abs(scalar_form))
        assert np.max(np.abs(array_form - scalar_form)) <= 1e-10 * scale


@pytest.mark.parametrize("array, bound", [("q", 1e-9), ("v", 5e-9), ("lam", 5e-9)])
def test_both_forms_give_the_same_trajectory(both_forms, array, bound):
    arrays, scalars = both_forms
    scalar = _columns(scalars, ARRAYS[array])
    assert arrays[array].shape == scalar.shape
    # each signal against its own largest value over the run
    error = np.max(np.abs(arrays[array] - scalar), axis=0)
    assert np.all(error <= bound * np.max(np.abs(scalar), axis=0))


def test_array_form_takes_fewer_lines_than_the_scalar_form():
    array_lines = _code_lines(AndrewsSqueezer)
    scalar_lines = _code_lines(AndrewsSqueezerScalars)
    assert array_lines < scalar_lines, (array_lines, scalar_lines)
