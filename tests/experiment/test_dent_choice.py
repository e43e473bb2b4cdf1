"""Which depression is the dent: a 3 x 3-pixel pit 40 um deep beside the real dent was taken for
it (the 25-pixel dust rule counted the smoothed pit, spread over more pixels), and the scan was
then refused as an impossible dent for the rod."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import DentNotFoundError, HeightMap, analyze, measure_dent


@pytest.fixture(scope="module")
def groove() -> tuple[np.ndarray, float, S.ScanTruth]:
    z, dx, _, truth = S.synthetic_scan(delta_p=22e-6, sliding_length=1400e-6, seed=1)
    return z, dx, truth


def test_a_small_deep_pit_is_dust_not_the_dent(
    tmp_path: Path, groove: tuple[np.ndarray, float, S.ScanTruth]
) -> None:
    z, dx, truth = groove
    pitted = z.copy()
    pitted[30:33, 30:33] -= 40e-6
    d = measure_dent(HeightMap(pitted, dx, dx))
    assert d.delta_p.value == pytest.approx(truth.groove.depth, rel=0.02)
    assert d.sliding_length.value == pytest.approx(truth.groove.sliding_length, rel=0.05)
    assert not any("qualify as a dent" in w for w in d.warnings)
    np.save(tmp_path / "pit.npy", pitted)
    res = analyze(None, tmp_path / "pit.npy", pixel_size=dx, height_unit="m", figures=False)
    assert not res.errors and res.dent is not None


def test_a_lone_pit_is_counted_on_the_unsmoothed_scan() -> None:
    rng = np.random.default_rng(2)
    z = rng.normal(0.0, 0.1e-6, (120, 140))
    z[60:63, 70:73] -= 40e-6
    with pytest.raises(DentNotFoundError, match=r"cover at most (9|1\d) pixels \(need 25\)"):
        measure_dent(HeightMap(z, 8e-6, 8e-6))


def test_two_candidates_measure_the_largest_and_name_both(
    groove: tuple[np.ndarray, float, S.ScanTruth],
) -> None:
    """A 12 x 12-pixel pit 40 um deep (deeper than the dent): the dent, of the
    larger volume, is measured, and a warning says where each is."""
    z, dx, truth = groove
    pitted = z.copy()
    pitted[40:52, 40:52] -= 40e-6
    d = measure_dent(HeightMap(pitted, dx, dx))
    assert d.delta_p.value == pytest.approx(truth.groove.depth, rel=0.02)
    (note,) = [w for w in d.warnings if "qualify as a dent" in w]
    assert note.startswith("2 depressions qualify as a dent (at x = ")
    measured, other = note.split("; at ")[:2]
    assert "22 um deep" in measured and "(measured)" in measured
    assert re.match(r"x = 0\.3\d* mm, y = 0\.3\d* mm: 40 um deep, 1\d\d pixels\)", other)
    assert "crop the scan" in note


def test_the_papers_dents_have_one_candidate(scans: dict) -> None:
    for sc in scans.values():
        d = measure_dent(HeightMap(sc.z, sc.dx, sc.dx))
        assert not any("qualify as a dent" in w for w in d.warnings)


def test_the_old_name_of_delta_p_still_works_with_a_deprecation_warning() -> None:
    with pytest.warns(DeprecationWarning, match="'depth' is renamed 'delta_p'"):
        old = S.synthetic_scan(depth=10e-6, sliding_length=300e-6, pixel=10e-6, seed=2)
    new = S.synthetic_scan(delta_p=10e-6, sliding_length=300e-6, pixel=10e-6, seed=2)
    np.testing.assert_array_equal(old[0], new[0])
    assert old[3].groove.depth == new[3].groove.depth == pytest.approx(10e-6, rel=1e-9)
