"""Paths on the command line get one line naming the option (or argument) and the path as
given: a folder where a file is expected, a file where a folder is, a missing or unwritable
folder, a missing store, a folder given as an input file; never an ``[Errno]`` text or a
temporary path. Also: ``--from`` names what it reads, ``analyze`` warns on stderr."""

from __future__ import annotations

import errno
import json
from collections.abc import Callable
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.cli import analyze as analyze_cli
from impactlab.cli import output_paths
from impactlab.sweep import Study, run_sweep

CliMain = Callable[..., tuple[int, str, str]]


class ConstantEvaluator:
    """e = 0.5 in every case (a stand-in for the engine)."""

    identity = "constant-evaluator/1"

    def output_fields(self) -> tuple[str, ...]:
        return ("e",)

    def status_messages(self) -> dict[int, str]:
        return {0: "ok"}

    def regimes(self) -> dict[int, str]:
        return {0: "slip"}

    def integer_outputs(self) -> tuple[str, ...]:
        return ()

    def validate(self, categories: object) -> None:
        return None

    def __call__(
        self, cases: dict[str, np.ndarray], statics: object, outputs: list[str]
    ) -> tuple[dict[str, np.ndarray], np.ndarray]:
        mu = np.asarray(cases["mu"], dtype=float)
        return {"e": np.full(mu.shape, 0.5)}, np.zeros(mu.shape, dtype=np.int32)


@pytest.fixture
def store(tmp_path: Path) -> Path:
    study = Study(name="paths", chunk_size=10, grid={"mu": [0.1, 0.2]},
                  fixed={"angle": 0.4, "vy": -1.41})  # fmt: skip
    return run_sweep(study, tmp_path / "s.zarr", evaluator=ConstantEvaluator(), quiet=True).path


def _one_error(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert "Errno" not in err and "Traceback" not in err
    return lines[0]


def test_export_to_a_folder(cli_main: CliMain, store: Path, tmp_path: Path) -> None:
    code, _, err = cli_main("sweep", "export", str(store), str(tmp_path))
    assert code == 2
    assert _one_error(err) == (
        f"error: target {str(tmp_path)!r} is a folder: give the name of the file to write, "
        "ending in .csv (CSV), .nc or .nc4 (NetCDF-4)"
    )
    code, _, err = cli_main("sweep", "export", str(store), str(tmp_path / "no" / "x.nc"))
    assert code == 2 and "the folder" in _one_error(err) and "does not exist" in err


def test_plot_into_a_file(cli_main: CliMain, store: Path, tmp_path: Path) -> None:
    afile = tmp_path / "afile"
    afile.write_text("")
    code, _, err = cli_main("sweep", "plot", str(store), "--out", str(afile))
    assert code == 2 and f"--out {str(afile)!r} exists and is not a folder" in _one_error(err)


def test_run_store_inside_a_file(cli_main: CliMain, tmp_path: Path) -> None:
    study = tmp_path / "study.toml"
    study.write_text('[fixed]\nangle = "20 deg"\nvy = "-1.41 m/s"\n[grid]\nmu = [0.1, 0.2]\n')
    afile = tmp_path / "afile"
    afile.write_text("")
    code, _, err = cli_main("sweep", "run", str(study), "--out", str(afile / "x.zarr"))
    assert code == 2 and f"is inside {str(afile)!r}, a file" in _one_error(err)
    code, _, err = cli_main("sweep", "run", str(study), "--netcdf", str(tmp_path / "no" / "x.nc"))
    assert code == 2 and _one_error(err).startswith("error: --netcdf ")


def test_unwritable_folder_names_the_option_not_a_temporary_path(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    def refuse(**kwargs: object) -> str:
        raise OSError(errno.ENOENT, "No such file or directory", "/x/.s.zarr.creating-1")

    monkeypatch.setattr(output_paths.tempfile, "mkdtemp", refuse)
    with pytest.raises(output_paths.UserError) as err:
        output_paths.output_store(tmp_path / "s.zarr", "--out")
    text = str(err.value)
    assert text.startswith(f"--out {str(tmp_path / 's.zarr')!r}: cannot create the store in ")
    assert "creating" not in text and "Errno" not in text


def test_missing_store_and_file_store(cli_main: CliMain, tmp_path: Path) -> None:
    code, _, err = cli_main("sweep", "info", str(tmp_path / "nothere.zarr"))
    assert code == 2
    assert (
        _one_error(err) == f"error: sweep store {str(tmp_path / 'nothere.zarr')!r} does not exist"
    )
    afile = tmp_path / "afile"
    afile.write_text("")
    code, _, err = cli_main("sweep", "info", str(afile))
    assert code == 2 and "is a file, not a sweep store" in _one_error(err)


def test_input_files_name_their_option(cli_main: CliMain, tmp_path: Path) -> None:
    code, _, err = cli_main("invert", "--file", str(tmp_path))
    assert code == 2
    assert _one_error(err) == f"error: --file {str(tmp_path)!r} is a folder: give a TOML file"
    missing = str(tmp_path / "nothere.toml")
    for option in ("--geometry", "--rod"):
        code, _, err = cli_main("analyze", "m.c3d", "s.npy", option, missing)
        assert code == 2
        assert _one_error(err) == f"error: {option} {missing!r} does not exist"


def test_from_names_what_it_reads(cli_main: CliMain, tmp_path: Path) -> None:
    other = tmp_path / "other.json"
    other.write_text(json.dumps({"a": 1}))
    code, _, err = cli_main("simulate", "--from", str(other))
    assert code == 2
    line = _one_error(err)
    assert "'impactlab simulate ... --json'" in line and "'impactlab drop ... --json'" in line
    assert ">= 0.3" not in line and "the file records no impact" in line


def test_analyze_warnings_go_to_stderr(capsys: pytest.CaptureFixture[str]) -> None:
    res = SimpleNamespace(
        summary=dict,
        kinematics=None,
        dent=None,
        model=None,
        markers_path="drop.c3d",
        scan_path="dent.npy",
        warnings=["scan: delta_p = 22 nm is shallower than 0.1 um"],
        figures={},
        files={},
    )
    analyze_cli._print_summary(res)  # type: ignore[arg-type]
    out, err = capsys.readouterr()
    assert "shallower" not in out
    assert err == "warning: scan: delta_p = 22 nm is shallower than 0.1 um\n"
