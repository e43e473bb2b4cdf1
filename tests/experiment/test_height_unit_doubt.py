"""A scan read in a height unit 1000 times too small (um heights as nm) gives a dent both
shallower than 0.1 um and hundreds of times shallower than the tip's cap at its width: the
analysis is not ok (a doubt), so that it is not taken as a measurement; the right unit is ok."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, analyze
from impactlab.experiment.profilometry.plausibility import UNIT_DOUBT_RATIO

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


def _analyze(tmp_path: Path, unit: str):
    geometry = MarkerGeometry.from_mapping(
        {"units": "mm", "M1": [-30, 18, 0], "M2": [-90, 0, 22], "M3": [-130, -20, 4]}
    )
    return analyze(DATA / "drop.csv", DATA / "dent.npy", PAPER_ROD, geometry=geometry, up="+y",
                   pixel_size="12 um", height_unit=unit, out_dir=tmp_path / unit)  # fmt: skip


def test_heights_read_in_nm_for_um_are_not_ok(tmp_path: Path) -> None:
    with pytest.warns(UserWarning, match="a height unit 1000 times too small"):
        res = _analyze(tmp_path, "nm")
    assert not res.ok
    assert any("994 times shallower than the tip's cap" in d for d in res.doubts)
    assert not any("shallower than 0.1 um" in w for w in res.warnings)  # said by the doubt


def test_the_right_unit_is_ok(saved_example: Any) -> None:
    """The example read in um (conftest.py: its 12 um pixels, its geometry, an output folder)."""
    res = saved_example
    assert res.ok and not res.doubts
    assert res.dent is not None
    assert res.dent.delta_p.value == pytest.approx(22.02e-6, rel=1e-3)
    assert UNIT_DOUBT_RATIO < 994  # the nm reading's ratio, above the bound
