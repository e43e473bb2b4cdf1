"""``best`` and ``verdict``: the ok configurations are ranked over the measured quantities that
all of them predict; one more measured quantity that only one of them predicts never turns the
verdict to it, and no configuration that agrees with nothing is named best beside one that
agrees with something."""

from __future__ import annotations

import pytest

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import Explanation, explain
from impactlab.explain.configurations import FLEXIBLE, RIGID
from impactlab.explain.runs import Outcome
from impactlab.explain.tables import comparison_table, summary_table

#: The paper's 20 deg drop with a measured e, dent and contact duration that the flexible rod
#: meets in e and the dent (the duration: one contact's, which a drop does not predict).
DURATION_CSV = (
    "label,angle [deg],vy [m/s],mu,e,e_sigma,delta_p [um],delta_p_sigma [um],"
    "duration [ms],duration_sigma [ms]\n"
    "20 deg,20,-1.41,0.20,0.72,0.03,32,2.2,0.95,0.1\n"
)
CONFIGS = (RIGID, FLEXIBLE)
DROP = {"label": "d", "angle": "45 deg", "vy": -2.0, "mu": 0.2, "e": 0.5, "e_sigma": 0.03,
        "duration": "1 ms", "duration_sigma": "0.1 ms"}  # fmt: skip


def _explained(drop: dict, outcomes: dict) -> Explanation:
    meas = Measurements.from_records([drop])
    comparison = comparison_table(meas, CONFIGS, outcomes)
    summary = summary_table(meas, CONFIGS, outcomes, comparison)
    return Explanation(comparison, summary, CONFIGS, "ghaednia", "coulomb", (), None, outcomes)


@pytest.fixture(scope="module")
def with_duration(tmp_path_factory: pytest.TempPathFactory) -> tuple[Explanation, Explanation]:
    """The drop explained with its duration, and without that column."""
    folder = tmp_path_factory.mktemp("duration")
    (folder / "dur.csv").write_text(DURATION_CSV)
    lines = [",".join(line.split(",")[:-2]) for line in DURATION_CSV.splitlines()]
    (folder / "no_dur.csv").write_text("\n".join(lines) + "\n")
    return explain(folder / "dur.csv"), explain(folder / "no_dur.csv")


def test_a_quantity_only_the_rigid_rod_predicts_does_not_make_it_best(
    with_duration: tuple[Explanation, Explanation],
) -> None:
    x, without = with_duration
    s = x.summary.set_index("configuration")
    assert s.loc["rigid body", "within_2_sigma"] == 0 and s.loc["rigid body", "compared"] == 3
    assert s.loc["flexible rod", "within_2_sigma"] == 2
    z = x.comparison.set_index(["configuration", "quantity"])["z"]  # as docs/explain.md states
    rigid = [round(z[("rigid body", q)], 1) for q in ("e", "delta_p", "duration")]
    assert rigid == [-9.9, 13.7, -8.3]
    assert [round(z[("flexible rod", q)], 2) for q in ("e", "delta_p")] == [0.13, 0.21]
    v = x.verdict("20 deg")
    assert v.configuration == x.best("20 deg") == "flexible rod"
    assert v.quantities == ("e", "delta_p") and v.left_out == ("duration",)
    assert "duration (not predicted by flexible rod, " in v.reason
    assert any(n.startswith("best: flexible rod: ") and n.endswith("(drops: 20 deg)")
               for n in x.notes)  # fmt: skip
    # measuring the duration as well changes nothing of the verdict
    assert without.best("20 deg") == "flexible rod"
    assert without.verdict("20 deg").quantities == v.quantities
    assert not any(n.startswith("best: ") for n in without.notes)  # nothing left out
    best = x.to_dict()["best"]
    assert best == [{"drop": "20 deg", "configuration": "flexible rod", "agrees": True,
                     "least_disagreeing": None, "undecided": [],
                     "ranked_over": ["e", "delta_p"], "left_out": ["duration"],
                     "within_2_sigma": 2, "chi2": {"value": v.chi2, "unit": "1"},
                     "provisional": False, "caveat": None, "reason": v.reason}]  # fmt: skip
    assert "(2 of 2 within 2 sigma, chi2 0.06259)" in v.reason


def test_none_is_named_best_that_agrees_with_fewer_values_than_another() -> None:
    """Over e, which both predict, neither agrees (the flexible rod is closer); the rigid rod
    agrees with the duration, which the flexible rod does not predict: no verdict, and the
    reason says why."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.8, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.7}, unsupported=("duration",)),
    }
    x = _explained(DROP, outcomes)
    v = x.verdict("d")
    assert x.best("d") is None and v.configuration is None
    assert v.quantities == ("e",) and v.left_out == ("duration",)
    assert v.reason.startswith("none is named: flexible rod ranks first over e, the quantities")
    assert "but rigid body agrees with more of the measured values (1 against 0)" in v.reason
    assert v.agrees is False and v.to_dict()["agrees"] is False  # the first agrees with nothing
    # with every ok configuration agreeing with nothing, none is named best: the lowest chi2
    # is the least disagreeing one
    outcomes[("d", RIGID.name)] = Outcome("ok", True, {"e": 0.8, "duration": 2.0e-3})
    v = _explained(DROP, outcomes).verdict("d")
    assert v.configuration is None and v.least_disagreeing == FLEXIBLE.name


def test_configurations_that_share_no_quantity_name_none() -> None:
    drop = {"label": "d", "angle": "45 deg", "vy": -2.0, "mu": 0.2, "duration": "1 ms",
            "duration_sigma": "0.1 ms", "delta_p": "40 um", "delta_p_sigma": "4 um"}  # fmt: skip
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"duration": 1.0e-3},
                                   unsupported=("delta_p",)),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"delta_p": 40e-6},
                                      unsupported=("duration",)),
    }  # fmt: skip
    v = _explained(drop, outcomes).verdict("d")
    assert v.configuration is None and v.quantities == ()
    assert "predict no measured quantity in common" in v.reason
    # an ok configuration that predicts no measured value is no rival
    outcomes[("d", FLEXIBLE.name)] = Outcome("ok", True, {}, unsupported=("duration", "delta_p"))
    assert _explained(drop, outcomes).best("d") == RIGID.name


def test_the_rigid_rod_stays_best_where_it_agrees_over_the_shared_quantities() -> None:
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.51, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.7}, unsupported=("duration",)),
    }
    x = _explained(DROP, outcomes)
    assert x.best("d") == RIGID.name
    assert x.verdict("d").reason.startswith("rigid body: the most values within 2 sigma")


def test_a_first_that_agrees_only_with_a_quantity_left_out_says_so() -> None:
    """The rigid body is first over e (closer, neither within 2 sigma) and agrees with the
    duration, which the flexible rod does not predict: named, and the reason says where its
    agreement lies rather than claiming "the most values within 2 sigma" at 0."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.7, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.8}, unsupported=("duration",)),
    }
    v = _explained(DROP, outcomes).verdict("d")
    assert v.configuration == RIGID.name and v.agrees is True and v.within_2_sigma == 0
    assert "the most values within 2 sigma" not in v.reason
    assert "agrees within 2 sigma only with duration" in v.reason
