"""The engine's diagnostic outputs ``energy_rise`` and ``friction_excess`` in a sweep: computed
when kept (they were NaN), and the other outputs bit for bit those of a sweep without them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.sweep import Study, open_sweep, run_sweep


def _study(keep: list[str] | None) -> Study:
    """The paper's impulse-ratio friction at mu = 0.8 and 70 deg: an energy gain (flagged)."""
    return Study(
        name="diag",
        grid={"angle": np.radians([20.0, 70.0]), "mu": [0.2, 0.8]},
        fixed={"vy": -1.41, "friction": "impulse_ratio"},
        outputs=keep,
    )


@pytest.mark.usefixtures("engine")
def test_kept_diagnostics_are_computed_and_change_no_other_output(tmp_path) -> None:
    outputs = ["e", "energy_dissipated", "n_steps", "regime"]
    plain = open_sweep(run_sweep(_study(outputs), tmp_path / "a.zarr", quiet=True).path)
    diag = open_sweep(
        run_sweep(
            _study([*outputs, "energy_rise", "friction_excess"]), tmp_path / "b.zarr", quiet=True
        ).path
    )
    assert (diag["status"].values == 0).all()
    rise, excess = diag["energy_rise"].values, diag["friction_excess"].values
    assert np.isfinite(rise).all() and np.isfinite(excess).all()
    gain = diag["energy_dissipated"].values < 0  # energy created: the rise is positive there
    assert gain.any() and (rise[gain] > 0).all()
    assert (diag["flags"].values[gain] & 1).all()  # flagged energy gain
    for name in [*outputs, "flags", "status"]:
        assert np.array_equal(plain[name].values, diag[name].values, equal_nan=True), name


@pytest.mark.usefixtures("engine")
def test_a_sweep_that_keeps_every_output_has_its_diagnostics(tmp_path) -> None:
    ds = open_sweep(run_sweep(_study(None), tmp_path / "all.zarr", quiet=True).path)
    assert not math.isnan(float(ds["energy_rise"].values[1, 1]))
    assert np.isfinite(ds["friction_excess"].values).all()
