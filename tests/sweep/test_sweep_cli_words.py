"""The first word of ``impactlab sweep``: a mistyped subcommand is named as one (not read as a
study file), and a store's own contact laws come back on resume without ``--law-file``."""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr
from sweep_fakes import run_cli

from impactlab.contact import law_names, unregister_law
from impactlab.contact._common import jg_critical
from impactlab.materials import AISI_201, AISI_1010, ContactPair

SUBCOMMANDS = "subcommands: run, uncertainty, info, plot, export (impactlab sweep --help)"


@pytest.mark.parametrize(
    ("word", "meant"),
    [("infoo", "info"), ("rn", "run"), ("plt", "plot"), ("exprt", "export"), ("uncertanty", None)],
)
def test_a_mistyped_subcommand_is_named(tmp_path, monkeypatch, capsys, word, meant) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", word, "big.zarr")
    assert code == 2 and out == ""
    meant = meant or "uncertainty"
    assert err == (
        f"error: no subcommand {word!r} (did you mean {meant!r}?) and no study file of that "
        f"name; {SUBCOMMANDS}\n"
    )


def test_a_study_file_named_like_a_subcommand_still_runs(tmp_path, monkeypatch, capsys) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "rn").write_text("[fixed]\nangle = '20 deg'\nvy = -1.41\n[grid]\nmu = [0.1]\n")
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "rn", "--out", "rn.zarr", "-q")
    assert code == 0, err
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "study.toml")  # no file, no near word
    assert code == 2 and err == "error: study file 'study.toml' does not exist\n"


STUDY = "[fixed]\nangle = '20 deg'\nvy = -1.41\n[grid]\nmu = [0.1]\n"


def test_an_options_value_is_not_read_as_a_subcommand(tmp_path, monkeypatch, capsys) -> None:
    """``--out runs``: ``runs`` (near ``run``) is the value of ``--out``, not a mistyped word."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.toml").write_text(STUDY)
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "--out", "runs", "bad.toml", "-q")
    assert code == 0, err
    assert (tmp_path / "runs" / "zarr.json").is_file()
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "--netcdf", "exports", "bad.toml")
    assert code == 2
    assert err.startswith("error: --netcdf 'exports' must end in .nc or .nc4 (NetCDF-4)")
    code, _, err = run_cli(
        monkeypatch, capsys, "sweep", "-q", "--netcdf", "exports.nc", "-o", "x.zarr", "bad.toml"
    )
    assert code == 0, err
    assert (tmp_path / "exports.nc").is_file()


def test_a_mistyped_subcommand_after_options_is_named(tmp_path, monkeypatch, capsys) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "--out", "x.zarr", "rn")
    assert code == 2 and out == ""
    assert err.startswith("error: no subcommand 'rn' (did you mean 'run'?)")


NAME = "sweep-measured"


def _law_file(folder) -> str:
    """A law from synthetic 'measured' curves of the paper's pair (Hertz to delta_c, then
    F ~ delta^1.2)."""
    pair = ContactPair(AISI_201, AISI_1010)
    dc, fc = jg_critical(pair.E_star, 8.8e-3, pair.yield_strength, pair.nu)
    d = dc * np.geomspace(1.0, 300.0, 40)
    dm = dc * np.geomspace(1.0, 300.0, 20)
    np.savetxt(folder / "loading.csv", np.c_[d, fc * (d / dc) ** 1.2], delimiter=",",
               header="delta,F")  # fmt: skip
    np.savetxt(folder / "unloading.csv", np.c_[dm, 0.6 * dm * (1.0 - np.sqrt(dc / dm))],
               delimiter=",", header="delta_max,delta_r")  # fmt: skip
    lines = {
        "name": NAME,
        "body_material": "aisi-201",
        "flat_material": "aisi-1010",
        "radius": "8.8 mm",
        "loading": "loading.csv",
        "unloading": "unloading.csv",
    }
    path = folder / "law.toml"
    path.write_text("".join(f"{k} = {json.dumps(v)}\n" for k, v in lines.items()))
    return str(path)


@pytest.fixture
def forget_law():
    yield
    if NAME in law_names():
        unregister_law(NAME)


@pytest.mark.usefixtures("engine", "forget_law")
def test_a_resume_without_the_law_file_uses_the_stored_law(tmp_path, monkeypatch, capsys):
    law = _law_file(tmp_path)
    study = tmp_path / "s.toml"
    study.write_text(
        f"[study]\nchunk_size = 1\n[fixed]\nlaw = '{NAME}'\nangle = '40 deg'\nmu = 0.1\n"
        "[grid]\nvy = ['-1.4 m/s', '-2 m/s']\n"
    )
    store = tmp_path / "s.zarr"
    args = ("sweep", "run", str(study), "--out", str(store), "-q")
    code, _, err = run_cli(monkeypatch, capsys, "--law-file", law, *args)
    assert code == 0, err
    first = xr.open_zarr(store)["e"].values.copy()
    unregister_law(NAME)  # a new process: the law is not registered
    (store / ".sweep" / "done" / "1").unlink()  # one chunk to compute again
    code, _, err = run_cli(monkeypatch, capsys, *args)
    assert code == 0, err
    np.testing.assert_array_equal(xr.open_zarr(store)["e"].values, first)
    unregister_law(NAME)
    code, _, err = run_cli(monkeypatch, capsys, *args[:3], "--out", str(tmp_path / "new.zarr"))
    last = err.splitlines()[-1]  # after the chunk size's warning
    assert code == 2 and last.startswith(f"error: unknown contact law {NAME!r}")  # a new store
    own = f"a law of your own: impactlab --law-file FILE, or {NAME} = 'FILE' in the study's"
    assert last.endswith(f"{own} [laws] table")
