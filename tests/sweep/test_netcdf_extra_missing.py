"""Without the optional netCDF4 package, NetCDF export is refused in one line naming the extra
to install, and ``sweep run --netcdf`` says so before the study runs (the whole sweep ran,
then a traceback of xarray's ModuleNotFoundError)."""

from __future__ import annotations

import sys

import pytest
from sweep_fakes import run_cli

from impactlab._validation import MissingExtraError
from impactlab.sweep.netcdf import require_netcdf

STUDY = "[fixed]\nangle = '20 deg'\nvy = -1.41\n[grid]\nmu = [0.1, 0.2]\n"
SAID = "NetCDF export needs the netCDF4 package, an optional extra: pip install 'impactlab[netcdf]'"


@pytest.fixture
def no_netcdf(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "netCDF4", None)  # import netCDF4 raises ImportError


def test_the_missing_extra_is_named(no_netcdf: None) -> None:
    with pytest.raises(MissingExtraError) as caught:
        require_netcdf()
    assert str(caught.value).startswith(SAID)
    assert issubclass(MissingExtraError, ImportError) and issubclass(MissingExtraError, ValueError)


def test_sweep_run_says_it_before_the_study_runs(tmp_path, monkeypatch, capsys, no_netcdf) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.chdir(tmp_path)
    (tmp_path / "s.toml").write_text(STUDY)
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "-q", "--netcdf", "s.nc", "-o", "s.zarr", "s.toml"
    )
    assert code == 2 and out == "" and err.startswith(f"error: {SAID}") and err.count("\n") == 1
    assert not (tmp_path / "s.zarr").exists() and not (tmp_path / "s.nc").exists()


def test_sweep_export_says_it_in_one_line(tmp_path, monkeypatch, capsys) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.chdir(tmp_path)
    (tmp_path / "s.toml").write_text(STUDY)
    assert run_cli(monkeypatch, capsys, "sweep", "-q", "-o", "s.zarr", "s.toml")[0] == 0
    monkeypatch.setitem(sys.modules, "netCDF4", None)
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", "s.zarr", "s.nc")
    assert code == 2 and err.startswith(f"error: {SAID}") and err.count("\n") == 1
    assert run_cli(monkeypatch, capsys, "sweep", "export", "s.zarr", "s.csv")[0] == 0


def test_the_fe_mesh_without_gmsh_names_its_extra(monkeypatch: pytest.MonkeyPatch) -> None:
    from impactlab.fe.mesh import build_mesh

    monkeypatch.setitem(sys.modules, "gmsh", None)
    with pytest.raises(MissingExtraError, match=r"pip install 'impactlab\[fe\]'"):
        build_mesh(None)  # type: ignore[arg-type]
