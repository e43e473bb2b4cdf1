"""A scan read with a pixel size too small gives a dent narrower than the tip could make at its
depth: the analysis is not ok (a doubt), so that it is not taken as a measurement (a 6 um pixel
for the example's 12 um gave L_s = 703 um, T = 2.06 ms and an ok result); the right pixel size is
ok, and the example dent itself sits at its tip's cap."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, analyze
from impactlab.experiment.profilometry.plausibility import NARROW_DOUBT_RATIO

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


def _analyze(tmp_path: Path, pixel: str):
    geometry = MarkerGeometry.from_mapping(
        {"units": "mm", "M1": [-30, 18, 0], "M2": [-90, 0, 22], "M3": [-130, -20, 4]}
    )
    out = tmp_path / pixel.replace(" ", "")
    return analyze(DATA / "drop.csv", DATA / "dent.npy", PAPER_ROD, geometry=geometry, up="+y",
                   pixel_size=pixel, height_unit="um", out_dir=out)  # fmt: skip


@pytest.mark.parametrize("pixel", ["6 um", "8 um"])
def test_a_pixel_size_too_small_is_not_ok(tmp_path: Path, pixel: str) -> None:
    with pytest.warns(UserWarning, match="a residual dent is never deeper"):
        res = _analyze(tmp_path, pixel)
    assert not res.ok
    doubt = next(d for d in res.doubts if "a residual dent is never deeper" in d)
    assert doubt.startswith("scan: delta_p = 22.0")
    assert "check the pixel size" in doubt


def test_the_right_pixel_size_is_ok(saved_example: Any) -> None:
    """The example on its 12 um pixels (conftest.py: heights in um, its geometry, an output
    folder)."""
    res = saved_example
    assert res.ok and not res.doubts
    assert NARROW_DOUBT_RATIO >= 2.0  # the example dent: 1.0 times its tip's cap


def test_a_levelling_in_doubt_is_not_ok(tmp_path: Path) -> None:
    """The example dent on a domed specimen (radius 0.2 m, 8.7 um sag at the scan's corners)
    gave delta_p 5 sigma off and L_s 35 % short, ok and appended to a calibration file; its
    warning said the bias lay beyond the +-. It is a doubt now."""
    import numpy as np

    z = np.load(DATA / "dent.npy").astype(np.float64)  # um on 12 um pixels
    ny, nx = z.shape
    y, x = np.mgrid[0:ny, 0:nx] * 12e-6
    z += ((x - x.mean()) ** 2 + (y - y.mean()) ** 2) / (2 * 0.2) * 1e6
    np.save(tmp_path / "domed.npy", z)
    geometry = MarkerGeometry.from_mapping(
        {"units": "mm", "M1": [-30, 18, 0], "M2": [-90, 0, 22], "M3": [-130, -20, 4]}
    )
    with pytest.warns(UserWarning, match="the levelling is in doubt"):
        res = analyze(DATA / "drop.csv", tmp_path / "domed.npy", PAPER_ROD, geometry=geometry,
                      up="+y", pixel_size="12 um", height_unit="um",
                      out_dir=tmp_path / "o")  # fmt: skip
    assert not res.ok
    assert any(d.startswith("scan: the levelling is in doubt") for d in res.doubts)
