"""A sweep with ``friction = "partial_slip"`` (also beside other models on a friction axis)
stores its results, flags and statuses like the other models: the values of
``simulate_batch(friction="partial_slip")`` bit for bit."""

from __future__ import annotations

import numpy as np

import impactlab as il
from impactlab.sweep import Study, run_sweep
from impactlab.sweep.engine import EngineEvaluator

ANGLES = np.radians([10.0, 30.0, 60.0, 85.0])


def test_partial_slip_sweep_stores_batch_results(tmp_path) -> None:
    study = Study(
        name="slip",
        chunk_size=3,
        grid={"friction": ["mindlin", "partial_slip"], "angle": ANGLES},
        fixed={"mu": 0.3, "vy": -1.41, "law": "hertz"},
        outputs=["e", "spin_out", "sliding_length", "stick_time", "regime"],
    )
    ds = run_sweep(study, tmp_path / "slip.zarr", quiet=True).dataset
    assert ds["status"].values.tolist() == [[0] * 4, [0] * 4]
    assert "flags" in ds.data_vars
    want = il.simulate_batch(
        il.Rod.paper(), law="hertz", friction="partial_slip", mu=0.3, vy=-1.41, angle=ANGLES
    )
    got = ds.sel(friction="partial_slip")
    for name in ("e", "spin_out", "sliding_length", "stick_time", "flags"):
        np.testing.assert_array_equal(got[name].values, want[name].astype(got[name].dtype))
    np.testing.assert_array_equal(got["regime"].values, want["regime"].astype(np.int8))
    # partial slip differs from the point-contact Mindlin model, but not by much in e
    mind = ds.sel(friction="mindlin")
    assert not np.array_equal(mind["spin_out"].values, got["spin_out"].values)
    np.testing.assert_allclose(mind["e"].values, got["e"].values, rtol=0.05)


def test_flexible_rod_sweep_runs_partial_slip(tmp_path) -> None:
    """A flexible rod's drops with partial slip: the values of simulate_drops bit for bit."""
    angles = np.radians([20.0, 45.0])
    study = Study(
        name="slipflex",
        grid={"angle": angles},
        fixed={
            "body": "flexible_rod",
            "friction": "partial_slip",
            "law": "ghaednia",
            "mu": 0.3,
            "vy": -1.41,
        },
        outputs=["e", "dent_depth", "sequence_duration", "max_force"],
    )
    ds = run_sweep(study, tmp_path / "slipflex.zarr", quiet=True).dataset
    assert ds["status"].values.tolist() == [0, 0]
    want = il.simulate_drops(
        il.FlexibleRod.paper(),
        law="ghaednia",
        friction="partial_slip",
        mu=0.3,
        vy=-1.41,
        angle=angles,
    )
    for name in ("e", "dent_depth", "sequence_duration", "max_force", "flags"):
        np.testing.assert_array_equal(ds[name].values, getattr(want, name).astype(ds[name].dtype))
    EngineEvaluator().validate({"friction": ["partial_slip"], "body": ["rod", "flexible_rod"]})
