"""A full disk while a store is exported (NetCDF, CSV) or plotted ends in one line that names
the file and the cause, never a traceback, and leaves no file half-written (a PNG, a table)."""

from __future__ import annotations

import errno
import os
from collections import namedtuple
from pathlib import Path

import pytest
import xarray as xr
from matplotlib.figure import Figure
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Study, run_sweep

_Usage = namedtuple("_Usage", "total used free")


@pytest.fixture(scope="module")
def store(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("full") / "s.zarr"
    study = Study(
        name="full",
        chunk_size=8,
        grid={"angle": [0.2, 0.4, 0.6], "mu": [0.1, 0.3, 0.5, 0.7]},
        fixed={"vy": -1.41},
    )
    return run_sweep(study, path, evaluator=FakeEvaluator(), quiet=True).path


def _hdf_error_on_close(monkeypatch) -> None:
    """netCDF4 as on a full disk: the file half-written, then RuntimeError at its close."""

    def to_netcdf(self, path, *args, **kwargs):
        Path(path).write_bytes(b"\x89HDF\r\n\x1a\n half")
        raise RuntimeError("NetCDF: HDF error")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", to_netcdf)


def _free(monkeypatch, free: int) -> None:
    monkeypatch.setattr(
        "impactlab.sweep.filewrite.shutil.disk_usage", lambda _p: _Usage(10**9, 10**9, free)
    )


def test_netcdf_export_on_a_full_disk_is_one_line(tmp_path, store, monkeypatch, capsys) -> None:
    _hdf_error_on_close(monkeypatch)
    _free(monkeypatch, 0)
    out = tmp_path / "out.nc"
    code, stdout, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(out))
    assert code == 1 and stdout == ""
    assert err == (
        f"error: no space left on the device writing {str(out)!r}: free space and run the "
        "command again\n"
    )
    assert list(tmp_path.iterdir()) == []


def test_netcdf_export_failing_otherwise_quotes_the_library(
    tmp_path, store, monkeypatch, capsys
) -> None:
    _hdf_error_on_close(monkeypatch)
    _free(monkeypatch, 10**9)
    out = tmp_path / "out.nc"
    code, _stdout, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(out))
    assert code == 1 and err.count("\n") == 1 and "Traceback" not in err
    assert "the NetCDF library could not write the file (NetCDF: HDF error" in err
    assert repr(str(out)) in err
    assert list(tmp_path.iterdir()) == []


def _enospc(*_args, **_kwargs):
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))  # no file named, as the writers do


def test_csv_export_on_a_full_disk_names_the_file(tmp_path, store, monkeypatch, capsys) -> None:
    monkeypatch.setattr("pandas.DataFrame.to_csv", _enospc)
    out = tmp_path / "out.csv"
    code, _stdout, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(out))
    assert code == 1
    assert err == (
        f"error: no space left on the device writing {str(out)!r}: free space and run the "
        "command again\n"
    )
    assert list(tmp_path.iterdir()) == []


def test_a_plot_on_a_full_disk_names_its_file_and_leaves_no_empty_png(
    tmp_path, store, monkeypatch, capsys
) -> None:
    real = Figure.savefig
    calls = {"n": 0}

    def savefig(self, fname, *args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 1:
            return real(self, fname, *args, **kwargs)
        Path(fname).write_bytes(b"")  # the file created, nothing in it: then the disk is full
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(Figure, "savefig", savefig)
    plots = tmp_path / "plots"
    code, _stdout, err = run_cli(
        monkeypatch, capsys, "sweep", "plot", str(store), "--out", str(plots)
    )
    assert code == 1 and err.startswith("error: no space left on the device writing ")
    files = sorted(plots.iterdir())
    assert len(files) == 1 and files[0].stat().st_size > 0 and files[0].suffix == ".png"
    named = err.split("writing ")[1].split(":")[0].strip("'")
    assert Path(named).parent == plots and Path(named).suffix == ".png"
    assert not Path(named).exists()
