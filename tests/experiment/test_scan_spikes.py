"""A spike (one pixel far below its neighbours: dust, a dropout on a steep flank) inside the
dent is neither its deepest point nor part of its bottom's fit: delta_p and L_s come out as on
the clean scan, and a warning names the spike when it was the deepest pixel."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import HeightMap, measure_dent

Z, DX, _, _ = S.synthetic_scan(delta_p=22e-6, sliding_length=400e-6, pixel=10e-6, seed=1,
                               dropouts=0.0)  # fmt: skip
CLEAN = measure_dent(HeightMap(Z, DX, DX))
I0, J0 = np.unravel_index(int(np.nanargmin(Z)), Z.shape)


@pytest.mark.parametrize("offset", [(0, 0), (3, -2), (6, 8), (-10, 14)])
@pytest.mark.parametrize("depth", [-60e-6, -200e-6])
def test_a_spike_moves_neither_delta_p_nor_the_sliding_length(
    offset: tuple[int, int], depth: float
) -> None:
    z = Z.copy()
    z[I0 + offset[0], J0 + offset[1]] = depth
    dent = measure_dent(HeightMap(z, DX, DX))
    assert abs(dent.delta_p.value - CLEAN.delta_p.value) <= 3 * CLEAN.delta_p.sigma
    ls, ls0 = dent.sliding_length, CLEAN.sliding_length
    assert abs(ls.value - ls0.value) <= 3 * max(ls0.sigma, DX)
    assert any("a spike at x = " in w and "the bottom is taken at" in w for w in dent.warnings)


def test_a_clean_scan_has_no_spike_warning() -> None:
    assert not any("spike" in w for w in CLEAN.warnings)
