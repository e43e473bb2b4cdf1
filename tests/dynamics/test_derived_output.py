"""A derived output registered from outside the package (``impactlab.schema.register_output``)
appears in ImpactResult, BatchResult, the drop result, a batch of drops and a sweep store, with
its unit; bad registrations are refused."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

import impactlab as il
from impactlab import schema
from impactlab.materials import AISI_1010

NAME = "permanent_share"


def _share(delta_p: object, delta_max: object) -> object:
    """delta_p / delta_max: the share of the largest interference left as a dent."""
    return np.divide(delta_p, delta_max)  # type: ignore[call-overload]


@pytest.fixture(scope="module")
def toy() -> Iterator[schema.DerivedField]:
    field = schema.register_output(
        NAME, "1", "permanent share of the largest interference", ("delta_p", "delta_max"), _share
    )
    yield field
    schema.unregister_output(NAME)


KW = {"law": "ghaednia", "mu": 0.2}


def test_impact_result(toy: schema.DerivedField) -> None:
    r = il.simulate(il.Rod.paper(), angle=math.radians(40), velocity=(0.0, -1.4), **KW)
    want = r.delta_p / r.delta_max
    assert 0.0 < want < 1.0
    assert getattr(r, NAME) == want and r.to_dict()[NAME] == want
    assert schema.unit(NAME) == "1"


def test_batch_result(toy: schema.DerivedField) -> None:
    b = il.simulate_batch(il.Rod.paper(), angle=np.radians([20.0, 60.0]), vy=-1.4, **KW)
    want = b["delta_p"] / b["delta_max"]
    np.testing.assert_array_equal(b[NAME], want)
    np.testing.assert_array_equal(getattr(b, NAME), want)
    ds = b.to_xarray()
    np.testing.assert_array_equal(ds[NAME].values, want)
    assert ds[NAME].attrs["units"] == "1"
    np.testing.assert_array_equal(b.to_dataframe()[NAME].to_numpy(), want)


def test_drop_result(toy: schema.DerivedField) -> None:
    """A drop has no delta_p of one unloading (its final dent is ``dent_depth``): a derived
    output that needs it reads NaN, as in a flexible sweep store."""
    r = il.simulate_drop(il.Rod.paper(), angle=math.radians(40), velocity=(0.0, -1.4), **KW)
    assert math.isnan(getattr(r, NAME)) and r.to_dict()[NAME] is None  # JSON: NaN is null
    assert r.dent_depth > 0.0 and r.delta_max > 0.0


RATIO = "e_per_depth"


@pytest.fixture(scope="module")
def ratio() -> Iterator[schema.DerivedField]:
    """A derived output whose needs a drop has: e / delta_max [1/m]."""
    field = schema.register_output(
        RATIO, "1/m", "e per metre of the largest interference", ("e", "delta_max"), _per_depth
    )
    yield field
    schema.unregister_output(RATIO)


def _per_depth(e: object, delta_max: object) -> object:
    return np.divide(e, delta_max)  # type: ignore[call-overload]


def test_drop_batch_result(toy: schema.DerivedField, ratio: schema.DerivedField) -> None:
    """``simulate_drops`` has every derived output as ``DropResult`` has it, case by case: by
    name, as an attribute, in ``to_xarray``, ``to_dataframe`` and ``to_pint``; a need that a
    drop lacks (delta_p) reads NaN there as here."""
    angles = np.radians([20.0, 40.0])
    drops = il.simulate_drops(il.Rod.paper(), angle=angles, vy=-1.4, **KW)
    assert drops.computed.all()
    want = drops["e"] / drops["delta_max"]
    assert np.all(want > 0.0) and np.all(np.isfinite(want))
    np.testing.assert_array_equal(drops[RATIO], want)
    np.testing.assert_array_equal(getattr(drops, RATIO), want)
    ds = drops.to_xarray()
    np.testing.assert_array_equal(ds[RATIO].values, want)
    assert ds[RATIO].attrs["units"] == "1/m"
    np.testing.assert_array_equal(drops.to_dataframe()[RATIO].to_numpy(), want)
    q = drops.to_pint()[RATIO]
    np.testing.assert_array_equal(q.to("1/m").magnitude, want)
    for i, angle in enumerate(angles):
        one = il.simulate_drop(il.Rod.paper(), angle=angle, velocity=(0.0, -1.4), **KW)
        assert getattr(one, RATIO) == drops[RATIO][i]
        assert math.isnan(getattr(one, NAME))
    assert np.isnan(drops[NAME]).all() and np.isnan(ds[NAME].values).all()
    with pytest.raises(KeyError, match=RATIO):
        drops["no_such_output"]


def test_sweep_store(toy: schema.DerivedField, tmp_path) -> None:
    from impactlab.sweep import Study, run_sweep

    study = Study(
        name="derived",
        grid={"angle": np.radians([20.0, 60.0])},
        fixed={"vy": -1.4, "mu": 0.2, "law": "ghaednia", "flat_material": "aisi-1010"},
        outputs=["e", NAME],
    )
    ds = run_sweep(study, tmp_path / "derived.zarr", quiet=True).dataset
    b = il.simulate_batch(il.Rod.paper(), AISI_1010, angle=np.radians([20.0, 60.0]), vy=-1.4, **KW)
    np.testing.assert_allclose(ds[NAME].values, b[NAME], rtol=1e-12)
    assert ds[NAME].attrs["units"] == "1"
    assert "delta_p" not in ds  # a need is computed, not stored unless kept


def test_bad_registrations_are_refused() -> None:
    with pytest.raises(ValueError, match="output name 'e' is taken"):
        schema.register_output("e", "1", "x", ("e",), lambda e: e)
    with pytest.raises(ValueError, match="needs must name engine outputs"):
        schema.register_output("toy_bad", "1", "x", ("velocity",), lambda velocity: velocity)
    with pytest.raises(ValueError, match="compute must be callable"):
        schema.register_output("toy_bad", "1", "x", ("e",), 3.0)  # type: ignore[arg-type]
    assert "toy_bad" not in schema.FIELDS


@pytest.mark.slow
def test_sweep_with_spawned_workers(toy: schema.DerivedField, tmp_path) -> None:
    """The pool's workers (started with "spawn") know nothing of the field: the writer, in
    this process, computes it from the engine outputs they return."""
    from impactlab.sweep import Study, run_sweep

    study = Study(
        name="derived-pool",
        grid={"angle": np.radians([20.0, 60.0])},
        fixed={"vy": -1.4, "mu": 0.2, "law": "ghaednia"},
        outputs=[NAME],
    )
    pool = run_sweep(study, tmp_path / "pool.zarr", quiet=True, backend="processes", workers=1)
    here = run_sweep(study, tmp_path / "here.zarr", quiet=True)
    np.testing.assert_array_equal(pool.dataset[NAME].values, here.dataset[NAME].values)
    assert np.isfinite(pool.dataset[NAME].values).all()
