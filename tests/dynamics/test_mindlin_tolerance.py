"""Mindlin friction takes rtol up to MINDLIN_RTOL_MAX: up to it e follows the tolerance; beyond
it the stiff tangential spring outruns the steps (e = 0.61 for 0.49 at 10 deg, rtol 1e-3), and
the tolerance is refused by simulate (its fast path and its full one), simulate_batch,
run_arrays, a sweep and the command line alike; the other rigid models keep the whole range."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.input_checks import MINDLIN_RTOL_MAX, friction_rtol_max
from impactlab.sweep import Study, run_sweep

ROD = il.Rod.paper()
SHALLOW = {"angle": math.radians(10.33), "velocity": (0.0, -0.1136), "mu": 0.181, "law": "ghaednia"}
MESSAGE = r"rtol 0\.001 is too loose for friction 'mindlin' \(allowed: up to 0\.0001"


def test_up_to_the_cap_e_follows_the_tolerance() -> None:
    ref = il.simulate(ROD, friction="mindlin", rtol=1e-10, **SHALLOW)
    loose = il.simulate(ROD, friction="mindlin", rtol=MINDLIN_RTOL_MAX, **SHALLOW)
    assert ref.ok and loose.ok
    assert loose.e == pytest.approx(ref.e, rel=5e-3)


def test_a_looser_tolerance_is_refused_everywhere(tmp_path, cli_main) -> None:
    with pytest.raises(ValueError, match=MESSAGE):
        il.simulate(ROD, friction="mindlin", rtol=1e-3, **SHALLOW)  # the fast path's inputs
    with pytest.raises(ValueError, match=MESSAGE):
        il.simulate(
            ROD, friction="mindlin", rtol=1e-3, **(SHALLOW | {"velocity": np.array([0.0, -0.1136])})
        )  # the full path
    with pytest.raises(ValueError, match=MESSAGE):
        il.simulate_batch(ROD, angle=np.radians([5.0, 45.0]), vy=-1.41, mu=0.2,
                          friction="mindlin", rtol=1e-3)  # fmt: skip
    study = Study.from_dict({
        "fixed": {"vy": -1.41, "mu": 0.2},
        "grid": {"angle": ["5 deg", "45 deg"], "friction": ["coulomb", "mindlin"]},
        "engine": {"rtol": 1e-3},
    })  # fmt: skip
    with pytest.raises(ValueError, match=MESSAGE):
        run_sweep(study, tmp_path / "s.zarr", quiet=True)
    assert not (tmp_path / "s.zarr").exists()
    argv = ("simulate", "rod", "--friction", "mindlin", "--rtol", "1e-3", "--angle", "20 deg")
    code, _, err = cli_main(*argv, "--vy", "-1.41")
    assert code == 2 and "--rtol 0.001 is too loose for friction 'mindlin'" in err


@pytest.mark.parametrize("friction", ["impulse_ratio", "coulomb"])
def test_the_other_rigid_models_keep_the_whole_range(friction: str) -> None:
    assert friction_rtol_max(friction) == math.inf
    assert il.simulate(ROD, friction=friction, rtol=1e-3, **SHALLOW).ok
