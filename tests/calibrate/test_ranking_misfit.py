"""A model whose best fit misses a measured value by more than 5 sigma: its ranking row says
so (``misfit_max``, the note), and where PSIS-LOO cannot tell the best from such a runner-up the
warning says the fit does."""

from __future__ import annotations

import math
from types import SimpleNamespace

from impactlab.calibrate import Calibration
from impactlab.calibrate.api import _best_warnings
from impactlab.calibrate.ranking import MISFIT, annotate, misfit_max


def _post(*z: float):
    ppc = [{"drop": f"d{i}", "quantity": "e", "z_best": v} for i, v in enumerate(z)]
    return SimpleNamespace(converged=True, loo={"pareto_k_max": 0.3}, ppc=ppc)


def _rows():
    return [
        {"model": "a", "elpd_diff": 0.0, "dse": 0.0},
        {"model": "b", "elpd_diff": 3.0, "dse": 2.5},
    ]


def test_misfit_max_is_the_largest_absolute_z_of_the_best_fit():
    assert misfit_max(_post(0.4, -12.5, 3.0)) == 12.5
    assert misfit_max(_post(0.4, math.nan)) == math.inf
    assert math.isnan(misfit_max(SimpleNamespace()))


def test_a_runner_up_that_misses_by_12_sigma_is_named_in_its_row_and_the_warning():
    """Three drops: PSIS-LOO cannot separate the models (2 dse), the runner-up misses a value by
    12.5 sigma at its best fit: the warning no longer says the data do not single one out."""
    rows = annotate(_rows(), {"a": _post(0.4, -1.2), "b": _post(2.0, -12.5)}, drops=3)
    assert rows[0]["misfit_max"] == 1.2 and rows[1]["misfit_max"] == 12.5
    assert MISFIT not in rows[0]["note"] and rows[1]["note"].endswith(MISFIT)
    assert rows[1]["distinguishable"] is False  # PSIS-LOO's verdict is unchanged
    (text,) = _best_warnings(rows)
    assert "'b' misses a measured value by 12.5 sigma" in text
    assert "the fit, not PSIS-LOO, tells them apart" in text
    assert "do not single out" not in text


def test_a_best_model_that_misfits_has_it_among_its_caveats_and_warnings():
    rows = annotate(_rows(), {"a": _post(6.0), "b": _post(7.0)}, drops=3)
    assert MISFIT in Calibration({}, rows, None, {}).best_caveats
    texts = _best_warnings(rows)
    assert any("'a' misses a measured value by 6.0 sigma" in t for t in texts)
    # both miss: PSIS-LOO's wording stands
    assert any("the data do not single out one model" in t for t in texts)


def test_within_5_sigma_no_misfit_note():
    rows = annotate(_rows(), {"a": _post(4.9), "b": _post(-5.0)}, drops=3)
    assert all(MISFIT not in r["note"] for r in rows)
