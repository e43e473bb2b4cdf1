"""A round dent (no sliding) measured with its noise: L_s within about 1.6 sigma of zero, on which
the inversion's T rests, is not resolved: the Monte Carlo discards the samples that draw
L_s <= 0, and the analysis is not ok (a doubt naming them) instead of a T clear of zero."""

from __future__ import annotations

import math
from pathlib import Path

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, analyze


def test_a_round_dent_leaves_t_unresolved(tmp_path: Path) -> None:
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(20), (0.0, -1.41), e=0.5, mu=0.2)
    tracks, _ = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=3)
    S.write_c3d(tracks, tmp_path / "drop.c3d")
    z, dx, dy, _ = S.synthetic_scan(delta_p=22e-6, sliding_length=0.0, seed=2)
    S.write_scan(z, dx, dy, tmp_path / "dent.x3p")
    geometry = MarkerGeometry(S.DEFAULT_MARKERS, ("M1", "M2", "M3"))
    res = analyze(tmp_path / "drop.c3d", tmp_path / "dent.x3p", PAPER_ROD, geometry=geometry,
                  n_samples=4000)  # fmt: skip
    assert res.dent is not None and res.inversion is not None, res.errors
    ls = res.dent.sliding_length
    assert abs(ls.value) < 2.0 * ls.sigma  # consistent with zero
    assert not res.ok
    assert any("drew |sliding_length| <= 0" in d for d in res.doubts), res.doubts
