"""Exports of a store of any size: the CSV table is written block by block (at most
``CSV_BLOCK_CASES`` cases in memory) and is byte for byte the table of the whole Dataset at once;
the NetCDF file is compressed and written chunk by chunk from the store, with the variables,
attributes and units of the Dataset."""

from __future__ import annotations

import json
import os
import shutil
import tracemalloc
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import xarray as xr
from sweep_fakes import CrashingEvaluator, FakeEvaluator, FlaggingEvaluator

import impactlab.sweep.netcdf as export
from impactlab.sweep import Normal, Sample, Study, Uniform, open_sweep, run_sweep
from impactlab.sweep.slabs import slabs


def _reference_csv(ds: xr.Dataset, path: Path) -> None:
    """The CSV table as the whole Dataset gives it in one ``to_dataframe`` (the export's
    definition; it holds every case in memory)."""
    dims = [str(d) for d in (ds["status"].dims if "status" in ds else ds.dims)]
    table = ds.to_dataframe(dim_order=dims).reset_index()
    table = table[export._columns(dims, ds.attrs.get("outputs", []), list(map(str, table)))]
    table.columns = [export._header(str(c), ds[c].attrs.get("units")) for c in table.columns]
    table.to_csv(path, index=False)


def _reference_netcdf(ds: xr.Dataset, path: Path) -> None:
    """The NetCDF file of the loaded Dataset, uncompressed (strings fixed-width, dictionary
    attributes JSON text)."""

    def attrs(a: Mapping[str, Any]) -> dict[str, Any]:
        return {k: json.dumps(v) if isinstance(v, dict) else v for k, v in a.items()}

    def plain(var: xr.Variable) -> xr.Variable:
        values = var.values
        if values.dtype.kind == "T":
            values = np.array(values.tolist(), dtype=str)
        return xr.Variable(var.dims, values, attrs(var.attrs))

    loaded = ds.load()
    coords = {str(k): plain(v.variable) for k, v in loaded.coords.items()}
    data = {str(k): plain(v.variable) for k, v in loaded.data_vars.items()}
    xr.Dataset(data, coords=coords, attrs=attrs(loaded.attrs)).to_netcdf(path, engine="netcdf4")


STUDIES = {
    # a category dimension (chunks of extent 1 along it) between grid dimensions, flags
    "grid": lambda: Study(
        name="grid",
        chunk_size=12,
        grid={
            "angle": np.radians(np.linspace(5, 85, 9)),
            "law": ["ghaednia", "hertz"],
            "mu": np.linspace(0, 0.6, 7),
        },
        fixed={"vy": -1.41},
    ),
    # a grid and a sample (a dimension without coordinate), inputs along the sample only
    "sampled": lambda: Study(
        name="sampled",
        chunk_size=5,
        grid={"angle": ["20 deg", "40 deg"], "mu": [0.1, 0.3, 0.5]},
        fixed={"law": "hertz"},
        sample=Sample(size=11, seed=1, inputs={"vy": Uniform(-7.0, -1.0), "spin": Normal(0, 1)}),
        outputs=["regime", "e", "delta_p"],
    ),
    # failed cases (status 1: NaN outputs, regime and flags -1)
    "failed": lambda: Study(
        name="failed",
        chunk_size=7,
        grid={"vy": np.linspace(-7, -1, 13)},
        fixed={"angle": 0.3, "mu": 0.2},
    ),
}


def _store(tmp_path: Path, name: str) -> Path:
    store = tmp_path / f"{name}.zarr"
    if name == "incomplete":  # 3 of 10 chunks done: the others' status reads -1
        study = Study(
            name="part",
            chunk_size=10,
            sample=Sample(size=97, seed=2, inputs={"mu": Uniform(0.0, 0.6)}),
            fixed={"vy": -1.41, "angle": "30 deg"},
        )
        with pytest.raises(RuntimeError, match="simulated crash"):
            run_sweep(study, store, evaluator=CrashingEvaluator(after=3), workers=1, quiet=True)
        return store
    run_sweep(STUDIES[name](), store, evaluator=FlaggingEvaluator(), quiet=True)
    return store


@pytest.fixture(scope="module")
def stores(tmp_path_factory):
    """``stores(name)``: the store of a study, run once for the module (the tests only read it),
    with the reference CSV of its whole Dataset beside it (``expected.csv``)."""
    made: dict[str, Path] = {}

    def get(name: str) -> Path:
        if name not in made:
            folder = tmp_path_factory.mktemp(name)
            made[name] = _store(folder, name)
            _reference_csv(open_sweep(made[name]), folder / "expected.csv")
        return made[name]

    return get


@pytest.mark.parametrize("name", [*STUDIES, "incomplete"])
@pytest.mark.parametrize("block", [None, 5, 23])
def test_the_csv_is_the_whole_tables_byte_for_byte(
    stores, tmp_path, monkeypatch, name, block
) -> None:
    store = stores(name)
    if block is not None:  # case counts (126, 66, 13, 97) no multiple of the block
        monkeypatch.setattr(export, "CSV_BLOCK_CASES", block)
    export.export_csv(open_sweep(store), tmp_path / "got.csv")
    expected = (store.parent / "expected.csv").read_bytes()
    assert (tmp_path / "got.csv").read_bytes() == expected
    if name == "incomplete":
        assert b",-1," in expected  # the cases not computed


def test_a_dataset_in_memory_and_without_a_store(stores, tmp_path, monkeypatch) -> None:
    ds = open_sweep(stores("sampled")).load()
    for var in ds.variables.values():
        var.encoding = {}
    monkeypatch.setattr(export, "CSV_BLOCK_CASES", 4)
    _reference_csv(ds, tmp_path / "expected.csv")
    export.export_csv(ds, tmp_path / "got.csv")
    assert (tmp_path / "got.csv").read_bytes() == (tmp_path / "expected.csv").read_bytes()


def test_the_csv_holds_one_block_at_a_time(stores, tmp_path, monkeypatch) -> None:
    store = stores("grid")  # 126 cases
    rows: list[int] = []
    whole = xr.Dataset.to_dataframe

    def spy(self, *args, **kwargs):
        table = whole(self, *args, **kwargs)
        rows.append(len(table))
        return table

    monkeypatch.setattr(xr.Dataset, "to_dataframe", spy)
    monkeypatch.setattr(export, "CSV_BLOCK_CASES", 10)
    export.export_csv(open_sweep(store), tmp_path / "g.csv")
    assert sum(rows) == 126 and max(rows) <= 10 and len(rows) > 12


@pytest.mark.parametrize("shape", [(5,), (2, 3, 4), (5, 1, 7), (1, 1), (4, 6, 3), (3, 0, 2)])
@pytest.mark.parametrize("limit", [1, 2, 5, 7, 24, 1000])
def test_the_blocks_cover_the_cases_in_order(shape, limit) -> None:
    cases = np.arange(int(np.prod(shape))).reshape(shape)
    for chunks in (None, tuple(max(1, n // 2) for n in shape)):
        blocks = list(slabs(shape, limit, chunks))
        parts = [cases[s].ravel() for s in blocks]
        assert np.array_equal(np.concatenate(parts), cases.ravel())
        assert max(len(p) for p in parts) <= limit


def test_the_blocks_follow_the_store_chunks() -> None:
    blocks = list(slabs((100, 100, 100), 65_536, (6, 100, 100)))
    assert [s[0] for s in blocks[:2]] == [slice(0, 6), slice(6, 12)]  # one chunk each
    assert len(blocks) == 17 and blocks[-1][0] == slice(96, 100)


def test_netcdf_reads_the_store_chunk_by_chunk(tmp_path) -> None:
    study = Study(
        name="big",
        chunk_size=10_000,
        grid={"angle": np.linspace(0.1, 1.4, 100), "mu": np.linspace(0, 0.6, 100)},
        fixed={"vy": -1.41},
        sample=Sample(size=20, seed=3, inputs={"spin": Normal(0, 1)}),
    )  # 200,000 cases: 9 MB of outputs and status
    store = run_sweep(study, tmp_path / "b.zarr", evaluator=FakeEvaluator(), quiet=True).path
    export.export_netcdf(open_sweep(store)[["e"]], tmp_path / "warm.nc")  # imports, caches
    ds = open_sweep(store)
    total = sum(v.nbytes for v in ds.data_vars.values())
    tracemalloc.start()
    try:
        export.export_netcdf(ds, tmp_path / "b.nc")
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert total > 8e6 and peak < total / 3  # about 1.5 MB: a few chunks at a time


@pytest.mark.parametrize("name", ["grid", "incomplete"])
def test_netcdf_is_compressed_and_reads_back_as_the_dataset(stores, tmp_path, name) -> None:
    store = stores(name)
    _reference_netcdf(open_sweep(store), tmp_path / "ref.nc")
    nc4 = pytest.importorskip("netCDF4")
    cache = nc4.get_chunk_cache()
    export.export_netcdf(open_sweep(store), tmp_path / "got.nc")
    assert nc4.get_chunk_cache() == cache  # the library's setting as it was
    assert not list(tmp_path.glob(".*partial"))
    with xr.open_dataset(tmp_path / "got.nc") as got, xr.open_dataset(tmp_path / "ref.nc") as ref:
        xr.testing.assert_identical(got, ref)  # values, variables, attributes, units
        chunks = tuple(open_sweep(store).attrs["chunk_shape"])
        for var in ("e", "status"):
            enc = got[var].encoding
            assert enc.get("zlib") is True or enc.get("compression") == "zlib", enc
            assert enc["shuffle"] and tuple(enc["chunksizes"]) == chunks
        assert got["e"].attrs["units"] == "1" and "not computed" in got.attrs["status_messages"]
    if name == "incomplete":
        with xr.open_dataset(tmp_path / "got.nc") as got:
            assert int((got["status"] == -1).sum()) == 67


def test_a_failed_netcdf_export_leaves_no_file(stores, tmp_path, monkeypatch) -> None:
    store = shutil.copytree(stores("failed"), tmp_path / "failed.zarr")

    def broken(self, path, *args, **kwargs):
        Path(path).write_bytes(b"half")
        raise OSError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", broken)
    with pytest.raises(OSError, match="disk full"):
        export.export_netcdf(open_sweep(store), tmp_path / "f.nc")
    assert os.listdir(tmp_path) == ["failed.zarr"]
