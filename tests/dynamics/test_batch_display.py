"""How a batch shows itself: its fields in ``dir()`` (tab completion) and a misspelt one named
with the nearest; ``to_dataframe`` with SI units in ``df.attrs`` and ``regime`` by name (as
``History.to_dataframe`` and ``ImpactResult.regime``); one-line reprs with their counts (a
batch of drops, a sweep's numbers and result)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import impactlab as il
from impactlab import schema
from impactlab.dynamics import BatchResult, DropBatchResult
from impactlab.dynamics.kernels.layout import OUTPUT_FIELDS
from impactlab.sweep import Study
from impactlab.sweep.runner import SweepResult, SweepStats


@pytest.fixture(scope="module")
def batch() -> BatchResult:
    """Slip, stick and a case refused for its inputs (the tip moves away)."""
    angles, vy, mu = [0.35, 0.4, 0.3], [-1.41, -1.41, 1.0], [0.2, 0.9, 0.2]
    return il.simulate_batch(il.Rod.paper(), angle=angles, vy=vy, mu=mu)


@pytest.fixture(scope="module")
def drops() -> DropBatchResult:
    """One drop refused (mu < 0), one computed."""
    return il.simulate_drops(il.Rod.paper(), angle=0.35, vy=-1.41, mu=[-1.0, 0.2])


def test_fields_are_listed_and_a_typo_is_named(batch: BatchResult, drops: DropBatchResult) -> None:
    for result, field, typo, near in (
        (batch, "sliding_length", "sliding_lenght", "sliding_length"),
        (drops, "dent_depth", "dent_dept", "dent_depth"),
    ):
        names = dir(result)
        assert {field, "angle", "mu", "e", "to_dataframe", "messages"} <= set(names)
        with pytest.raises(AttributeError) as err:
            getattr(result, typo)
        text = str(err.value)
        assert text.startswith(f"{type(result).__name__} has no field or attribute {typo!r}")
        assert f"(did you mean {near!r}?)" in text and "its fields: mu, angle, vx" in text
        assert not hasattr(result, "_private") and not hasattr(result, "nothing_like_it")


def test_dataframes_carry_units_and_the_regime_by_name(
    batch: BatchResult, drops: DropBatchResult
) -> None:
    df = batch.to_dataframe()
    assert df.attrs["units"] == {c: "1" if c == "status" else schema.unit(c) for c in df.columns}
    assert df.attrs["units"]["angle"] == "rad" and df.attrs["units"]["delta_p"] == "m"
    assert str(df["regime"].dtype) == "category"
    assert list(df["regime"].cat.categories) == ["frictionless", "slip", "stick", "reversal"]
    assert df["regime"].tolist()[:2] == ["slip", "stick"] and df["regime"].isna().tolist()[2]
    one = il.simulate(il.Rod.paper(), angle=0.35, velocity=(0.0, -1.41), mu=0.2)
    assert df["regime"][0] == one.regime
    for j, name in enumerate(OUTPUT_FIELDS):  # the numbers are the batch's own
        if name not in ("regime", "flags", "n_steps", "energy_rise", "friction_excess"):
            np.testing.assert_array_equal(df[name].to_numpy(), batch.out[:, j], err_msg=name)
    ddf = drops.to_dataframe()
    units = ddf.attrs["units"]
    assert set(units) == set(ddf.columns)
    assert units["dent_depth"] == "m" and units["sequence_duration"] == "s"
    assert units["vy"] == "m/s" and units["n_jumps"] == "1"
    np.testing.assert_array_equal(ddf["dent_depth"].to_numpy(), drops.dent_depth)


def test_a_drop_batch_repr_counts_its_cases(batch: BatchResult, drops: DropBatchResult) -> None:
    text = repr(drops)
    assert text.startswith("DropBatchResult(2 cases, 1 computed, ") and "\n" not in text
    assert "law='ghaednia'" in text and "gravity=9.80665 m/s^2" in text and "rtol=1e-07" in text
    assert repr(batch).startswith("BatchResult(3 cases, 2 computed, ")


def test_sweep_reprs_are_one_line(tmp_path: Path) -> None:
    stats = SweepStats(
        n_chunks=33,
        n_cases=1089,
        chunks_computed=33,
        cases_computed=1089,
        wall_s=1.25,
        backend="threads",
        workers=4,
        cache={"worker-0": {"hits": 5, "misses": 0}},
        first_task_s={"worker-0": 0.5},
    )
    assert repr(stats) == (
        "SweepStats(1089 cases in 33 chunks; this run: 1089 cases in 33 chunks computed, "
        "0 already stored; wall 1.25 s, 871.2 impacts/s; backend='threads', workers=4)"
    )
    study = Study(name="map", grid={"angle": [0.3, 0.4]}, fixed={"vy": -1.41, "mu": 0.2})
    result = SweepResult(tmp_path / "map.zarr", study, stats)
    text = repr(result)
    assert text.startswith(f"SweepResult(path={str(tmp_path / 'map.zarr')!r}, study='map', ")
    assert text.endswith("1089 cases in 33 chunks; this run: 1089 cases computed in 1.25 s, "
                         "backend='threads')")  # fmt: skip
    resumed = SweepStats(n_chunks=1, n_cases=20, chunks_before=1, backend="threads", workers=1)
    assert "0 cases in 0 chunks computed, 1 already stored; wall 0 s; " in repr(resumed)
    assert math.isfinite(resumed.throughput)
