"""A dent whose edge (its width's or length's crossing, extrapolated to zero depth) lies in
pixels without data that reach the scan's edge runs into a region without data: refused, not
measured with the fill's flat slope (L_s = 1433 +- 31466 um); an uncertainty larger than the
quantity draws a warning, except L_s near 0 (a round dent, no sliding) whose uncertainty is
small against the width."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import DentCutOffError, measure_dent
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.metrics import sliding_length_note, unmeasured_notes

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


def test_an_unmeasured_sliding_length_is_named_against_the_width() -> None:
    (note,) = sliding_length_note(1.7e-6, 150e-6, 1.2e-3)
    assert note.startswith("sliding_length = 1.7 um has an uncertainty of 150 um, larger than")
    assert "10% of the width (1200 um)" in note
    assert sliding_length_note(1.7e-6, 2.5e-6, 1.2e-3) == []
    assert sliding_length_note(1433e-6, 31466e-6, 1.27e-3) != []


@pytest.mark.parametrize("seed", range(4))
def test_a_round_dent_has_a_measured_sliding_length_near_zero(seed: int) -> None:
    """'sliding_length = 1.686 um has an uncertainty of 2.52 um, larger than itself: it is not
    measured' for every round dent: L_s = 1.7 +- 2.5 um is a measurement of no sliding."""
    z, dx, dy, _ = S.synthetic_scan(sliding_length=0.0, margin=0.5e-3, seed=seed, pixel=8e-6)
    d = measure_dent(HeightMap(z, dx, dy, f"round{seed}"))
    assert abs(d.sliding_length.value) < 3.0 * d.sliding_length.sigma
    assert d.sliding_length.sigma < 10e-6
    assert not d.warnings
