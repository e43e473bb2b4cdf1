"""A scan format that SurfaceTopography reads without a physical size (a NumPy .npz archive)
takes the pixel size as given, whatever the height unit: the sizes were handed to it in m with
the heights' unit, and came out a factor of that unit too small (12 um as 1.2e-11 m in um)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import HeightMap, measure_dent, read_scan


@pytest.mark.parametrize("unit", ["m", "mm", "um", "nm"])
def test_the_pixel_size_is_the_one_given(tmp_path: Path, unit: str) -> None:
    z, dx, _, _ = S.synthetic_scan(delta_p=22e-6, sliding_length=400e-6, pixel=10e-6, seed=1)
    path = tmp_path / "scan.npz"
    factor = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}[unit]
    np.savez(path, z=z / factor)
    scan = read_scan(path, pixel_size="10 um", height_unit=unit)
    assert scan.dx == pytest.approx(10e-6, rel=1e-12)
    assert scan.dy == pytest.approx(10e-6, rel=1e-12)
    same = measure_dent(HeightMap(z, dx, dx))
    dent = measure_dent(scan)
    assert dent.sliding_length.value == pytest.approx(same.sliding_length.value, rel=1e-6)
    assert dent.delta_p.value == pytest.approx(same.delta_p.value, rel=1e-6)
