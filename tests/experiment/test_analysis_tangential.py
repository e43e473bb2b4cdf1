"""``analyze`` passes the tip's measured incoming tangential velocity to the inversion (``vt_in``):
a drop with a horizontal velocity inverts to the engine's duration, as one without."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, analyze
from impactlab.materials import AISI_1010


def test_analyze_inverts_a_drop_that_moves_along_the_flat(tmp_path: Path) -> None:
    truth = S.engine_impact(PAPER_ROD, AISI_1010, math.radians(45), (-0.3, -2.18), mu=0.13)
    tracks, info = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=1)
    c3d = S.write_c3d(tracks, tmp_path / "drop.c3d")
    z, dx, _, _ = S.synthetic_scan(
        delta_p=truth.delta_p,
        sliding_length=abs(truth.sliding_length),
        noise=0.05e-6,
        seed=1,
        pileup=0.2e-6,
    )
    scan = S.write_scan(z, dx, dx, tmp_path / "dent.x3p", fmt="x3p")
    res = analyze(c3d, scan, PAPER_ROD, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))
    assert res.errors == {}
    vt = res.kinematics.v_tip_in[0]
    assert vt.value == pytest.approx(-0.3, abs=4 * vt.sigma)
    assert res.inversion.inputs["vt_in"] == (vt.value, vt.sigma)
    # 0.1770 ms (+24 %) without vt_in; within 1 % (its sigma) with it
    assert res.inversion.duration == pytest.approx(truth.duration, rel=0.01)
    assert abs(res.inversion.duration - truth.duration) < 2 * res.inversion.sigma_T_linear
