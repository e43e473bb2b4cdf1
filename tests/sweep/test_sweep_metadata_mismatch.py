"""Metadata that is valid JSON and that Zarr reads, but no longer follows from the study (a
data type, shape, chunk shape, fill value or dimension name changed; a root that lost its
attributes), is refused by name like junk metadata, and a run of the same study writes it
again, keeping every chunk."""

from __future__ import annotations

import json
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, run_cli, store_files

from impactlab.sweep import RepairableStoreError, Study, open_sweep, run_sweep, store_info
from impactlab.sweep.dimensions import Sample
from impactlab.sweep.distributions import Uniform


def _study() -> Study:
    return Study(
        name="meta",
        chunk_size=10,
        grid={"angle": np.radians([10.0, 30.0, 50.0, 70.0])},
        sample=Sample(size=5, seed=3, inputs={"mu": Uniform(0.0, 0.6)}),
        fixed={"vy": -1.41},
    )


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("ref") / "ref.zarr"
    return run_sweep(_study(), path, evaluator=FakeEvaluator(), quiet=True).path


def _edit(f: Path, change: Callable[[dict[str, Any]], None]) -> None:
    meta = json.loads(f.read_text())
    change(meta)
    f.write_text(json.dumps(meta, indent=2))


def _set(key: str, value: Any) -> Callable[[dict[str, Any]], None]:
    return lambda meta: meta.__setitem__(key, value)


def _chunks(meta: dict[str, Any]) -> None:
    meta["chunk_grid"]["configuration"]["chunk_shape"] = [1, 5]


CHANGES: dict[str, tuple[str, Callable[[dict[str, Any]], None]]] = {
    "result dtype": ("e", _set("data_type", "float32")),
    "result shape": ("e", _set("shape", [4, 6])),
    "result fill": ("e", _set("fill_value", 0.0)),
    "result chunks": ("e", _chunks),
    "result dims": ("e", _set("dimension_names", ["angle", "other"])),
    "status dtype": ("status", _set("data_type", "int16")),
    "coordinate dtype": ("angle", _set("data_type", "float32")),
    "sampled fill": ("mu", _set("fill_value", 0.0)),
}


@pytest.mark.parametrize("change", sorted(CHANGES))
def test_metadata_that_no_longer_follows_from_the_study_is_repaired(
    tmp_path, reference, change
) -> None:
    node, edit = CHANGES[change]
    store = tmp_path / "a.zarr"
    shutil.copytree(reference, store)
    _edit(store / node / "zarr.json", edit)
    with pytest.raises(RepairableStoreError) as opened:
        open_sweep(store)
    message = str(opened.value)
    assert f"{node}/zarr.json does not match the study" in message and str(store) in message
    assert "run the same study into it again" in message and "\n" not in message
    assert opened.value.missing_arrays == (node,)
    with pytest.raises(RepairableStoreError, match="does not match the study"):
        store_info(store)
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0 and again.stats.chunks_before == again.stats.n_chunks
    assert store_files(store) == store_files(reference)


def test_info_and_export_name_the_file_and_the_difference(
    tmp_path, reference, monkeypatch, capsys
) -> None:
    store = tmp_path / "a.zarr"
    shutil.copytree(reference, store)
    _edit(store / "e" / "zarr.json", _set("data_type", "float32"))
    for args in (("info", str(store)), ("export", str(store), str(tmp_path / "o.csv"))):
        code, _out, err = run_cli(monkeypatch, capsys, "sweep", *args)
        assert code == 2 and 'e/zarr.json does not match the study: data_type "float32"' in err
        assert "reshape" not in err and "Traceback" not in err
    assert not (tmp_path / "o.csv").exists()


def test_a_root_without_its_attributes_is_rewritten_from_the_study_record(
    tmp_path, reference, monkeypatch, capsys
) -> None:
    store = tmp_path / "a.zarr"
    shutil.copytree(reference, store)
    (store / "zarr.json").write_text(
        json.dumps({"zarr_format": 3, "node_type": "group", "attributes": {}})
    )
    with pytest.raises(RepairableStoreError) as opened:
        open_sweep(store)
    assert "zarr.json lacks the study's attributes (study_hash" in str(opened.value)
    assert opened.value.root is not None
    code, _out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store))
    assert code == 2 and "lacks the study's attributes" in err and "--restart would" in err
    code, _out, err = run_cli(
        monkeypatch, capsys, "sweep", "export", str(store), str(tmp_path / "o.csv")
    )
    assert code == 2 and not (tmp_path / "o.csv").exists()
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    ds = open_sweep(store)
    assert ds.attrs["study_hash"] == open_sweep(reference).attrs["study_hash"]
    assert "e" in ds.data_vars
