"""What a calibration says about its own chains: convergence that cannot be assessed, every
model's convergence problems among the calibration's warnings, a posterior against a bound of
its prior, and a best model that the data do not single out or whose chain has not converged."""

from __future__ import annotations

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.calibrate import Calibration, CandidateModel, calibrate, parse_parameter
from impactlab.calibrate.diagnostics import edge_note
from impactlab.calibrate.ranking import annotate
from impactlab.calibrate.synthetic import synthetic_measurements

MU = parse_parameter("mu", "uniform(0, 0.6)")


def _data(template, mu=0.15):
    return synthetic_measurements(template, CandidateModel(), [MU], [mu],
                                  np.random.default_rng(0))  # fmt: skip


def test_too_few_draws_is_not_assessable_and_says_so(template, capfd):
    """Two draws per walker: R-hat, ESS and tau are NaN; that is a convergence problem, in the
    model's warnings and the calibration's, and ArviZ's log lines stay out of the console."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        cal = calibrate(_data(template), [MU], walkers=4, steps=10, burn=8, n_ppc=0)
    post = cal.best
    assert np.isnan(post.summary["mu"]["rhat"])
    assert not post.converged
    assert any("R-hat and ESS not assessable" in w for w in post.convergence)
    assert "ghaednia/coulomb: mu: R-hat and ESS not assessable" in " | ".join(cal.warnings)
    assert any("not assessable" in str(w.message) for w in caught)
    assert cal.ranking[0]["converged"] is False and "not converged" in cal.ranking[0]["note"]
    assert cal.best_caveats == ["not converged"]
    out = capfd.readouterr()
    assert "Shape validation failed" not in out.out + out.err


def test_a_posterior_against_its_priors_bound_is_flagged(template):
    """Data made with mu = 0.15, prior uniform(0, 0.1): the posterior piles at 0.1."""
    prior = parse_parameter("mu", "uniform(0, 0.1)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cal = calibrate(_data(template), [prior], walkers=8, steps=30, n_ppc=0)
    text = "mu: the posterior lies against the upper bound of its prior (0.1;"
    assert any(w.startswith(text) for w in cal.best.warnings)
    assert any(w.startswith(f"ghaednia/coulomb: {text}") for w in cal.warnings)
    assert "widen the prior if larger values are possible" in " ".join(cal.warnings)
    # the ranking's note and the caveats say so too: the table's interval is the prior's edge
    assert "at a prior bound (its interval is cut there)" in cal.ranking[0]["note"]
    assert "at a prior bound (its interval is cut there)" in cal.best_caveats


def test_edge_note_only_for_piled_draws():
    p = parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)")
    rng = np.random.default_rng(0)
    assert edge_note(p, rng.uniform(1e8, 1e9, 4000)) is None  # the prior itself
    assert edge_note(p, rng.normal(5e8, 5e7, 4000)) is None  # well inside
    piled = np.clip(rng.normal(9.2e8, 7e7, 4000), 1e8, 1e9)
    note = edge_note(p, piled)
    assert note is not None and "upper bound of its prior (1000 MPa;" in note
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    low = edge_note(mu, np.abs(rng.normal(0.0, 0.01, 4000)))
    assert low is not None and "the smallest possible value: the data favour the limit" in low


def _post(converged: bool, k: float = 0.3):
    return SimpleNamespace(converged=converged, loo={"pareto_k_max": k})


def _row(model, diff, dse):
    return {"model": model, "elpd_diff": diff, "dse": dse}


def test_the_ranking_says_what_is_not_distinguishable_or_not_converged():
    posts = {"a": _post(False), "b": _post(True), "c": _post(True, 0.6)}
    rows = annotate([_row("a", 0.0, 0.0), _row("b", 0.27, 1.98), _row("c", 9.0, 2.0)], posts)
    assert [r["distinguishable"] for r in rows] == [False, False, True]
    assert rows[0]["note"] == "not distinguishable (elpd_diff < 2 dse); not converged"
    assert rows[1]["note"] == "not distinguishable (elpd_diff < 2 dse)"
    assert rows[2]["note"] == "" and rows[2]["pareto_k_max"] == 0.6
    assert [r["converged"] for r in rows] == [False, True, True]
    clear = annotate([_row("b", 0.0, 0.0), _row("c", 9.0, 2.0)], posts)
    assert clear[0]["distinguishable"] is True and clear[0]["note"] == ""
    single = annotate([_row("b", 0.0, 0.0)], posts)
    assert single[0]["distinguishable"] is None and single[0]["note"] == ""


def test_best_caveats_come_from_the_ranking():
    cal = Calibration({}, annotate([_row("a", 0.0, 0.0), _row("b", 0.27, 1.98)],
                                   {"a": _post(False), "b": _post(True)}), None, {})  # fmt: skip
    assert cal.best_caveats == ["not distinguishable (elpd_diff < 2 dse)", "not converged"]


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_two_models_the_data_do_not_tell_apart(template):
    """The same physics under two names: equal elpd, so the best-ranked is not
    distinguishable from the other; the calibration warns, the rows and best_caveats say so."""
    models = [CandidateModel(name="first"), CandidateModel(name="second")]
    cal = calibrate(_data(template), [MU], models, walkers=6, steps=12, n_ppc=0)
    assert [r["distinguishable"] for r in cal.ranking] == [False, False]
    assert all("not distinguishable (elpd_diff < 2 dse)" in r["note"] for r in cal.ranking)
    assert "not distinguishable (elpd_diff < 2 dse)" in cal.best_caveats
    assert any("is not distinguishable from" in w for w in cal.warnings)


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_misfits_are_shown_in_display_units_without_a_stray_unit():
    """A dent in um (not 4.952e-05), a restitution without a unit (not "0.31 +- 0.02 -")."""
    from impactlab.calibrate import Measurements

    recs = [
        {"label": f"d{a}", "angle": f"{a} deg", "vy": vy, "mu": 0.15, "e": 0.95,
         "e_sigma": 0.02, "delta_p": f"{dp} um", "delta_p_sigma": "2 um"}
        for a, vy, dp in ((20, -1.41, 20), (45, -2.18, 30))
    ]  # fmt: skip
    cal = calibrate(Measurements.from_records(recs), [MU], walkers=4, steps=10, n_ppc=0)
    notes = " | ".join(cal.best.warnings)
    assert "d20 delta_p: best fit " in notes and " um is " in notes and "measured 20 um" in notes
    line = next(w for w in cal.warnings if w.startswith("no model reproduces d20 e"))
    assert line.startswith("no model reproduces d20 e = 0.95 +- 0.02: the closest best fit")
    assert " -:" not in line and " - " not in line.split("(")[0]


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_an_unused_parameters_chain_is_not_a_convergence_problem(template):
    """Hertz does not use S_y: its S_y chain is the prior's and says nothing of the model."""
    sy = parse_parameter("flat_yield_strength", "uniform(250 MPa, 350 MPa)")
    cal = calibrate(_data(template), [MU, sy], ["ghaednia/coulomb", "hertz/coulomb"],
                    walkers=8, steps=10, burn=8, n_ppc=0)  # fmt: skip
    hertz = cal.posteriors["hertz/coulomb"]
    # not a convergence problem, nor a warning of the model (its report, the paper's section)
    assert not any(w.startswith("flat_yield_strength:") for w in hertz.warnings)
    assert not any(c.startswith("flat_yield_strength:") for c in hertz.convergence)
    assert any(c.startswith("mu:") for c in hertz.convergence)
    assert not any(w.startswith("hertz/coulomb: flat_yield_strength") for w in cal.warnings)
