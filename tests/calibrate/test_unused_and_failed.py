"""What a calibration says of a parameter a model does not use (no convergence line: its chain
samples the prior) and of a model that fails on much of its prior (a warning: the posterior is
cut to where the model runs, and for the tabulated law that is the windows of its curves)."""

from __future__ import annotations

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.calibrate import CalibrationWarning, CandidateModel, calibrate, parse_parameter
from impactlab.calibrate.diagnostics import FAILED_SHARE_MAX, convergence_notes, failed_note
from impactlab.calibrate.posterior import LogPosterior

MU = parse_parameter("mu", "uniform(0, 0.6)")
SY = parse_parameter("flat_yield_strength", "uniform(200 MPa, 500 MPa)")
STUCK = {"rhat": 1.7, "ess_bulk": 12.0, "tau": 1.6}


def test_an_unused_parameter_gets_no_convergence_line():
    summary = {"damping": STUCK, "mu": STUCK}
    notes = convergence_notes(summary, kept=20, burn=20, draws=160, skip=("damping",))
    assert notes and all(n.startswith("mu: ") for n in notes)
    both = convergence_notes(summary, kept=20, burn=20, draws=160)
    assert any(n.startswith("damping: R-hat 1.700 > 1.05") for n in both)


def _post(draws, failed, failures=None):
    return SimpleNamespace(draws=draws, failed_draws=failed, failures=failures or {})


def test_a_model_failing_on_much_of_its_prior_is_named():
    why = {"contact law rejected its parameters (outside the law's validity)": 900, "x": 3}
    assert failed_note("ghaednia", _post(1000, 50, why)) is None  # 5 %: not more
    assert FAILED_SHARE_MAX == 0.05
    text = failed_note("ghaednia", _post(1000, 51, why))
    assert text is not None and text.startswith("5.1 % of the 1000 parameter values run")
    assert "most often: contact law rejected its parameters" in text
    assert "a 90 % interval may span values where it does not" in text
    assert "E*/S_y" not in text
    tab = failed_note("tabulated", _post(100, 52, why))
    assert tab is not None and "law 'tabulated' runs only where the pair's E*/S_y" in tab
    assert "360.3" in tab  # the paper's pair's curves
    assert failed_note("ghaednia", _post(0, 0)) is None


def test_the_log_posterior_counts_the_failed_parameter_values(template, monkeypatch):
    from impactlab.calibrate import posterior as module
    from impactlab.calibrate.models import Prediction

    def fake(model, meas, params, theta, **kw):  # every case of a mu > 0.3 refused
        bad = np.asarray(theta)[:, 0] > 0.3
        w, d = len(theta), meas.n_drops
        status = np.where(bad[:, None], 12, 0).repeat(d, axis=1).astype(np.int32)
        values = {q: np.zeros((w, d)) for q in meas.quantities}
        return Prediction(values, status, np.zeros((w, d), dtype=bool))

    monkeypatch.setattr(module, "predict", fake)
    post = LogPosterior(CandidateModel(), template, [MU])
    post.evaluate(np.array([[0.1], [0.2], [0.4], [0.5], [0.7]]))  # mu > 0.3 refused, 0.7 outside
    assert (post.draws, post.failed_draws) == (4, 2)
    assert post.evaluations == 4 * template.n_drops


def test_the_tabulated_law_cut_to_its_curves_is_a_warning(template):
    """S_y in [200, 500] MPa: the tabulated law runs only near the paper's pair's curves
    (E*/S_y 360.3 +- 5 %) and another's (504.5): most values of the prior are refused."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        cal = calibrate(template, [SY, MU], ["tabulated/coulomb"], walkers=6, steps=10,
                        n_ppc=0)  # fmt: skip
    post = cal.best
    assert post.failed_draws > FAILED_SHARE_MAX * post.draws > 0
    lines = [str(w.message) for w in caught if issubclass(w.category, CalibrationWarning)]
    hit = [w for w in lines if "gave a likelihood of zero" in w]
    assert len(hit) == 1 and hit[0].startswith("tabulated/coulomb: ")
    assert "its posterior lies in those windows" in hit[0]
    assert any("gave a likelihood of zero" in w for w in post.warnings)
    assert not math.isnan(post.summary["flat_yield_strength"]["median"])


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")
def test_a_model_that_always_runs_gives_no_such_warning(template):
    cal = calibrate(template, [MU], walkers=6, steps=10, n_ppc=0)
    assert cal.best.failed_draws == 0 and cal.best.draws > 0
    assert not any("likelihood of zero" in w for w in cal.warnings)
