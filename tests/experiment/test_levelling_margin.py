"""Too little undeformed surface around the dent for the levelling plane: a warning with the
reason and what to do (delta_p came out 2 % deep, 4 sigma, in silence); a plane that fails
altogether says so instead of "no dent found"; a constant scan is named flat. Scans with enough
margin are unchanged."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import DentNotFoundError, HeightMap, measure_dent
from impactlab.experiment.profilometry.levelling import level_plane, pixel_noise

DENT = Path(__file__).resolve().parents[2] / "examples" / "data" / "dent.npy"


def _synthetic(margin: float) -> HeightMap:
    z, dx, dy, _ = S.synthetic_scan(margin=margin, seed=1, direction=0.0, pixel=12e-6)
    return HeightMap(z, dx, dy, source="synthetic")


def _cropped(pixels: int) -> HeightMap:
    z = np.load(DENT)[pixels:-pixels, pixels:-pixels] * 1e-6
    return HeightMap(z, 12e-6, 12e-6, source="cropped.npy")


def test_the_pixel_noise_is_the_white_noise() -> None:
    rng = np.random.default_rng(3)
    x, y = np.arange(200) * 1e-5, np.arange(150) * 1e-5
    z = 1e-3 * x[None, :] + 2e-4 * y[:, None] + rng.normal(0.0, 1e-7, (150, 200))
    assert pixel_noise(z) == pytest.approx(1e-7, rel=0.05)
    assert level_plane(HeightMap(z, 1e-5, 1e-5)).pixel_sigma == pytest.approx(1e-7, rel=0.05)


@pytest.mark.parametrize("margin", [0.06e-3, 0.02e-3])
def test_a_narrow_margin_draws_a_warning(margin: float) -> None:
    d = measure_dent(_synthetic(margin))
    (note,) = [w for w in d.warnings if w.startswith("the levelling is in doubt")]
    assert "too little undeformed surface around the dent" in note
    assert "scan a larger area around the dent" in note


@pytest.mark.parametrize("hm", [_synthetic(0.3e-3), _synthetic(0.07e-3)])
def test_enough_margin_draws_none(hm: HeightMap) -> None:
    assert not any("levelling" in w for w in measure_dent(hm).warnings)


def test_the_example_is_unchanged() -> None:
    d = measure_dent(HeightMap(np.load(DENT) * 1e-6, 12e-6, 12e-6))
    assert d.delta_p.value == pytest.approx(22.0156e-6, abs=1e-10) and not d.warnings


def test_a_failed_levelling_is_not_called_no_dent() -> None:
    """'no dent found: the deepest point is 14.7 um below the levelled surface, less than the
    detection threshold 8 x noise = 56.1 um', for a 22 um deep dent filling the scan."""
    with pytest.raises(DentNotFoundError, match="no dent found: the levelling failed: ") as e:
        measure_dent(_cropped(30))
    assert "times the pixel-to-pixel noise" in str(e.value)
    assert "scan a larger area around the dent" in str(e.value)


def test_a_constant_scan_is_flat() -> None:
    with pytest.raises(DentNotFoundError, match=r"the scan is flat \(every height the same"):
        measure_dent(HeightMap(np.zeros((60, 80)), 12e-6, 12e-6))
