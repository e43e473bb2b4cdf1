"""A folder inside a sweep store (one of its arrays) given as the store is named as such."""

from __future__ import annotations

from pathlib import Path

import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Study, open_sweep, run_sweep, store_info


def test_an_array_of_a_store_is_not_the_store(tmp_path: Path, monkeypatch, capsys) -> None:
    study = Study.from_dict(
        {"grid": {"angle": ["20 deg", "40 deg"]}, "fixed": {"vy": -1.41, "mu": 0.2}}
    )
    store = tmp_path / "s.zarr"
    run_sweep(study, store, evaluator=FakeEvaluator(), quiet=True)
    inner = store / "angle"
    message = f"{str(inner)!r} is an array inside the sweep store {str(store)!r}"
    for read in (open_sweep, store_info):
        with pytest.raises(ValueError, match=message.replace(".", r"\.")):
            read(inner)
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "info", str(inner))
    assert code == 2 and err.strip() == f"error: {message}: give the store's folder"
