"""A sweep refused before it runs leaves nothing behind: a scheduler address that is not one is
refused (naming it) before the store is made, and ``--plot DIR`` is made only once the sweep
ran (a run refused for a store of another study leaves no empty plot folder)."""

from __future__ import annotations

from pathlib import Path

import pytest
from sweep_fakes import run_cli

from impactlab.sweep import Study, run_sweep

STUDY = """
[study]
name = "tiny"
[grid]
angle = ["20 deg", "40 deg"]
[fixed]
vy = -1.41
mu = 0.2
"""


@pytest.mark.parametrize("address", ["foo", "tcp://foo", "tcp://host:port", ""])
def test_a_scheduler_that_is_not_an_address_is_refused_before_the_store(
    tmp_path: Path, address: str
) -> None:
    study = Study.from_dict(
        {"grid": {"angle": ["20 deg", "40 deg"]}, "fixed": {"vy": -1.41, "mu": 0.2}}
    )
    store = tmp_path / "s.zarr"
    with pytest.raises(ValueError, match=rf"scheduler {address!r}: expected a Dask scheduler's"):
        run_sweep(study, store, scheduler=address, quiet=True)
    assert not store.exists()


def test_the_command_line_leaves_no_store_and_no_plot_folder(
    tmp_path: Path, monkeypatch, capsys
) -> None:
    toml = tmp_path / "tiny.toml"
    toml.write_text(STUDY, encoding="utf-8")
    store, plots = tmp_path / "t.zarr", tmp_path / "plots"
    args = ("sweep", "run", str(toml), "--out", str(store), "--plot", str(plots))
    code, _, err = run_cli(monkeypatch, capsys, *args, "--scheduler", "foo")
    assert code == 2 and "error: scheduler 'foo': expected a Dask scheduler's address" in err
    assert not store.exists() and not plots.exists()
    # a store of another study: refused, and no plot folder made for it
    other = tmp_path / "other.toml"
    other.write_text(STUDY.replace('"tiny"', '"other"'), encoding="utf-8")
    assert run_cli(monkeypatch, capsys, "sweep", "run", str(other), "--out", str(store))[0] == 0
    code, _, err = run_cli(monkeypatch, capsys, *args)
    assert code == 2 and not plots.exists()
