"""``Calibration.predict`` keeps the marks a single result carries: the share of its cases whose
contact law was used beyond its verified range (with the CalibrationWarning ``calibrate``
gives), a warning for a drop whose every draw failed, and a refused case's own reason; and its
arguments are checked by name (formerly the mark was dropped, a failed drop was silent, and a
single record, None or a bad seed raised errors from inside the library)."""

from __future__ import annotations

import dataclasses
import warnings
from typing import Any

import numpy as np
import pint
import pytest

from impactlab.calibrate import Calibration, CalibrationWarning
from impactlab.calibrate import parse_parameter as parameter
from impactlab.calibrate.drop_predictions import predict_drops
from impactlab.flags import FLAG_LAW_EXTRAPOLATED
from impactlab.sweep.engine import ENGINE

SY = parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)")
NEW = {"label": "new", "angle": "30 deg", "vy": -2.0}
EXTRAPOLATED = (
    r"model 'ghaednia/coulomb': the contact law 'ghaednia' is extrapolated in 100 % of the 6 "
    r"predicted cases \(drops 'new', 'slow'; flag LAW_EXTRAPOLATED"
)


class _WithinRange:
    """The compiled engine with the LAW_EXTRAPOLATED bit cleared: a law inside its range."""

    def __getattr__(self, name: str) -> Any:
        return getattr(ENGINE, name)

    def __call__(self, cases, statics, outputs):  # type: ignore[no-untyped-def]
        res, status = ENGINE(cases, statics, outputs)
        flags = np.nan_to_num(res["flags"]).astype(np.int64) & ~FLAG_LAW_EXTRAPOLATED
        return {**res, "flags": flags.astype(np.float64)}, status


def _quiet(fn: Any, *args: Any, **kw: Any) -> Any:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return fn(*args, **kw)


def test_an_extrapolated_law_is_marked_and_warned_about(mu_calibration: Calibration) -> None:
    """The paper's rod presses Ghaednia's law far past its verified range."""
    with pytest.warns(CalibrationWarning, match=EXTRAPOLATED):
        got = mu_calibration.predict([NEW, {**NEW, "label": "slow", "vy": -1.0}], ["e"], draws=3)
    assert got.extrapolated is not None and got.extrapolated.shape == (3, 2)
    assert got.extrapolated.all()
    rows = got.summary()
    assert [r["extrapolated"] for r in rows] == [1.0, 1.0]
    assert all(r["failed"] == 0.0 and r["reason"] == "" for r in rows)


def test_a_law_within_its_range_is_not_warned_about(mu_calibration: Calibration) -> None:
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        got = mu_calibration.predict([NEW], ["e"], draws=3, evaluator=_WithinRange())
    assert not [w for w in seen if "extrapolated" in str(w.message)]
    assert got.extrapolated is not None and not got.extrapolated.any()
    assert got.summary()[0]["extrapolated"] == 0.0


def test_a_drop_whose_every_draw_failed_is_warned_about(mu_calibration: Calibration) -> None:
    with pytest.warns(CalibrationWarning, match=(
        r"model 'ghaednia/coulomb' predicts nothing for 1 drop\(s\): every one of the 3 posterior "
        r"draws failed \('t': result flagged GRAVITY_DOMINATED .*\); their values are NaN"
    )):  # fmt: skip
        got = mu_calibration.predict([NEW, {**NEW, "label": "t", "vy": -1e-5}], ["e"], draws=3)
    row = got.summary()[1]
    assert row["failed"] == 1.0 and np.isnan(row["median"]) and np.isnan(row["extrapolated"])
    assert row["reason"].startswith("result flagged GRAVITY_DOMINATED")


def test_a_refused_drop_names_its_own_reason(mu_calibration: Calibration) -> None:
    """A rate law refuses a flat yield strength outside its fitted 150-450 MPa: the reason was
    'simulate refused the case (or the drop failed)'."""
    name = "ghaednia/coulomb/flexible_rod/cowper-symonds"
    definition = {"law": "ghaednia", "friction": "coulomb", "body": "flexible_rod",
                  "rate": "cowper-symonds", "fixed": {}, "law_params": {}}  # fmt: skip
    first = next(iter(mu_calibration.posteriors.values()))
    post = dataclasses.replace(first, model=name, params=(SY,),
                               samples=np.array([[110e6], [900e6]]))  # fmt: skip
    settings = {"model_definitions": {name: definition}, "engine": {}}
    cond = [{**NEW, "mu": 0.2}, {**NEW, "label": "other", "mu": 0.3}]
    with pytest.warns(CalibrationWarning, match=r"predicts nothing for 2 drop\(s\).*'new': "
                      r"simulate refused the case: rate 'cowper-symonds'"):  # fmt: skip
        got = predict_drops({name: post}, settings, cond, ["e"], draws=2)
    assert set(got.refused) == {"new", "other"}
    reason = got.summary()[0]["reason"]
    assert reason.startswith("simulate refused the case: rate 'cowper-symonds': its constants")
    assert "outside 150 to 450 MPa" in reason


def test_one_record_is_one_drop(mu_calibration: Calibration) -> None:
    one = _quiet(mu_calibration.predict, NEW, ["e"], draws=3)
    listed = _quiet(mu_calibration.predict, [NEW], ["e"], draws=3)
    assert one.labels == ("new",)
    np.testing.assert_array_equal(one.values["e"], listed.values["e"])


@pytest.mark.parametrize(
    ("conditions", "match"),
    [
        (None, r"conditions must be records \(a list of dicts, one per drop.*got None$"),
        (5, r"conditions must be records .*got 5 \(a int\)"),
        (["new"], r"conditions must be records .*; item 1 is 'new' \(a str\)"),
    ],
)
def test_conditions_that_are_no_records_are_refused(
    mu_calibration: Calibration, conditions: Any, match: str
) -> None:
    with pytest.raises(ValueError, match=match):
        mu_calibration.predict(conditions, ["e"], draws=3)


def test_a_dataframe_is_pointed_to_its_records(mu_calibration: Calibration) -> None:
    import pandas

    with pytest.raises(ValueError, match=r"got a DataFrame: pass df.to_dict\('records'\)"):
        mu_calibration.predict(pandas.DataFrame([NEW]), ["e"], draws=3)


@pytest.mark.parametrize("seed", [-1, 1.5, "a", True, 2**32, np.float64(3.0)])
def test_a_bad_seed_is_refused_by_name(mu_calibration: Calibration, seed: Any) -> None:
    with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 4294967295\] \(or None"):
        mu_calibration.predict([NEW], ["e"], draws=3, seed=seed)


@pytest.mark.parametrize("seed", [None, 0, np.int64(7), 2**32 - 1])
def test_a_good_seed_is_taken(mu_calibration: Calibration, seed: Any) -> None:
    assert _quiet(mu_calibration.predict, [NEW], ["e"], draws=3, seed=seed).draws.shape == (3, 1)


def test_a_pint_quantity_reads_as_its_value_with_unit(mu_calibration: Calibration) -> None:
    """Every other entry point takes a Quantity of any registry; a record refused it."""
    ureg: Any = pint.UnitRegistry()
    given = {"label": "new", "angle": ureg("30 deg"), "vy": ureg("-200 cm/s")}
    got = _quiet(mu_calibration.predict, [given], ["e"], draws=3)
    want = _quiet(mu_calibration.predict, [NEW], ["e"], draws=3)
    np.testing.assert_array_equal(got.values["e"], want.values["e"])
