"""``analyze``'s unit arguments are checked before any work, as its other arguments are: a
unit that is not a length, or one no measurement file is written in, is a ValueError naming
the argument and its option, and nothing is written."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.experiment import analyze

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"marker_units": "kg"}, r"marker_units \(--marker-units\): 'kg' is not a length unit"),
        ({"height_unit": "kg"}, r"height_unit \(--height-unit\): 'kg' is not a length unit"),
        ({"height_unit": "ly"}, r"height_unit \(--height-unit\): 'ly' is 9\.46073e\+15 m, outside"),
        ({"marker_units": "km"}, r"marker_units \(--marker-units\): 'km' is 1000 m, outside"),
    ],
)
def test_a_bad_unit_is_refused_before_anything_is_written(
    tmp_path: Path, kwargs: dict[str, str], message: str
) -> None:
    out = tmp_path / "out"
    with pytest.raises(ValueError, match=message):
        analyze(DATA / "drop.csv", DATA / "dent.npy", PAPER_ROD, pixel_size="12 um",
                out_dir=out, **kwargs)  # fmt: skip
    assert not out.exists()
