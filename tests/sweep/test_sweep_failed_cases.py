"""A case with status != 0 has no result in the store: every output NaN, -1 for the integer
outputs (``regime``, ``n_steps``, ``flags``), whatever the engine or evaluator left in them
(impactlab.sweep.store.SweepStore.write_chunk)."""

from __future__ import annotations

import numpy as np
from sweep_fakes import VY_LIMIT, FakeEvaluator

from impactlab.sweep import Study, run_sweep


class ValuesOnFailedCases(FakeEvaluator):
    """The fake engine, but with numbers left in the outputs of its failed cases (as an engine
    stopped mid-integration leaves its duration, forces and regime)."""

    def __call__(self, cases, statics, outputs):
        res, status = super().__call__(cases, statics, outputs)
        return {o: np.where(np.isnan(v), 7.0, v) for o, v in res.items()}, status


def _no_result_where_failed(ds) -> None:
    failed = ds["status"].values != 0
    assert failed.any() and (~failed).any()
    for name in ds.data_vars:
        if name == "status":
            continue
        values = ds[name].values
        if values.dtype.kind == "f":
            assert np.isnan(values[failed]).all(), name
        else:
            assert (values[failed] == -1).all(), name


def test_rigid_and_partial_slip_failures_store_no_result(tmp_path, engine) -> None:
    """A rod at 90 deg hit at 50 m/s exceeds the law's validity (status 1) in both the rigid
    and the partial-slip engines: its stopped integration is not a result."""
    study = Study(
        name="failed",
        chunk_size=4,
        grid={"friction": ["coulomb", "partial_slip"], "vy": [-50.0, -1.41]},
        fixed={"mu": 0.2, "angle": float(np.radians(90.0))},
        outputs=["e", "duration", "delta_max", "max_force", "t_max", "n_steps", "regime"],
    )
    ds = run_sweep(study, tmp_path / "failed.zarr", evaluator=engine, quiet=True).dataset.load()
    status = ds["status"].transpose("friction", "vy").values
    assert (status[:, 0] == 1).all() and (status[:, 1] == 0).all()
    _no_result_where_failed(ds)
    assert np.isfinite(ds["duration"].sel(vy=-1.41).values).all()


def test_numbers_an_evaluator_leaves_on_failed_cases_are_not_stored(tmp_path) -> None:
    study = Study(
        name="leaky",
        chunk_size=2,
        grid={"vy": [-1.0, VY_LIMIT - 1.0, VY_LIMIT - 2.0]},
        fixed={"mu": 0.2, "angle": 0.5},
    )
    ds = run_sweep(
        study, tmp_path / "leaky.zarr", evaluator=ValuesOnFailedCases(), quiet=True
    ).dataset.load()
    _no_result_where_failed(ds)
    assert ds["duration"].values[0] == 1e-4 and ds["regime"].values[0] >= 0
