"""``BatchResult`` and ``DropBatchResult`` read alike: every column of each one's own
``to_dataframe()`` is served by ``[name]`` with the same values (status, flags,
max_delta_ratio, ...), and both compare and hash by identity (no ``==`` over arrays)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import impactlab as il

ROD = il.Rod.paper()
VY = [-1.0, -300.0, float("nan")]


@pytest.fixture(scope="module")
def batches() -> tuple[il.BatchResult, il.DropBatchResult]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        b = il.simulate_batch(ROD, angle=0.35, vy=VY, mu=0.2)
        d = il.simulate_drops(ROD, angle=0.35, vy=VY, mu=0.2)
    return b, d


def test_every_dataframe_column_is_served_by_name(batches: tuple) -> None:
    for batch in batches:
        df = batch.to_dataframe()
        for name in df.columns:
            got = batch[name]
            if name == "regime":
                continue  # names in the DataFrame, codes by name
            column = df[name].to_numpy(dtype=float, na_value=np.nan)
            assert np.array_equal(np.asarray(got, dtype=float), column, equal_nan=True), name


def test_status_flags_and_ratio_read_alike(batches: tuple) -> None:
    b, d = batches
    for batch in (b, d):
        assert batch["status"].tolist() == batch.status.tolist() == [0, 1, 4]
        flags = batch["flags"]
        assert np.isnan(flags[1:]).all() and flags[0] == batch.flags[0]
        assert np.isnan(batch["max_delta_ratio"][1:]).all()
        assert batch["max_delta_ratio"][0] > 0


def test_drop_batches_compare_and_hash_by_identity(batches: tuple) -> None:
    _, d = batches
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        twin = il.simulate_drops(ROD, angle=0.35, vy=VY, mu=0.2)
    assert d == d and d != twin and d in [d] and twin not in [d]
    assert len({d, twin}) == 2 and hash(d) == object.__hash__(d)
