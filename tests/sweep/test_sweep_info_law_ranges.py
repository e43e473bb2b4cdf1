"""``impactlab sweep info`` shows the range of each law of the store's study (its
``law_ranges`` attribute): one table row per law, and in ``--json`` the attribute as recorded
(range and source; null for a store that records none)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
import zarr
from sweep_fakes import run_cli

from impactlab._json import shape_problems
from impactlab.sweep import Study, run_sweep
from impactlab.sweep.study_meta import law_ranges


def _store(tmp_path: Path, fake: Any) -> tuple[Path, Study]:
    study = Study(name="ranges", fixed={"angle": 0.5, "mu": 0.2, "law": "ghaednia"},
                  grid={"vy": [-1.0, -2.0]})  # fmt: skip
    path = tmp_path / "ranges.zarr"
    run_sweep(study, path, evaluator=fake, quiet=True)
    return path, study


def test_info_shows_each_laws_range(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
    fake: Any,
) -> None:
    """Formerly ``sweep info`` showed neither the ranges nor the sources a store records."""
    path, study = _store(tmp_path, fake)
    expected = law_ranges(study)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(path), "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["law_ranges"] == expected and shape_problems(data) == []
    assert set(data["law_ranges"]["ghaednia"]) == {"range", "source"}
    monkeypatch.setenv("COLUMNS", "400")  # a wide table: each row on one line
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(path))
    assert code == 0, err
    rows = [line for line in out.splitlines() if "law range: " in line]
    assert len(rows) == 1 and "law range: ghaednia" in rows[0]
    assert expected["ghaednia"]["range"] in rows[0]
    assert expected["ghaednia"]["source"] not in out  # the sources: --json only


def test_a_store_without_law_ranges_says_so(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
    fake: Any,
) -> None:
    path, _ = _store(tmp_path, fake)
    group = zarr.open_group(str(path), mode="r+")
    attrs = {k: v for k, v in group.attrs.items() if k != "law_ranges"}
    group.attrs.clear()
    group.attrs.update(attrs)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(path), "--json")
    assert code == 0 and json.loads(out)["law_ranges"] is None, err
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(path))
    assert code == 0 and "not recorded in this store" in out, err
