"""Ranking first is not explaining the drop: a named row whose chi2 over the values it predicts
has a p-value below 0.01 (chi2 with n degrees of freedom) is worded as ranking first but
inconsistent with the measurements, marked ``first, inconsistent`` in the table and
``consistent: false`` in JSON; a row whose contact law is extrapolated says so in its reason."""

from __future__ import annotations

import math

import pytest
from scipy.stats import chi2 as chi2_distribution

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import Explanation
from impactlab.explain.configurations import FLEXIBLE, RIGID
from impactlab.explain.correlated import drop_pairs
from impactlab.explain.runs import Outcome
from impactlab.explain.tables import comparison_table, summary_table
from impactlab.explain.verdict import LEVEL, p_value

CONFIGS = (RIGID, FLEXIBLE)
DROP = {"label": "d", "angle": "45 deg", "vy": -2.0, "mu": 0.2, "e": 0.5, "e_sigma": 0.03,
        "delta_p": "40 um", "delta_p_sigma": "4 um"}  # fmt: skip


def _explained(drop: dict, rigid: dict, flexible: dict) -> Explanation:
    meas = Measurements.from_records([drop])
    outcomes = {("d", RIGID.name): Outcome("ok", True, rigid),
                ("d", FLEXIBLE.name): Outcome("ok", True, flexible)}  # fmt: skip
    comparison = comparison_table(meas, CONFIGS, outcomes)
    summary = summary_table(meas, CONFIGS, outcomes, comparison)
    pairs = {"d": drop_pairs(meas, 0)}
    return Explanation(comparison, summary, CONFIGS, "ghaednia", "coulomb", (), None, outcomes,
                       pairs)  # fmt: skip


def _marks(x: Explanation) -> dict[str, str]:
    head, rows = x.display_rows()
    return {r[1]: r[head.index("verdict")] for r in rows[1:]}


def test_the_level_is_the_chi_square_99_percent_quantile() -> None:
    assert LEVEL == 0.01
    for n in (1, 2, 3, 4):
        q = chi2_distribution.ppf(1 - LEVEL, n)
        assert p_value(q, n) == pytest.approx(LEVEL, rel=1e-9)
    assert p_value(6.63, 1) > LEVEL > p_value(6.64, 1)  # 6.635 for one value


def test_a_first_the_measurements_reject_ranks_first_but_is_not_best() -> None:
    """The rigid rod meets e (z +0.33) and misses the dent by z +4 (chi2 16.1 over 2 values,
    p = 3e-4); the flexible rod meets neither. Ranked first, named, and inconsistent."""
    x = _explained(DROP, {"e": 0.51, "delta_p": 56e-6}, {"e": 0.62, "delta_p": 60e-6})
    v = x.verdict("d")
    assert v.configuration == x.best("d") == RIGID.name and v.consistent is False
    assert v.p_value == pytest.approx(chi2_distribution.sf(v.chi2, 2), rel=1e-9)
    assert v.reason.startswith("rigid body: ranks first by the most values within 2 sigma, then "
                               "the lowest chi2, over e, delta_p (1 of 2 within 2 sigma, chi2 "
                               "16.11), but is itself inconsistent with the measurements (chi2 "
                               "16.11 over 2 values, p = 0.00032, below 0.01)")  # fmt: skip
    assert _marks(x) == {RIGID.name: "first, inconsistent", FLEXIBLE.name: ""}
    best = x.to_dict()["best"][0]
    assert best["configuration"] == RIGID.name and best["consistent"] is False
    assert best["p_value"] == {"value": pytest.approx(v.p_value), "unit": "1"}
    assert v.note == f"best: {v.reason}"  # a note says it, as for a provisional verdict


def test_the_line_lies_at_p_001() -> None:
    """e at z 0, the dent at z +3.0 (chi2 9, p = 0.011): consistent, plain best; at z +3.1
    (chi2 9.61, p = 0.0082): inconsistent."""
    far = {"e": 0.62, "delta_p": 60e-6}
    x = _explained(DROP, {"e": 0.5, "delta_p": 52e-6}, far)
    v = x.verdict("d")
    assert v.configuration == RIGID.name and v.consistent is True and v.p_value > LEVEL
    assert "inconsistent" not in v.reason and _marks(x)[RIGID.name] == "best"
    assert v.note == ""
    x = _explained(DROP, {"e": 0.5, "delta_p": 52.4e-6}, far)
    v = x.verdict("d")
    assert v.configuration == RIGID.name and v.consistent is False and v.p_value < LEVEL
    assert _marks(x)[RIGID.name] == "first, inconsistent"


def test_a_correlated_chi2_of_1e8_is_inconsistent() -> None:
    """e and spin_out correlated at -0.99999999: the rigid rod's e at z -2.58 and spin_out at
    +1.17 count one value within 2 sigma, but their joint chi2 is about 1e8."""
    drop = {"label": "d", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.5, "e_sigma": 0.03,
            "spin_out": -10.5, "spin_out_sigma": 0.5,
            "correlation_e_spin_out": -0.99999999}  # fmt: skip
    x = _explained(drop, {"e": 0.5 - 0.03 * 2.58, "spin_out": -10.5 + 0.5 * 1.17},
                   {"e": 0.5 + 0.03 * 7.46, "spin_out": -10.5 - 0.5 * 3.1})  # fmt: skip
    v = x.verdict("d")
    assert v.configuration == RIGID.name and v.within_2_sigma == 1 and v.chi2 > 1e7
    assert v.consistent is False and "p < 1e-300, below 0.01" in v.reason
    assert _marks(x)[RIGID.name] == "first, inconsistent"


def test_the_paper_drops_rank_rows_the_measurements_reject(paper_explained) -> None:
    """At 20 and 70 deg the first row misses e and the dent or scar by 8 to 12 sigma: named as
    ranking first, inconsistent, its extrapolated contact law said in the reason."""
    x = paper_explained
    for drop, n in (("20 deg", 129.6), ("70 deg", 279.3)):
        v = x.verdict(drop)
        assert v.configuration is not None and v.consistent is False
        words = f"but is itself inconsistent with the measurements (chi2 {n} over 3 values, p = "
        assert words in v.reason
        assert (
            "; it uses the contact law beyond its verified range "
            "(law_extrapolated: max_delta_ratio " in v.reason
        )
        assert _marks_of(x, drop)[v.configuration] == "first, inconsistent"
    v45 = x.verdict("45 deg")
    assert v45.configuration is None and v45.consistent is False  # the least disagreeing
    assert "inconsistent" not in v45.reason


def _marks_of(x: Explanation, drop: str) -> dict[str, str]:
    head, rows = x.display_rows()
    at = next(i for i, r in enumerate(rows) if r[0] == drop)
    block = rows[at + 1 : at + 1 + len(x.configurations)]
    return {r[1]: r[head.index("verdict")] for r in block}


def test_a_first_that_misses_a_value_only_it_predicts_is_not_consistent(tmp_path) -> None:
    """The rigid rod ranked first over e (z +0.12), the one value every row predicts, and was
    called consistent (p = 0.90) while it missed the duration, which only it predicts, by 8.3
    sigma: its consistency is over every value it predicts."""
    from impactlab.explain import explain

    path = tmp_path / "dur.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma,duration [ms],duration_sigma [ms]\n"
        "r1,20,-1.41,0.2,0.42,0.02,0.95,0.1\n"
    )
    v = explain(path).verdict("r1")
    assert v.configuration == "rigid body" and v.ranked_over == ("e",)
    assert v.left_out == ("duration",)
    assert v.consistent is False and v.p_value < 1e-10
    assert "inconsistent with the measurements (chi2 " in v.reason
    assert "over 2 values it predicts" in v.reason


def test_the_p_value_is_that_of_the_chi2_beside_it(tmp_path) -> None:
    """The rigid rod ranked over e alone (chi2 0.015) but predicting e and the duration: its
    p-value is that of its chi2 over both (68.5, p = 1.3e-15), and both are fields, in Python
    and JSON, beside the ranking's chi2."""
    from impactlab.explain import explain

    path = tmp_path / "dur.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma,duration [ms],duration_sigma [ms]\n"
        "r1,20,-1.41,0.2,0.42,0.02,0.95,0.1\n"
    )
    x = explain(path)
    v = x.verdict("r1")
    assert v.ranked_over == ("e",) and v.chi2 == pytest.approx(0.01514, rel=1e-3)
    assert v.predicted_over == ("e", "duration")
    assert v.consistency_chi2 == pytest.approx(68.49, rel=1e-3)
    assert v.p_value == pytest.approx(
        chi2_distribution.sf(v.consistency_chi2, len(v.predicted_over)), rel=1e-9
    )
    assert f"chi2 {v.consistency_chi2:.4g} over 2 values it predicts" in v.reason
    best = x.to_dict()["best"][0]
    assert best["chi2"] == {"value": pytest.approx(v.chi2), "unit": "1"}
    assert best["predicted_over"] == ["e", "duration"]
    assert best["consistency_chi2"] == {"value": pytest.approx(v.consistency_chi2), "unit": "1"}
    p = chi2_distribution.sf(best["consistency_chi2"]["value"], len(best["predicted_over"]))
    assert best["p_value"] == {"value": pytest.approx(p, rel=1e-9), "unit": "1"}


def test_a_verdict_that_ranks_nothing_has_no_consistency_chi2() -> None:
    """None ok: nothing ranked, so no chi2, nothing predicted over, no p-value."""
    x = _explained(DROP, {"e": 0.51, "delta_p": 56e-6}, {"e": 0.62, "delta_p": 60e-6})
    x.summary["ok"] = False
    v = x.verdict("d")
    assert v.configuration is None and v.predicted_over == () and v.consistent is None
    assert math.isnan(v.consistency_chi2) and math.isnan(v.p_value)
    best = x.to_dict()["best"][0]
    assert best["predicted_over"] == [] and best["consistency_chi2"]["value"] is None
