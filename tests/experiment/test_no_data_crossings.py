"""A dent whose edge (its width's or length's crossing, extrapolated to zero depth) lies in
pixels without data that reach the scan's edge runs into a region without data: refused, not
measured with the fill's flat slope (L_s = 1433 +- 31466 um); an uncertainty larger than the
quantity always draws a warning."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab.experiment import DentCutOffError, measure_dent
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.metrics import unmeasured_notes

DENT = Path(__file__).resolve().parents[2] / "examples" / "data" / "dent.npy"


def _framed(pixels: int) -> HeightMap:
    """The example's scan (heights in um, 12 um pixels) with a no-data frame ``pixels`` wide."""
    z = np.load(DENT) * 1e-6
    if pixels:
        z[:pixels], z[-pixels:], z[:, :pixels], z[:, -pixels:] = (np.nan,) * 4
    return HeightMap(z, 12e-6, 12e-6, "framed.npy")


def test_an_edge_in_a_no_data_frame_is_refused() -> None:
    with pytest.raises(DentCutOffError, match="the dent runs into a region without data") as e:
        measure_dent(_framed(25))
    assert "width" in str(e.value) and "scan the dent again with data all around it" in str(e.value)


def test_a_frame_clear_of_the_dent_changes_nothing() -> None:
    plain, framed = measure_dent(_framed(0)), measure_dent(_framed(15))
    assert framed.sliding_length.value == pytest.approx(plain.sliding_length.value, abs=2e-6)
    assert framed.sliding_length.sigma < 2.0 * plain.sliding_length.sigma
    assert not framed.warnings


def test_an_uncertainty_above_the_value_is_named() -> None:
    (note,) = unmeasured_notes(width=(1.2656e-3, 31.47e-3), length=(2.7e-3, 1e-5))
    assert note.startswith("width = 1266 um has an uncertainty of 3.15e+04 um, larger than")
    assert unmeasured_notes(delta_p=(22e-6, 2.7e-8)) == []
