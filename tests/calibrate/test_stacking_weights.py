"""Stacking weights of the ranking (Yao et al. 2018, doi:10.1214/17-BA1091) from pointwise elpd
arrays whose answer is known, however negative the elpd (``arviz.compare`` exponentiates them
as they are: below about -745 each underflows to 0, and it stopped at equal weights)."""

from __future__ import annotations

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.calibrate._arviz import quiet
from impactlab.calibrate.ranking import rank_models, stacking_weights

#: Two models, two drops, predictive densities [[3, 1], [1, 2]]: the stacking objective
#: log(3w + (1 - w)) + log(w + 2(1 - w)) is largest at 2/(1 + 2w) = 1/(2 - w), w = 3/4.
DENSITIES = np.array([[3.0, 1.0], [1.0, 2.0]])


@pytest.mark.parametrize("offset", [0.0, -1000.0, -5000.0])
def test_two_models_two_drops(offset):
    w = stacking_weights(np.log(DENSITIES) + offset)
    np.testing.assert_allclose(w, [0.75, 0.25], atol=1e-6)


def test_each_drop_may_be_shifted_on_its_own():
    """A constant per drop does not change the weights: drops at -800, -2000 and -9000."""
    eps = -50.0  # density ratio e^-50: the other model all but gives the drop no density
    e = np.array([[0.0, eps], [eps, 0.0], [eps, 0.0]]) + np.array([[-800.0], [-2000.0], [-9e3]])
    assert (np.exp(e) == 0.0).all()  # what arviz.compare would have worked with
    np.testing.assert_allclose(stacking_weights(e), [1 / 3, 2 / 3], atol=1e-6)


def test_a_model_better_on_every_drop_takes_all_the_weight():
    e = np.array([[-1000.0, -1003.0], [-2000.0, -2001.0], [-700.0, -750.0]])
    np.testing.assert_allclose(stacking_weights(e), [1.0, 0.0], atol=1e-6)


def test_equal_models_share_the_weight_and_a_drop_no_model_predicts_is_left_out():
    e = np.array([[-3.0, -3.0, -3.0], [-1.0, -1.0, -1.0]])
    np.testing.assert_allclose(stacking_weights(e), [1 / 3] * 3, atol=1e-9)
    with_nan = np.vstack([np.log(DENSITIES), [np.nan, -np.inf]])
    np.testing.assert_allclose(stacking_weights(with_nan), [0.75, 0.25], atol=1e-6)
    # a drop that one model gives no density is its rival's alone
    one_sided = np.vstack([np.log(DENSITIES), [-np.inf, -5.0]])
    w = stacking_weights(one_sided)
    assert w[1] > 0.25 and w.sum() == pytest.approx(1.0)
    with pytest.raises(ValueError, match="elpd must be an"):
        stacking_weights(np.zeros(3))


def _post(pointwise):
    e = np.asarray(pointwise, dtype=float)
    n = e.size
    se = math.sqrt(n * float(np.var(e)))
    return SimpleNamespace(
        loo={"elpd": float(e.sum()), "se": se, "p_loo": 1.0, "pareto_k_max": 0.3, "n_bad_k": 0},
        log_lik=np.zeros((2, 3, n)), loo_pointwise=e, converged=True,
        law_extrapolated={"share": 0.5, "impacts": 4, "basis": "2 posterior draws"},
    )  # fmt: skip


def test_the_ranking_takes_the_stacking_weights_and_arviz_differences():
    e = np.log(DENSITIES) - 1000.0
    posts = {"B": _post(e[:, 1]), "A": _post(e[:, 0])}
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no library warning reaches the user
        rows = rank_models(posts)
    assert [r["model"] for r in rows] == ["A", "B"]  # elpd -2000 + log 3 > -2000 + log 2
    assert [r["weight"] for r in rows] == pytest.approx([0.75, 0.25], abs=1e-6)
    diff = e[:, 0] - e[:, 1]
    assert rows[1]["elpd_diff"] == pytest.approx(diff.sum())
    assert rows[1]["dse"] == pytest.approx(math.sqrt(2 * np.var(diff)))  # as arviz.compare
    assert rows[0]["elpd_diff"] == 0.0 and rows[0]["dse"] == 0.0
    assert [r["rank"] for r in rows] == [0, 1]
    assert rows[0]["law_extrapolated"] == 0.5


def test_quiet_hides_numpys_warnings_from_arviz():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with quiet():
            warnings.warn_explicit("divide by zero encountered in log", RuntimeWarning,
                                   "stats.py", 1, module="arviz.stats.stats")  # fmt: skip
    assert caught == []
