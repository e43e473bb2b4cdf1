"""An unknown material or body of a drop is refused with the nearest known name, as every
other unknown name of the measurements is."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab.calibrate import Measurements, read_measurements

DROP = {"label": "a", "angle": "20 deg", "vy": -1.41, "e": 0.45, "e_sigma": 0.02}


def test_unknown_flat_material_in_a_file_names_the_nearest(tmp_path: Path) -> None:
    path = tmp_path / "badmat.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],flat_material,e,e_sigma\na,20,-1.41,aisi1010,0.45,0.02\n"
    )
    with pytest.raises(ValueError, match=(
        r"badmat.csv: line 2: drop 1: unknown flat_material 'aisi1010' \(did you mean "
        r"'aisi-1010'\?\); known: aisi-201, aisi-1010"
    )):  # fmt: skip
        read_measurements(path)


@pytest.mark.parametrize(
    ("column", "value", "near"),
    [("body_material", "AL-6061-T6", "al-6061-t6"), ("body", "Rod", "rod")],
)
def test_unknown_category_names_the_nearest(column: str, value: str, near: str) -> None:
    with pytest.raises(
        ValueError, match=rf"unknown {column} '{value}' \(did you mean '{near}'\?\)"
    ):
        Measurements.from_records([{**DROP, column: value}])


def test_a_name_far_from_any_gets_no_suggestion() -> None:
    with pytest.raises(ValueError, match=r"unknown flat_material 'unobtainium'; known: ") as info:
        Measurements.from_records([{**DROP, "flat_material": "unobtainium"}])
    assert "did you mean" not in str(info.value)
