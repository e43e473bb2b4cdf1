"""Too little undeformed surface around the dent for the levelling plane: a warning with the
reason and what to do (delta_p came out 2 % deep, 4 sigma, in silence); a plane that fails
altogether says so instead of "no dent found"; a constant scan is named flat. Scans with enough
margin are unchanged, whether their noise is white or correlated over a few pixels (an optical
profilometer sampling finer than its lateral resolution), and a flat scan without a dent is
plainly "no dent found"."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy import ndimage

from impactlab import testing as S
from impactlab.experiment import DentNotFoundError, HeightMap, measure_dent
from impactlab.experiment.profilometry.levelling import lagged_noise, level_plane

DENT = Path(__file__).resolve().parents[2] / "examples" / "data" / "dent.npy"


def _synthetic(margin: float) -> HeightMap:
    z, dx, dy, _ = S.synthetic_scan(margin=margin, seed=1, direction=0.0, pixel=12e-6)
    return HeightMap(z, dx, dy, source="synthetic")


def _cropped(pixels: int) -> HeightMap:
    z = np.load(DENT)[pixels:-pixels, pixels:-pixels] * 1e-6
    return HeightMap(z, 12e-6, 12e-6, source="cropped.npy")


def _noise(shape: tuple[int, int], smooth: float, seed: int) -> np.ndarray:
    """Noise of 0.1 um standard deviation, Gaussian-correlated over ``smooth`` pixels."""
    n = np.random.default_rng(seed).normal(0.0, 1.0, shape)
    if smooth:
        n = ndimage.gaussian_filter(n, smooth)
    return 1e-7 * n / n.std()


@pytest.mark.parametrize("smooth", [0.0, 1.0, 2.0])
def test_the_lagged_noise_is_the_noise_white_or_correlated(smooth: float) -> None:
    x, y = np.arange(200) * 1e-5, np.arange(150) * 1e-5
    z = 1e-3 * x[None, :] + 2e-4 * y[:, None] + _noise((150, 200), smooth, 3)
    assert lagged_noise(z) == pytest.approx(1e-7, rel=0.08)
    with pytest.raises(ValueError, match="lag must be a whole number of pixels >= 1, got 0"):
        lagged_noise(z, lag=0)
    assert level_plane(HeightMap(z, 1e-5, 1e-5)).lag_sigma == pytest.approx(1e-7, rel=0.08)


@pytest.mark.parametrize("smooth", [0.0, 1.0, 2.0])
def test_correlated_noise_with_ample_margin_draws_no_warning(smooth: float) -> None:
    """Second differences of neighbours saw 1/3 (1 pixel) and 1/11 (2 pixels) of such noise:
    'the levelling is in doubt: ... 3.33 times the scan's pixel-to-pixel noise'."""
    z, dx, dy, truth = S.synthetic_scan(
        margin=0.8e-3, seed=1, direction=0.0, pixel=8e-6, noise=0.0, dropouts=0.0
    )
    d = measure_dent(HeightMap(z + _noise(z.shape, smooth, 0), dx, dy, source="correlated"))
    assert not d.warnings
    assert d.delta_p.value == pytest.approx(truth.groove.depth, abs=3.0 * d.delta_p.sigma + 0.1e-6)


@pytest.mark.parametrize("smooth", [0.0, 1.0, 2.0])
def test_a_flat_scan_without_a_dent_is_no_dent(smooth: float) -> None:
    hm = HeightMap(_noise((200, 250), smooth, 0), 8e-6, 8e-6, source="flat.npy")
    with pytest.raises(DentNotFoundError, match="no dent found: the deepest point is ") as e:
        measure_dent(hm)
    assert "levelling" not in str(e.value)


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
    assert "times the inliers' lagged noise" in str(e.value)
    assert "scan a larger area around the dent" in str(e.value)


def test_a_constant_scan_is_flat() -> None:
    with pytest.raises(DentNotFoundError, match=r"the scan is flat \(every height the same"):
        measure_dent(HeightMap(np.zeros((60, 80)), 12e-6, 12e-6))
