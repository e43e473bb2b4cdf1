"""z = (predicted - measured) / sigma and within 2 sigma on a hand-made case; a configuration
that is not ok (refused, flagged, not run) predicts nothing and agrees with nothing; chi2 and
``best`` compare like with like."""

from __future__ import annotations

import math

import pytest

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import Explanation
from impactlab.explain.configurations import FLEXIBLE, LIBRARY_RATES, RIGID
from impactlab.explain.runs import Outcome
from impactlab.explain.tables import comparison_table, summary_table

DROP = {"label": "d", "angle": "45 deg", "vy": -2.0, "mu": 0.2, "e": 0.5, "e_sigma": 0.03,
        "delta_p": "40 um", "delta_p_sigma": "4 um", "spin_out": -10.0,
        "spin_out_sigma": 1.0}  # fmt: skip
CONFIGS = (RIGID, FLEXIBLE, LIBRARY_RATES[0])


def _tables(outcomes):
    meas = Measurements.from_records([DROP])
    comparison = comparison_table(meas, CONFIGS, outcomes)
    return comparison, summary_table(meas, CONFIGS, outcomes, comparison)


def test_z_and_within_two_sigma_by_hand() -> None:
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.554, "delta_p": 48.4e-6, "spin_out": -13.5}),
        # a flagged run: its values are there but not a prediction of the drop
        ("d", FLEXIBLE.name): Outcome("not ok: result flagged ENERGY_GAIN", False,
                                      {"e": 0.5, "delta_p": 40e-6, "spin_out": -10.0}),
        ("d", LIBRARY_RATES[0].name): Outcome("refused: mu must be >= 0", False, {}),
    }  # fmt: skip
    comparison, summary = _tables(outcomes)
    rigid = comparison[comparison["configuration"] == RIGID.name].set_index("quantity")
    assert rigid.loc["e", "z"] == pytest.approx(1.8)  # (0.554 - 0.5) / 0.03
    assert rigid.loc["delta_p", "z"] == pytest.approx(2.1)  # 8.4 um / 4 um
    assert rigid.loc["spin_out", "z"] == pytest.approx(-3.5)
    assert list(rigid["within_2_sigma"]) == [True, False, False]
    assert set(rigid["unit"]) == {"1", "m", "rad/s"}
    s = summary.set_index("configuration")
    assert s.loc[RIGID.name, "within_2_sigma"] == 1 and s.loc[RIGID.name, "compared"] == 3
    assert s.loc[RIGID.name, "chi2"] == pytest.approx(3.24 + 4.41 + 12.25)
    for name in (FLEXIBLE.name, LIBRARY_RATES[0].name):  # never counted as agreement
        rows = comparison[comparison["configuration"] == name]
        assert rows["predicted"].isna().all() and not rows["within_2_sigma"].any()
        assert (rows["status"] == s.loc[name, "status"]).all()
        assert s.loc[name, "within_2_sigma"] == 0 and math.isnan(s.loc[name, "chi2"])
        assert not s.loc[name, "ok"]


def test_a_quantity_the_model_does_not_define_is_not_compared() -> None:
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.5, "delta_p": 40e-6, "spin_out": -10.0}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.5, "delta_p": 40e-6},
                                      unsupported=("spin_out",)),
        ("d", LIBRARY_RATES[0].name): Outcome("not run: a sphere", False, {}),
    }  # fmt: skip
    comparison, summary = _tables(outcomes)
    flex = comparison[comparison["configuration"] == FLEXIBLE.name].set_index("quantity")
    assert flex.loc["spin_out", "status"].startswith("not predicted")
    assert not flex.loc["spin_out", "within_2_sigma"]
    s = summary.set_index("configuration").loc[FLEXIBLE.name]
    assert (s["within_2_sigma"], s["compared"], s["n_measured"]) == (2, 2, 3)
    # a sum over fewer quantities is no chi2 of the drop: never lower for leaving one out
    assert math.isnan(s["chi2"])


def _explained(outcomes) -> Explanation:
    comparison, summary = _tables(outcomes)
    return Explanation(comparison, summary, CONFIGS, "ghaednia", "coulomb", (), None, outcomes)


def test_best_ranks_over_the_quantities_every_ok_configuration_predicts() -> None:
    """The flexible rows leave spin_out unpredicted: the ok configurations are ranked over e
    and delta_p, which all of them predict, never over sums of different quantities (the
    rigid rod's chi2 alone is a sum over all three; the others' is NaN)."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.6, "delta_p": 40e-6, "spin_out": -10.0}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.55, "delta_p": 40e-6},
                                      unsupported=("spin_out",)),
        ("d", LIBRARY_RATES[0].name): Outcome("ok", True, {"e": 0.52, "delta_p": 40e-6},
                                              unsupported=("spin_out",)),
    }  # fmt: skip
    x = _explained(outcomes)
    s = x.summary.set_index("configuration")
    assert s.loc[RIGID.name, "chi2"] == pytest.approx((0.1 / 0.03) ** 2)
    assert math.isnan(s.loc[FLEXIBLE.name, "chi2"])
    v = x.verdict("d")
    assert x.best("d") == v.configuration == LIBRARY_RATES[0].name  # e: 0.52 beats 0.55, 0.6
    assert v.ranked_over == ("e", "delta_p") and v.left_out == ("spin_out",)
    assert f"spin_out (not predicted by {FLEXIBLE.name}, {LIBRARY_RATES[0].name})" in v.reason
    # with the rigid rod not ok, the others are ranked over the quantities both predict
    outcomes[("d", RIGID.name)] = Outcome("refused: mu must be >= 0", False, {})
    assert _explained(outcomes).best("d") == LIBRARY_RATES[0].name


def test_best_names_the_known_drops_for_an_unknown_one() -> None:
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.5, "delta_p": 40e-6, "spin_out": -10.0}),
        ("d", FLEXIBLE.name): Outcome("not run: a sphere", False, {}),
        ("d", LIBRARY_RATES[0].name): Outcome("not run: a sphere", False, {}),
    }  # fmt: skip
    x = _explained(outcomes)
    with pytest.raises(KeyError, match=r"no drop 'D'; drops: \['d'\]"):
        x.best("D")
    outcomes[("d", RIGID.name)] = Outcome("refused: mu must be >= 0", False, {})
    assert _explained(outcomes).best("d") is None  # a known drop, nothing ok: None
