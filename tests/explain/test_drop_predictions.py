"""What a flexible rod's drop predicts of a measured drop: its dent, slip and scar as the
sequence's totals, but not one contact's duration or mean force (the sequence's include the
flights between contacts), nor a signed contact_travel (a scar is an unsigned extent); the same
in the calibration. A rod the flexible rows refuse as a body puts a caveat on the rigid row;
a refused run gives no law_extrapolated."""

from __future__ import annotations

import math

import pytest

from impactlab.calibrate import CandidateModel, calibrate
from impactlab.calibrate.measurements import Measurements
from impactlab.explain import explain
from impactlab.explain.tables import BODY_CAVEAT

#: A paper drop at 20 deg with a signed contact travel, one contact's duration and mean force.
ONE_CONTACT = {
    "label": "a", "angle": "20 deg", "vy": -1.41, "mu": 0.2,
    "contact_travel": "-22 um", "contact_travel_sigma": "3 um",
    "duration": "0.12 ms", "duration_sigma": "0.02 ms",
    "mean_force": "1000 N", "mean_force_sigma": "100 N",
    "scar_length": "261 um", "scar_length_sigma": "30 um",
}  # fmt: skip
NOT_A_DROPS = ["contact_travel", "duration", "mean_force"]


def test_a_drop_does_not_predict_one_contacts_duration_nor_a_signed_travel() -> None:
    flexible = CandidateModel(body="flexible_rod")
    quantities = ["e", "delta_p", "sliding_length", "scar_length", *NOT_A_DROPS]
    assert flexible.unsupported(quantities) == NOT_A_DROPS
    assert CandidateModel().unsupported(quantities) == []
    x = explain(Measurements.from_records([ONE_CONTACT]), rate_laws=[])
    c = x.comparison.set_index(["configuration", "quantity"])
    for q in NOT_A_DROPS:
        assert c.loc[("flexible rod", q), "status"].startswith("not predicted")
        assert math.isnan(c.loc[("flexible rod", q), "predicted"])
        assert c.loc[("rigid body", q), "status"] == "ok"
    # the scar: the extent over all contacts (the rigid rod's one contact: |contact_travel|)
    assert c.loc[("flexible rod", "scar_length"), "predicted"] == pytest.approx(261e-6, abs=1e-6)
    rigid = c.loc[("rigid body", "scar_length"), "predicted"]
    assert rigid == pytest.approx(-c.loc[("rigid body", "contact_travel"), "predicted"])
    s = x.summary.set_index("configuration")
    assert (s.loc["flexible rod", "compared"], s.loc["flexible rod", "n_measured"]) == (1, 4)
    assert math.isnan(s.loc["flexible rod", "chi2"])
    # over the scar, which both predict, the flexible rod is first, but the rigid rod agrees
    # with more values (ones the drop does not predict): no configuration is named
    v = x.verdict("a")
    assert x.best("a") is None and v.ranked_over == ("scar_length",)
    assert v.left_out == ("contact_travel", "duration", "mean_force")
    assert "but rigid body agrees with more of the measured values" in v.reason


def test_the_calibration_refuses_them_for_the_flexible_rod() -> None:
    meas = Measurements.from_records([ONE_CONTACT])
    with pytest.raises(ValueError, match="does not predict contact_travel, duration, mean_force"):
        calibrate(meas, {"damping": "uniform(0, 0.1)"}, "ghaednia/coulomb/flexible_rod")


#: A rod whose mass makes it, as a uniform bar of aluminium, wider than twice its tip radius.
WIDE_ROD = {
    "label": "wide", "body_material": "al-6061-t6", "flat_material": "aisi-1010",
    "length": "150 mm", "tip_radius": "5 mm", "mass": 0.08, "angle": "30 deg", "vy": -1.5,
    "mu": 0.15, "e": 0.45, "e_sigma": 0.03,
}  # fmt: skip


def test_a_rod_the_flexible_rows_refuse_puts_a_caveat_on_the_rigid_row() -> None:
    x = explain(Measurements.from_records([WIDE_ROD]), rate_laws=[])
    s = x.summary.set_index("configuration")
    assert s.loc["flexible rod", "status"].startswith("refused: the diameter that the mass")
    assert s.loc["rigid body", "ok"] and s.loc["rigid body", "caveat"] == BODY_CAVEAT
    assert s.loc["flexible rod", "caveat"] == ""
    assert f"rigid body: {BODY_CAVEAT} (drops: wide)" in x.notes
    _, rows = x.display_rows()
    status = {r[1]: r[-1] for r in rows}
    assert status["rigid body"] == "ok (see notes)"
    assert x.to_dict()["summary"][0]["caveat"] == BODY_CAVEAT
    # a refused run gave no result: no law_extrapolated, and it is not counted as a run
    assert s.loc["flexible rod", "law_extrapolated"] is None
    assert s.loc["rigid body", "law_extrapolated"] is True
    assert any("beyond its verified range in 1 of 1 runs" in n for n in x.notes)


def test_a_rod_the_flexible_rod_takes_has_no_caveat(paper_explained) -> None:
    assert (paper_explained.summary["caveat"] == "").all()
    assert all(r["caveat"] is None for r in paper_explained.to_dict()["summary"])
