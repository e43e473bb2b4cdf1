"""The rigid partial-slip engine takes rtol up to PARTIAL_SLIP_RTOL_MAX: up to it the results
follow the tolerance; beyond it the cells' events outrun the steps (e 11 % off at 3e-4) and the
tolerance is refused, by simulate, simulate_batch and a sweep alike."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.input_checks import PARTIAL_SLIP_RTOL_MAX
from impactlab.sweep import Study, run_sweep

ROD = il.Rod.paper()
CASE = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}


def test_up_to_the_bound_the_results_follow_the_tolerance() -> None:
    ref = il.simulate(ROD, friction="partial_slip", rtol=1e-10, **CASE)
    loose = il.simulate(ROD, friction="partial_slip", rtol=PARTIAL_SLIP_RTOL_MAX, **CASE)
    assert loose.e == pytest.approx(ref.e, rel=1e-3)
    assert loose.e_energy == pytest.approx(ref.e_energy, rel=1e-3)


def test_a_looser_tolerance_is_refused_everywhere(tmp_path) -> None:
    message = r"rtol 0.0003 is too loose for friction 'partial_slip' \(allowed: up to 1e-05"
    with pytest.raises(ValueError, match=message):
        il.simulate(ROD, friction="partial_slip", rtol=3e-4, **CASE)
    with pytest.raises(ValueError, match=message):
        il.simulate_batch(ROD, angle=np.radians([20.0, 45.0]), vy=-1.41, mu=0.2,
                          friction="partial_slip", rtol=3e-4)  # fmt: skip
    study = Study.from_dict({
        "fixed": {"vy": -1.41, "mu": 0.2, "friction": "partial_slip"},
        "grid": {"angle": ["20 deg", "45 deg"]},
        "engine": {"rtol": 3e-4},
    })  # fmt: skip
    with pytest.raises(ValueError, match=message):
        run_sweep(study, tmp_path / "s.zarr", quiet=True)
    assert not (tmp_path / "s.zarr").exists()
    # the other models keep the whole range
    assert il.simulate(ROD, friction="coulomb", rtol=3e-4, **CASE).ok
