"""delta_r of an FE run is the smallest gap between the withdrawn sphere and the dent; where
the surfaces still touch at the end although the dent at the axis is deeper than
UNRESOLVED_DENT delta_max, it is below the contact's resolution and nan (the paper's pair at
1.5 delta_c, shipped so), never 0."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

import impactlab.fe
from impactlab.fe.run import UNRESOLVED_DENT, residual_depth

DMAX = 6.5e-7


def test_a_gap_is_delta_r() -> None:
    assert residual_depth(np.array([4.8e-8, 5e-8, 1e-6]), np.array([-4.8e-8, 0.0]), DMAX) == 4.8e-8


def test_touching_surfaces_over_a_real_dent_leave_delta_r_unresolved() -> None:
    dent = np.array([-6.27e-9, -7.6e-9, 1.7e-8])
    assert math.isnan(residual_depth(np.array([0.0, 2e-9]), dent, DMAX))
    assert math.isnan(residual_depth(np.array([-1e-10, 2e-9]), dent, DMAX))


def test_touching_surfaces_without_a_dent_give_zero() -> None:
    flat = np.array([4.5e-11, -8e-12, 0.0])  # elastic: the surface back where it was
    assert residual_depth(np.array([-4.5e-11, 1e-9]), flat, DMAX) == 0.0
    assert residual_depth(np.array([0.0]), np.array([-0.5 * UNRESOLVED_DENT * DMAX]), DMAX) == 0.0


def test_the_shipped_run_at_one_and_a_half_delta_c_is_unresolved() -> None:
    data = Path(impactlab.fe.__file__).parent / "data" / "paper-aisi201-on-aisi1010.v1.json"
    runs = json.loads(data.read_text())["runs"]
    run = next(r for r in runs if r["delta_max_over_delta_c"] == 1.5)
    assert run["residual_depth"] is None and run["residual_ratio"] is None
    assert -run["dent"]["z"][0] > UNRESOLVED_DENT * run["delta_max"]  # 6.3 nm deep
    assert min(run["unloading"]["force"]) < -0.3  # the sphere held in tension at delta = 0
