"""Pixels without data next to the dent: the outline through a gap widens the ± of L_s (never a
silent shift of many sigma), and a gap can neither make a dent nor pass for the scan's edge."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import DentCutOffError, measure_dent
from impactlab.experiment.profilometry.heightmap import HeightMap


@pytest.fixture(scope="module")
def scan() -> tuple[np.ndarray, float, float]:
    """The 20 deg dent (delta_p 22 um, L_s 1400 um; 8 um pixels, its start at x = 1.04 mm,
    y = 1.4 mm) and the true L_s [m]."""
    z, dx, _, truth = S.synthetic_scan(delta_p=22e-6, sliding_length=1400e-6, seed=1)
    return z, dx, truth.groove.sliding_length


def _disc(z: np.ndarray, dx: float, centre: tuple[float, float], radius: float) -> np.ndarray:
    ny, nx = z.shape
    x, y = np.meshgrid(np.arange(nx) * dx, np.arange(ny) * dx)
    out = z.copy()
    out[(x - centre[0]) ** 2 + (y - centre[1]) ** 2 < radius**2] = np.nan
    return out


def test_a_clean_scan_has_no_gap_warning(scan: tuple[np.ndarray, float, float]) -> None:
    z, dx, truth = scan
    d = measure_dent(HeightMap(z, dx, dx, "clean"))
    assert not any("without data" in w for w in d.warnings)
    assert abs(d.sliding_length.value - truth) < 3 * d.sliding_length.sigma < 40e-6


@pytest.mark.parametrize(
    ("centre", "radius"),
    [((1.0363e-3, 1.4e-3), 100e-6), ((1.0363e-3, 1.4e-3), 50e-6), ((3.4814e-3, 2.296e-3), 150e-6)],
)
def test_a_gap_at_an_end_of_the_dent_widens_the_uncertainty(
    scan: tuple[np.ndarray, float, float], centre: tuple[float, float], radius: float
) -> None:
    """A 100 um disc without data at the dent's start gave L_s 1365.0 ± 3.7 um against 1400
    (9 sigma, and silent); now the ± covers it and a warning names the gap."""
    z, dx, truth = scan
    d = measure_dent(HeightMap(_disc(z, dx, centre, radius), dx, dx, "gap"))
    ls = d.sliding_length
    assert abs(ls.value - truth) < 2 * ls.sigma
    (note,) = [w for w in d.warnings if "pixels without data" in w]
    x = float(note.split("around x = ")[1].split(" mm")[0])
    assert abs(x - centre[0] * 1e3) < 0.01 and "L_s: ±" in note
    assert d.length.sigma > 2 * radius / math.sqrt(12) * 0.5


def test_a_band_without_data_beside_the_dent_makes_no_depression(
    scan: tuple[np.ndarray, float, float],
) -> None:
    """The filled band 70 um past the dent's end made a second 'depression' at x = 4.4 mm."""
    z, dx, truth = scan
    band = z.copy()
    band[:, int(3.55e-3 / dx) :] = np.nan
    d = measure_dent(HeightMap(band, dx, dx, "band"))
    assert not any("depressions qualify" in w for w in d.warnings), d.warnings
    assert abs(d.sliding_length.value - truth) < 3 * d.sliding_length.sigma


def test_a_dent_running_into_a_region_without_data_says_so(
    scan: tuple[np.ndarray, float, float],
) -> None:
    """The band over the dent's end was reported as the scan's right, bottom and top edges."""
    z, dx, _ = scan
    band = z.copy()
    band[:, int(3.3e-3 / dx) :] = np.nan
    with pytest.raises(DentCutOffError, match="runs into a region without data") as info:
        measure_dent(HeightMap(band, dx, dx, "band"))
    text = str(info.value)
    assert "x = 3.296 to" in text and "edge:" not in text and "bottom" not in text


def test_a_dent_cut_off_by_the_scan_edge_is_still_named_so(
    scan: tuple[np.ndarray, float, float],
) -> None:
    z, dx, _ = scan
    with pytest.raises(DentCutOffError, match=r"cut off by the scan's right \(x max\) edge"):
        measure_dent(HeightMap(z[:, : int(3.3e-3 / dx)], dx, dx, "cut"))
