"""``impactlab sweep export`` and ``--netcdf``: the file's suffix chooses its format (a CSV table
for ``.csv``, NetCDF-4 for ``.nc``/``.nc4``); any other suffix is refused in one line."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import (
    Normal,
    Sample,
    Study,
    Uniform,
    export_csv,
    export_file,
    export_netcdf,
    run_sweep,
)
from impactlab.sweep.inputs import INPUTS


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """A 4-case store, run once for the module: the tests only read it."""
    study = Study(
        name="exp",
        grid={"angle": ["20 deg", "40 deg"], "mu": [0.1, 0.3]},
        fixed={"vy": -1.41, "law": "hertz"},
        outputs=["e", "delta_p", "regime"],
    )
    path = tmp_path_factory.mktemp("exp") / "exp.zarr"
    return run_sweep(study, path, evaluator=FakeEvaluator(), quiet=True).path


def test_csv_is_a_table_with_the_units_in_its_header(store, tmp_path, monkeypatch, capsys):
    target = tmp_path / "exp.csv"
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 0 and out.strip() == str(target), err
    assert not target.read_bytes().startswith(b"\x89HDF")
    table = pd.read_csv(target)
    assert len(table) == 4  # one row per case
    assert {"angle [rad]", "mu", "e", "delta_p [m]", "regime", "status", "law"} <= set(
        table.columns
    )
    assert (table["law"] == "hertz").all()
    ds = xr.open_zarr(store)
    np.testing.assert_array_equal(table["delta_p [m]"], ds["delta_p"].values.ravel())
    np.testing.assert_array_equal(table["angle [rad]"], np.repeat(ds["angle"].values, 2))


@pytest.mark.parametrize("suffix", [".nc", ".nc4", ".NC"])
def test_netcdf_for_nc_and_nc4(store, tmp_path, monkeypatch, capsys, suffix):
    target = tmp_path / f"exp{suffix}"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 0, err
    assert target.read_bytes().startswith(b"\x89HDF")
    with xr.open_dataset(target) as back:
        assert back["e"].shape == (2, 2)


@pytest.mark.parametrize("name", ["exp.txt", "exp", "out.zarr", "exp.csv.gz"])
def test_other_suffixes_are_refused_in_one_line(store, tmp_path, monkeypatch, capsys, name):
    target = tmp_path / name
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 2 and out == "" and not target.exists()
    assert err == (
        f"error: export file {str(target)!r} must end in .csv (CSV), .nc or .nc4 (NetCDF-4)\n"
    )


def test_netcdf_option_takes_a_netcdf_file_only(tmp_path, monkeypatch, capsys):
    study = tmp_path / "s.toml"
    study.write_text("[fixed]\nangle = '20 deg'\nvy = -1.41\n[grid]\nmu = [0.1, 0.2]\n")
    target = tmp_path / "x.csv"
    code, _, err = run_cli(
        monkeypatch, capsys, "sweep", "run", str(study), "--out", str(tmp_path / "s.zarr"),
        "--netcdf", str(target),
    )  # fmt: skip
    assert code == 2 and err.count("\n") == 1
    assert err.startswith(f"error: --netcdf {str(target)!r} must end in .nc or .nc4 (NetCDF-4)")
    assert "impactlab sweep export" in err
    assert not (tmp_path / "s.zarr").exists()  # refused before the study runs


def test_python_exports_check_the_suffix(store, tmp_path):
    from impactlab.sweep import open_sweep

    ds = open_sweep(store)
    with pytest.raises(ValueError, match=r"NetCDF file .* must end in \.nc or \.nc4"):
        export_netcdf(ds, tmp_path / "x.csv")
    with pytest.raises(ValueError, match=r"CSV file .* must end in \.csv \(CSV\)$"):
        export_csv(ds, tmp_path / "x.nc")
    assert export_file(ds, tmp_path / "x.csv").read_text().startswith("angle [rad],mu,e,")
    assert not list(tmp_path.glob(".*partial"))


@pytest.mark.parametrize("name", [".csv", ".nc", ".NC4"])
def test_a_suffix_alone_is_refused_as_a_file_without_a_name(
    store, tmp_path, monkeypatch, capsys, name
):
    target = tmp_path / name
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 2 and out == "" and not target.exists()
    example = str(tmp_path / f"out{name}")
    assert err == (
        f"error: export file {str(target)!r} needs a name before its suffix, e.g. {example!r}\n"
    )


def _export_in_a_new_process(store, target, hash_seed: str) -> bytes:
    """``impactlab sweep export`` in a fresh interpreter (its own string hashing)."""
    env = {**os.environ, "PYTHONHASHSEED": hash_seed}
    done = subprocess.run(
        [sys.executable, "-m", "impactlab", "sweep", "export", str(store), str(target)],
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    return target.read_bytes()


def test_the_csv_columns_come_in_a_fixed_order(tmp_path, monkeypatch, capsys):
    """The same bytes from interpreters with other string hashing: hash seeds 1 and 2 iterate a
    set of these column names (all of them, or the inputs alone) in different orders, seed 3
    also reverses the pair vx, vy against them, and this process has a seed of its own."""
    study = Study(
        name="order",
        grid={"angle": ["20 deg", "40 deg"], "mu": [0.1, 0.3]},
        fixed={"vy": -1.41, "law": "hertz"},
        sample=Sample(size=3, seed=1, inputs={"vx": Uniform(0.0, 0.5), "spin": Normal(0.0, 1.0)}),
        outputs=["regime", "e", "delta_p"],
    )
    store = run_sweep(study, tmp_path / "o.zarr", evaluator=FakeEvaluator(), quiet=True).path
    first = _export_in_a_new_process(store, tmp_path / "a.csv", "1")
    for seed in ("2", "3"):
        assert _export_in_a_new_process(store, tmp_path / f"b{seed}.csv", seed) == first
    code, _, err = run_cli(
        monkeypatch, capsys, "sweep", "export", str(store), str(tmp_path / "c.csv")
    )
    assert code == 0 and (tmp_path / "c.csv").read_bytes() == first, err
    header = first.decode().splitlines()[0].split(",")
    assert header[:7] == ["angle [rad]", "mu", "sample", "regime", "e", "delta_p [m]", "status"]
    inputs = [h.split(" [")[0] for h in header[7:]]
    assert inputs == sorted(inputs, key=list(INPUTS).index)
    assert {"vy [m/s]", "vx [m/s]", "spin [rad/s]", "law"} <= set(header[7:])
