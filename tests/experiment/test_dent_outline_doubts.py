"""A dent's outline joined by something else: a second mark touching or overlapping it, or a pit
(dust, a dropout) at its edge. The length was extrapolated across the join (8 mm in a 6.4 mm
scan; L_s 4.8 times the truth) or took the pit in (+9 %), as plain success."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab.experiment import measure_dent
from impactlab.experiment.profilometry import HeightMap
from impactlab.experiment.profilometry.extent import OUTLINE_DOUBT
from impactlab.experiment.profilometry.plausibility import dent_findings

R, DX = 8.8e-3, 8e-6
X, Y = np.meshgrid(np.arange(800) * DX, np.arange(300) * DX)
DENT_NPY = Path(__file__).resolve().parents[2] / "examples" / "data" / "dent.npy"


def _groove(cx: float, depth: float, ls: float) -> np.ndarray:
    """A sphere of radius R pressed ``depth`` [m] deep and dragged ``ls`` [m] along x."""
    u = X - cx
    r2 = (u - np.clip(u, -ls / 2, ls / 2)) ** 2 + (Y - Y.mean()) ** 2
    return np.minimum(-depth + R - np.sqrt(R * R - r2), 0.0)


def _noisy(z: np.ndarray) -> np.ndarray:
    return z + 0.1e-6 * np.random.default_rng(0).standard_normal(z.shape)


@pytest.mark.parametrize("second_at", [4.0e-3, 3.8e-3])
def test_a_second_mark_joined_to_the_dent_is_a_doubt(second_at: float) -> None:
    z = _noisy(np.minimum(_groove(1.8e-3, 22e-6, 1.4e-3), _groove(second_at, 15e-6, 0.8e-3)))
    dent = measure_dent(HeightMap(z, DX, DX))
    said = [w for w in dent.warnings if w.startswith(OUTLINE_DOUBT)]
    assert said, dent.warnings
    _, doubts = dent_findings(dent, (), tip_radius=R)
    assert said[0] in doubts  # not a result to take as measured


def test_a_lone_or_separate_dent_has_no_such_doubt() -> None:
    alone = measure_dent(HeightMap(_noisy(_groove(1.8e-3, 22e-6, 1.4e-3)), DX, DX))
    assert alone.sliding_length.value == pytest.approx(1.4e-3, rel=0.01)
    apart = _noisy(np.minimum(_groove(1.8e-3, 22e-6, 1.4e-3), _groove(4.4e-3, 15e-6, 0.8e-3)))
    dent = measure_dent(HeightMap(apart, DX, DX))
    assert any(w.startswith("2 depressions qualify") for w in dent.warnings)
    assert not [w for w in dent.warnings if w.startswith(OUTLINE_DOUBT)]
    assert dent.sliding_length.value == pytest.approx(1.4e-3, rel=0.01)


def test_a_pit_at_the_dents_end_stays_out_of_its_outline() -> None:
    """examples/data/dent.npy (L_s 1400 um) with one 3 x 3 pixel pit 10 um deep just past the
    dent's end: L_s 1532 um (+9 %, 5.6 sigma) before; the outline is drawn without pits now."""
    z = np.load(DENT_NPY).astype(float)
    clean = measure_dent(HeightMap(z * 1e-6, 12e-6, 12e-6))
    z[75:78, 24:27] -= 10.0
    pitted = measure_dent(HeightMap(z * 1e-6, 12e-6, 12e-6))
    ls, ls0 = pitted.sliding_length, clean.sliding_length
    assert abs(ls.value - ls0.value) <= 3 * ls0.sigma
    assert pitted.delta_p.value == pytest.approx(clean.delta_p.value, rel=1e-3)
