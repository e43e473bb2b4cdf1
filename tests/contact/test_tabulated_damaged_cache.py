"""The tabulated law's curves: a damaged file of the curves cache (valid JSON that is not a
curves record, or text cut short) is skipped with a warning naming it, never an
AttributeError for every pair; a user's residual depth that falls sharply is still raised
onto the largest before it, with a warning naming the point and how far."""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

import impactlab.contact.tabulated as tab
from impactlab.contact import IndentationCurves, get_law, tabulated_model
from impactlab.contact.indentation_data import (
    RESIDUAL_RAISE_TOLERANCE,
    ResidualRaisedWarning,
    curves_file_record,
    read_curves,
    shipped_curves,
)
from impactlab.fe.accuracy import tolerances
from impactlab.materials import AISI_201, AISI_1010, ContactPair

R = 8.8e-3
PAIR = ContactPair(AISI_201, AISI_1010)


@pytest.mark.parametrize(
    "content",
    ["[]", "null", '"x"', "3", '{"format": 1}', "{", '{"curves": [[]]}', "not json"],
)
def test_a_damaged_cache_file_is_skipped_with_a_warning(
    content: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    good = curves_file_record([shipped_curves()[0]])
    (tmp_path / "a-good.json").write_text(json.dumps(good))
    bad = tmp_path / "b-bad.json"
    bad.write_text(
        content
        if content != '{"curves": [[]]}'
        else json.dumps({**good, "curves": [[]]})  # the right header, a curve set that is not
    )
    monkeypatch.setattr(tab, "curves_cache_dir", lambda: tmp_path)
    with pytest.raises(ValueError, match=r"is not an indentation curves file|not valid|JSON"):
        read_curves(bad)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        found = tab.cached_curves()
        model = get_law("tabulated").build(PAIR, R)  # every pair still builds
    assert [c.name for c in found] == [shipped_curves()[0].name]  # the good file is read
    assert model.source.startswith("paper-aisi201-on-aisi1010")
    named = [w for w in caught if issubclass(w.category, tab.DamagedCurvesWarning)]
    assert named and all(str(bad) in str(w.message) for w in named)
    assert "skipped, as if missing" in str(named[0].message)


def _user_data(dr_change: int | None = None) -> tuple[np.ndarray, ...]:
    """Loading and unloading data of the paper's pair from Ghaednia's law (the docs' example);
    ``dr_change``: the index of delta_r set to the one two places before it (a sharp fall)."""
    ref = get_law("ghaednia").build(PAIR, R)
    delta = np.geomspace(1e-8, 300e-6, 64)
    force = np.array([ref.force(d) for d in delta])
    delta_max = delta[31::4]
    delta_r = np.array([ref.unload(d).delta_r for d in delta_max])
    if dr_change is not None:
        delta_r[dr_change] = delta_r[dr_change - 2]
    return delta, force, delta_max, delta_r


def test_a_residual_depth_raised_beyond_the_tolerance_warns_naming_it() -> None:
    assert tolerances()["residual_ratio_absolute"] == RESIDUAL_RAISE_TOLERANCE
    data = _user_data(5)
    with pytest.warns(ResidualRaisedWarning) as caught:
        curves = IndentationCurves.from_arrays(PAIR, R, *data)
    (w,) = caught
    text = str(w.message)
    raised = np.maximum.accumulate(curves.residual_ratio) - curves.residual_ratio
    assert f"raised by {raised[5]:.3g} to " in text and "0.582" in text and "0.05" in text
    assert text.count(f"(delta_max = {data[2][5]:.4g} m) at index 5") == 1
    assert w.filename == __file__  # the caller's line
    model = tabulated_model(curves, PAIR, R)  # the documented raising itself is kept
    assert model.details["residual_raised"] == pytest.approx(raised[5])


def test_a_csv_point_raised_is_named_by_its_line(tmp_path: Path) -> None:
    delta, force, delta_max, delta_r = _user_data(5)
    load, unload = tmp_path / "load.csv", tmp_path / "unload.csv"
    np.savetxt(load, np.column_stack([delta, force]), delimiter=",", header="d,F", comments="")
    np.savetxt(unload, np.column_stack([delta_max, delta_r]), delimiter=",", header="dm,dr")
    with pytest.warns(ResidualRaisedWarning) as caught:
        IndentationCurves.from_csv(PAIR, R, load, unload)
    (w,) = caught  # once, by its line (the header is line 1, index 5 is line 7)
    assert f"unloading CSV {str(unload)!r} line 7: " in str(w.message)


def test_curves_made_directly_name_the_point_by_index() -> None:
    c = shipped_curves()[0]
    r = c.residual_ratio.copy()
    r[-1] = r[-2] - 0.1
    with pytest.warns(ResidualRaisedWarning, match=r"index \d+ \(delta_max/delta_c = "):
        IndentationCurves(
            "edited", "test", c.e_star_over_sy, c.nu, c.delta, c.force, c.delta_max, r
        )


def test_a_small_fall_is_raised_without_a_word() -> None:
    delta, force, delta_max, delta_r = _user_data()
    delta_r[5] *= 1.0 - 0.5 * RESIDUAL_RAISE_TOLERANCE  # ratio lowered by < 0.05 below [4]'s
    delta_r[5] = min(delta_r[5], delta_r[4] * delta_max[5] / delta_max[4])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        curves = IndentationCurves.from_arrays(PAIR, R, delta, force, delta_max, delta_r)
        shipped_curves.cache_clear()
        assert shipped_curves()  # the shipped curves raise nothing
    assert 0.0 < tab.residual_raised(curves) <= RESIDUAL_RAISE_TOLERANCE
