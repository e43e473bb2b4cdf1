"""When the ranking may not tell two models apart: an elpd_diff under 4 nats whatever its dse
(Sivula et al. 2020, arXiv:2008.10296), a model with a drop whose Pareto k
exceeds 0.7 (its PSIS-LOO elpd unreliable: Vehtari, Gelman & Gabry 2017); and a model whose
log likelihood is the same at every draw (no free parameter it uses), whose leave-one-out elpd
is exact: k = 0, no Pareto warning."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.calibrate import Calibration
from impactlab.calibrate._arviz import az
from impactlab.calibrate.api import _best_warnings
from impactlab.calibrate.ranking import annotate
from impactlab.calibrate.result import _loo

UNRELIABLE = "not distinguishable (Pareto k > 0.7: PSIS-LOO unreliable)"
SMALL = "not distinguishable (elpd_diff < 4)"


def _post(k: float = 0.3, converged: bool = True):
    return SimpleNamespace(converged=converged, loo={"pareto_k_max": k})


def _row(model, diff, dse):
    return {"model": model, "elpd_diff": diff, "dse": dse}


def test_a_difference_under_4_is_not_distinguishable_whatever_its_dse():
    """3.5 +- 0.5 is 7 dse, yet under 4 nats: not distinguishable; 4.5 +- 0.5 is."""
    posts = {"a": _post(), "b": _post(), "c": _post()}
    rows = annotate([_row("a", 0.0, 0.0), _row("b", 3.5, 0.5)], posts)
    assert [r["distinguishable"] for r in rows] == [False, False]
    assert rows[0]["note"] == rows[1]["note"] == SMALL
    clear = annotate([_row("a", 0.0, 0.0), _row("c", 4.5, 0.5)], posts)
    assert [r["distinguishable"] for r in clear] == [True, True]
    assert clear[0]["note"] == ""


@pytest.mark.parametrize("bad", ["a", "c"])
def test_a_pareto_k_above_0_7_in_either_model_compared_is_not_distinguishable(bad):
    """The docs' drops: Pareto k 1.05 and 1.12 at 70 deg, where an exact refit moves the drop's
    elpd by 1.1 and 2.5 nats: an elpd_diff of 9 +- 2 is not trusted then."""
    posts = {"a": _post(), "b": _post(), "c": _post()}
    posts[bad] = _post(1.05)
    rows = annotate([_row("a", 0.0, 0.0), _row("b", 30.0, 5.0), _row("c", 9.0, 2.0)], posts)
    assert rows[2]["distinguishable"] is False and rows[2]["note"] == UNRELIABLE
    # the best is judged against the runner-up, b: unreliable only when the best is
    assert rows[0]["distinguishable"] is (bad != "a")
    assert rows[1]["note"] == ("" if bad == "c" else UNRELIABLE)
    cal = Calibration({}, rows, None, {})
    assert (UNRELIABLE in cal.best_caveats) is (bad == "a")


def test_the_best_caveat_and_warning_name_the_pareto_k():
    posts = {"a": _post(1.06), "b": _post(1.0, converged=False)}
    rows = annotate([_row("a", 0.0, 0.0), _row("b", 2.0, 1.5)], posts)
    assert rows[0]["note"] == "not distinguishable (elpd_diff < 2 dse); " + UNRELIABLE
    assert rows[1]["note"] == "not distinguishable (elpd_diff < 2 dse); " + UNRELIABLE + (
        "; not converged"
    )
    (text,) = _best_warnings(rows)
    assert "elpd_diff 2.00 < 2 dse (3.00)" in text
    assert "Pareto k max 'a' 1.06, 'b' 1.00" in text


def test_one_drop_keeps_its_own_note_alone():
    posts = {"a": _post(1.2), "b": _post()}
    rows = annotate([_row("a", 0.0, 0.0), _row("b", 9.0, 0.0)], posts, drops=1)
    one = "not distinguishable (one drop: PSIS-LOO does not rank)"
    assert [r["note"] for r in rows] == [one, one]


def _idata(ll):
    rng = np.random.default_rng(0)
    return az.from_dict(log_likelihood={"drops": ll}, posterior={"zeta": rng.random(ll.shape[:2])})


def test_a_constant_log_likelihood_has_its_exact_elpd_and_no_pareto_warning():
    """The paper's rigid rod beside a free zeta: ArviZ gives k = inf for every drop (a Pareto
    tail fitted to constant ratios) and the calibration warned of 3 drops with k > 0.7."""
    ll = np.tile([-200.0, -570.0, -100.0], (8, 150, 1))
    loo, notes, pointwise = _loo(_idata(ll))
    assert loo["pareto_k_max"] == 0.0 and loo["n_bad_k"] == 0
    assert notes == []
    np.testing.assert_array_equal(pointwise, [-200.0, -570.0, -100.0])
    assert loo["elpd"] == -870.0 and loo["p_loo"] == 0.0
    assert loo["se"] == pytest.approx(np.sqrt(3 * np.var([-200.0, -570.0, -100.0])))


@pytest.mark.filterwarnings("ignore:Estimated shape parameter of Pareto")  # ArviZ's, of az.loo
def test_only_the_constant_drops_are_made_exact():
    """Drop 0 varies over the draws (PSIS, ArviZ's k), drops 1 and 2 do not (exact)."""
    rng = np.random.default_rng(1)
    ll = np.tile([-200.0, -570.0, -100.0], (8, 150, 1))
    ll[..., 0] += rng.normal(0.0, 0.5, (8, 150))
    idata = _idata(ll)
    loo, notes, pointwise = _loo(idata)
    r = az.loo(idata, pointwise=True)
    assert np.isinf(np.asarray(r.pareto_k)[1:]).all()  # what ArviZ says of them
    assert 0.0 < loo["pareto_k_max"] == pytest.approx(float(np.asarray(r.pareto_k)[0]))
    assert pointwise[0] == pytest.approx(float(np.asarray(r.loo_i)[0]))
    np.testing.assert_array_equal(pointwise[1:], [-570.0, -100.0])
    assert loo["elpd"] == pytest.approx(float(r.elpd_loo))
    assert loo["p_loo"] == pytest.approx(float(r.p_loo))
    assert notes == []
