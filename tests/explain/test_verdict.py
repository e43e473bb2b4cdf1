"""``best`` and ``verdict``: the ok configurations are ranked over the measured quantities that
all of them predict; one more measured quantity that only one of them predicts never turns the
verdict to it, and no configuration that agrees with nothing is named best beside one that
agrees with something."""

from __future__ import annotations

import pytest

from impactlab.calibrate.measurements import Measurements, read_measurements
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
    assert v.ranked_over == ("e", "delta_p") and v.left_out == ("duration",)
    assert "duration (not predicted by flexible rod, " in v.reason
    assert any(n.startswith("best: flexible rod: ") and n.endswith("(drops: 20 deg)")
               for n in x.notes)  # fmt: skip
    # measuring the duration as well changes nothing of the verdict
    assert without.best("20 deg") == "flexible rod"
    assert without.verdict("20 deg").ranked_over == v.ranked_over
    assert not any(n.startswith("best: ") for n in without.notes)  # nothing left out
    best = x.to_dict()["best"]
    assert best == [{"drop": "20 deg", "configuration": "flexible rod", "consistent": True,
                     "agrees": True, "agreements": 2, "least_disagreeing": None,
                     "undecided": [], "ranked_over": ["e", "delta_p"], "left_out": ["duration"],
                     "within_2_sigma": 2, "chi2": {"value": v.chi2, "unit": "1"},
                     "predicted_over": ["e", "delta_p"],
                     "consistency_chi2": {"value": v.chi2, "unit": "1"},
                     "p_value": {"value": v.p_value, "unit": "1"}, "provisional": False,
                     "caveat": None, "reason": v.reason}]  # fmt: skip
    assert "(2 of 2 within 2 sigma, chi2 0.06259)" in v.reason


def test_none_agrees_over_the_shared_values_whatever_one_agrees_with_left_out() -> None:
    """Over e, which both predict, neither agrees (the flexible rod is closer); the rigid rod
    agrees with the duration, which the flexible rod does not predict: the verdict is as
    without the duration, none named and the flexible rod the least disagreeing, and the
    reason says where the agreement lies."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.8, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.7}, unsupported=("duration",)),
    }
    x = _explained(DROP, outcomes)
    v = x.verdict("d")
    assert x.best("d") is None and v.configuration is None
    assert v.least_disagreeing == FLEXIBLE.name
    assert v.ranked_over == ("e",) and v.left_out == ("duration",)
    assert v.reason.startswith(
        "no configuration agrees within 2 sigma with a value ranked over: flexible rod "
        "disagrees least, over e, the quantities"
    )
    assert (
        "within 2 sigma only with values left out, which not every ok configuration "
        "predicts: rigid body with duration" in v.reason
    )
    assert v.agrees is False and v.to_dict()["agrees"] is False  # the first agrees with nothing
    no_duration = {k: v for k, v in DROP.items() if not k.startswith("duration")}
    without = _explained(no_duration, outcomes).verdict("d")
    assert (without.configuration, without.least_disagreeing) == (None, FLEXIBLE.name)
    # with every ok configuration agreeing with nothing, the old words stand
    outcomes[("d", RIGID.name)] = Outcome("ok", True, {"e": 0.8, "duration": 2.0e-3})
    v = _explained(DROP, outcomes).verdict("d")
    assert v.configuration is None and v.least_disagreeing == FLEXIBLE.name
    assert v.reason.startswith("no configuration agrees with any measured value within 2 sigma")


def test_another_that_agrees_with_more_left_out_withholds_a_verdict() -> None:
    """The flexible rod agrees with e, the rigid rod with e and the duration, which the
    flexible rod does not predict; over e the flexible rod is first (z 0 against 1.67): none is
    named, and the reason says why."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.55, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.5}, unsupported=("duration",)),
    }
    v = _explained(DROP, outcomes).verdict("d")
    assert v.configuration is None and v.least_disagreeing is None
    assert v.reason.startswith("none is named: flexible rod ranks first over e, the quantities")
    assert "but rigid body agrees with more of the measured values (2 against 1)" in v.reason


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
    assert v.configuration is None and v.ranked_over == ()
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


def test_a_first_that_agrees_only_with_a_quantity_left_out_is_not_named() -> None:
    """The rigid body is first over e (closer, neither within 2 sigma) and agrees with the
    duration alone, which the flexible rod does not predict: not named (docs/explain.md:
    measuring one more quantity never turns the verdict to a model for what it alone
    predicts), the least disagreeing, as without the duration."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.7, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.8}, unsupported=("duration",)),
    }
    x = _explained(DROP, outcomes)
    v = x.verdict("d")
    assert x.best("d") is None and v.configuration is None
    assert v.least_disagreeing == RIGID.name and v.agrees is True and v.within_2_sigma == 0
    assert "rigid body with duration" in v.reason
    no_duration = {k: v for k, v in DROP.items() if not k.startswith("duration")}
    without = _explained(no_duration, outcomes).verdict("d")
    assert (without.configuration, without.least_disagreeing) == (None, RIGID.name)
    head, rows = x.display_rows()
    assert {r[1]: r[head.index("verdict")] for r in rows}[RIGID.name] == (
        "least disagreeing (none agrees)"
    )


def test_a_measured_duration_does_not_turn_a_real_verdict(tmp_path) -> None:
    """The 20 deg drop with e alone, then with a duration only the rigid rod predicts (and
    meets): no configuration agrees with e, so none is named either way."""
    head = "label,angle [deg],vy [m/s],mu,e,e_sigma"
    (tmp_path / "e.csv").write_text(f"{head}\nd,20,-1.41,0.2,0.5,0.03\n")
    (tmp_path / "ed.csv").write_text(f"{head},duration [ms],duration_sigma [ms]\n"
                                     "d,20,-1.41,0.2,0.5,0.03,0.125,0.01\n")  # fmt: skip
    plain, more = (explain(tmp_path / f, rate_laws=[]).verdict("d") for f in ("e.csv", "ed.csv"))
    assert plain.configuration is None and plain.least_disagreeing == RIGID.name
    assert more.configuration is None and more.least_disagreeing == RIGID.name
    assert more.ranked_over == plain.ranked_over == ("e",) and more.left_out == ("duration",)
    assert more.chi2 == plain.chi2


def test_one_name_per_thing_in_python_and_json(tmp_path) -> None:
    """The quantities ranked over are ``ranked_over`` in Python and JSON (``quantities``, the
    former Python name, warns); the count ``agreements`` and the bool ``agrees`` are both in
    each; ``source`` is the file a Measurements was read from, None for one made in Python."""
    outcomes = {
        ("d", RIGID.name): Outcome("ok", True, {"e": 0.51, "duration": 1.0e-3}),
        ("d", FLEXIBLE.name): Outcome("ok", True, {"e": 0.7}, unsupported=("duration",)),
    }
    v = _explained(DROP, outcomes).verdict("d")
    with pytest.warns(DeprecationWarning, match="use Verdict.ranked_over"):
        assert v.quantities == v.ranked_over == ("e",)
    doc = v.to_dict()
    assert doc["ranked_over"] == ["e"] and "quantities" not in doc
    assert (doc["agreements"], doc["agrees"]) == (v.agreements, v.agrees) == (2, True)
    sphere = tmp_path / "sphere.csv"  # a sphere runs the rigid configuration alone: quick
    sphere.write_text("label,body,radius [mm],vy [m/s],mu,e,e_sigma\ns,sphere,5,-1,0.2,0.9,0.03\n")
    x = explain(read_measurements(sphere))
    assert x.source == str(sphere) and x.to_dict()["source"] == str(sphere)
    assert _explained(DROP, outcomes).to_dict()["source"] is None
