"""A sweep store's stored words for status 0 are "finished" (the engine ran the case to its
end; whether its result is ok, the flags say), as the counts label it; a store written with
the older word "ok" still opens and its counts read "finished"."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import zarr
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Study, export_netcdf, open_sweep, run_sweep, status_counts, store_info
from impactlab.sweep.storebuild import FINISHED
from impactlab.sweep.summary import FINISHED as COUNTS_FINISHED


def _run(tmp_path: Path) -> Path:
    store = tmp_path / "w.zarr"
    study = Study(name="words", grid={"mu": [0.1, 0.2], "vy": [-1.41, -6.0]},
                  fixed={"angle": 0.5}, outputs=["e"])  # fmt: skip
    run_sweep(study, store, evaluator=FakeEvaluator(), quiet=True)
    return store


def test_the_store_calls_status_zero_finished(tmp_path: Path) -> None:
    assert FINISHED == COUNTS_FINISHED
    store = _run(tmp_path)
    ds = xr.open_zarr(str(store), consolidated=False)
    status = ds["status"].attrs
    assert "0: finished" in status["long_name"] and "0: ok" not in status["long_name"]
    assert status["messages"]["0"] == "finished"
    assert ds.attrs["status_messages"]["0"] == "finished"
    assert ds.attrs["status_messages"]["1"] == "fake: vy outside the validity range"
    export_netcdf(ds, tmp_path / "w.nc")
    with xr.open_dataset(tmp_path / "w.nc") as back:
        assert '"0": "finished"' in str(back.attrs["status_messages"])


@pytest.mark.filterwarnings("ignore::UserWarning")  # zarr: consolidating a sweep store
def test_a_store_that_says_ok_still_opens_and_reads_finished(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    store = _run(tmp_path)
    g = zarr.open_group(str(store), mode="a", zarr_format=3)
    msgs = dict(g.attrs.asdict()["status_messages"])  # type: ignore[arg-type]
    msgs["0"] = "ok"
    g.attrs["status_messages"] = msgs
    g["status"].attrs["long_name"] = "case status (0: ok; see 'messages')"
    zarr.consolidate_metadata(str(store))
    ds = open_sweep(store)
    assert ds.attrs["status_messages"]["0"] == "ok"
    assert status_counts(ds) == {"0: finished": 2, "1: fake: vy outside the validity range": 2}
    assert store_info(store)["status"]["0: finished"] == 2
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store))
    assert code == 0, err
    assert "0: finished = 2" in out and "0: ok" not in out
    assert np.asarray(ds["status"].values).min() == 0


def test_a_batch_export_calls_status_zero_finished() -> None:
    """``BatchResult.to_xarray``'s ``status`` variable (the same words as a sweep store's)."""
    from impactlab.dynamics.export import status_attrs

    long_name = status_attrs()["long_name"]
    assert long_name.startswith("engine status of the case (0: finished,")
    assert "0: ok" not in long_name
