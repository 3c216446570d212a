"""Progress bars: shown on request, never changing a result, off when not interactive."""
import numpy as np

import acausal as ac

from .models import StepRC


def test_progress_bar_is_shown_on_request_and_changes_nothing(capsys):
    compiled = ac.compile(StepRC())
    quiet = ac.simulate(compiled, t_end=1.0, rtol=1e-9, progress=False)
    assert capsys.readouterr().err == ""
    shown = ac.simulate(compiled, t_end=1.0, rtol=1e-9, progress=True)
    assert "simulated time" in capsys.readouterr().err
    assert np.array_equal(shown.t, quiet.t)
    assert np.array_equal(shown["C1.v"], quiet["C1.v"])
    # default: only on a terminal (pytest's stderr is not one)
    ac.simulate(compiled, t_end=1.0, rtol=1e-9)
    assert capsys.readouterr().err == ""


def test_sweep_shows_runs_done(capsys):
    ds = ac.sweep(StepRC(), {"R1.R": [1.0, 2.0, 3.0]}, t_end=0.5, n_points=3, progress=True)
    err = capsys.readouterr().err
    assert "runs" in err and "/3 " in err          # the bar counts the 3 runs
    assert ds["success"].values.all()


def test_estimate_counts_its_simulations(capsys):
    compiled = ac.compile(StepRC())
    t = np.linspace(0.0, 1.0, 21)
    data = {"t": t, "C1.v": ac.simulate(compiled, 1.0, t_eval=t, rtol=1e-10)["C1.v"]}
    fit = ac.estimate(compiled, data, {"R1.R": 0.8}, progress=True)
    err = capsys.readouterr().err
    assert "simulations" in err
    assert abs(fit["R1.R"] - 0.5) < 1e-5 * 0.5          # the value the data was made with
    quiet = ac.estimate(compiled, data, {"R1.R": 0.8}, progress=False)
    assert capsys.readouterr().err == ""
    assert quiet.values == fit.values and quiet.n_simulations == fit.n_simulations
