"""``impactlab analyze ... --measurements FILE.csv --label NAME``: the analysed drop appended to
a measurements file for ``impactlab calibrate``; a drop without --flat in a file whose drops name
another flat is warned about; a file that cannot be written gets the analysis printed first, then
one error naming the measurements file (not its temporary file)."""

from __future__ import annotations

import errno
import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest

import impactlab.calibrate.measurement_append as append_module
from impactlab.calibrate import read_measurements

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"
ARGS = (
    "analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"), "--pixel-size", "12 um",
    "--height-unit", "um", "--up", "+y", "--geometry", str(DATA / "markers.toml"),
)  # fmt: skip

CliMain = Callable[..., tuple[int, str, str]]


def test_the_drop_is_appended_and_calibrate_reads_it(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "drops.csv"
    path.write_text(
        "# lab drops\nlabel,angle [deg],vy [m/s],mu,e,e_sigma\nold,45,-2,0.2,0.4,0.02\n"
    )
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d20")
    assert code == 0, err
    assert f"appended drop 'd20' to {path} (2 drops)" in err
    m = read_measurements(path)
    assert m.labels == ("old", "d20")
    assert {"e", "spin_out", "delta_p", "scar_length"} <= set(m.quantities)
    assert path.read_text().startswith("# lab drops\nlabel,angle [deg],vy [m/s],mu,e,e_sigma,")
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d20")
    assert code == 2 and "has a drop labelled 'd20' already: give another --label" in err
    code, _, err = cli_main(*ARGS, "--measurements", str(tmp_path / "d.toml"))
    assert code == 2 and "a drop is appended to a CSV file (.csv)" in err
    code, _, err = cli_main(*ARGS, "--label", "x")
    assert code == 2 and "give --measurements FILE.csv" in err


def test_a_result_that_is_not_ok_is_refused_unless_asked_for(
    tmp_path: Path, cli_main: CliMain
) -> None:
    rod = tmp_path / "rod.toml"
    rod.write_text(  # an inertia 100 times too small: a doubt
        '[rod]\nmass = 0.4607\nlength = "304.8 mm"\ntip_radius = "8.8 mm"\n'
        'inertia = "0.000035667 kg*m^2"\n'
    )
    path = tmp_path / "drops.csv"
    code, _, err = cli_main(*ARGS, "--rod", str(rod), "--measurements", str(path))
    assert code == 2
    assert "--measurements: nothing appended" in err and "is not ok (" in err
    assert "--include-doubtful" in err and not path.exists()
    code, _, err = cli_main(*ARGS, "--rod", str(rod), "--measurements", str(path),
                            "--include-doubtful")  # fmt: skip
    assert code == 0 and "appended though its analysis is not ok" in err
    assert read_measurements(path).labels == ("drop",)  # the marker file's name
    assert "# doubtful drop 'drop'" in path.read_text()


def test_the_help_shows_the_route_to_calibrate(tmp_path: Path, cli_main: CliMain) -> None:
    for cmd in ("analyze", "calibrate"):
        code, out, _ = cli_main(cmd, "--help")
        assert code == 0 and "Examples:" in out
        assert "--measurements drops.csv --label d20" in out
    (tmp_path / "results.json").write_text("{}")
    code, _, err = cli_main("calibrate", str(tmp_path / "results.json"), "-p", "mu=uniform(0, 1)")
    assert code != 0 and "impactlab analyze MARKERS SCAN --measurements" in err


def test_the_default_flat_is_named(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "drops.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma,flat_material\nd1,45,-2,0.2,0.4,0.02,aisi-304\n"
    )
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d2")
    assert code == 0, err
    assert (
        "drop 'd2' names no material of the flat and takes the default aisi-1010, while earlier "
        "drops name aisi-304: give --flat NAME (flat= in Python), or edit its flat_material field"
    ) in " ".join(err.split())
    assert [c["flat_material"] for c in read_measurements(path).categories] == [
        "aisi-304",
        "aisi-1010",
    ]


def test_no_warning_where_the_materials_agree(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "drops.csv"
    path.write_text("label,angle [deg],vy [m/s],mu,e,e_sigma\nd1,45,-2,0.2,0.4,0.02\n")
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d2")
    assert code == 0 and "names no material" not in err


@pytest.fixture
def read_only(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every write fails as on a read-only file system, naming the temporary file."""

    def refuse(path: object, data: bytes) -> None:
        partial = Path(str(path)).with_name(f".{Path(str(path)).name}.123.partial")
        raise OSError(errno.EROFS, "Read-only file system", str(partial))

    monkeypatch.setattr(append_module, "write_bytes_atomic", refuse)


@pytest.mark.parametrize("as_json", [False, True])
def test_the_analysis_is_shown_and_the_file_named(
    tmp_path: Path, cli_main: CliMain, read_only: None, as_json: bool
) -> None:
    """It printed nothing (the analysis lost) and named '.drops.csv.17816.partial'; a write
    that fails while the command works is the system's error, status 1."""
    path = tmp_path / "drops.csv"
    code, out, err = cli_main(*ARGS, "--measurements", str(path), *(["--json"] * as_json))
    assert code == 1  # the system's error while the command worked
    if as_json:
        assert json.loads(out)["ok"] is True
    else:
        assert "mean_force" in out and "sliding_length" in out
    lines = [x for x in err.splitlines() if x.startswith("error:")]
    assert lines == [
        f"error: read-only file system writing {str(path)!r}: make it writable (or write "
        "elsewhere) and run the command again"
    ], err
    assert ".partial" not in err and not path.exists()


def test_a_file_that_is_not_regular_is_refused_before_the_analysis(
    tmp_path: Path, cli_main: CliMain
) -> None:
    fifo = tmp_path / "drops.csv"
    os.mkfifo(fifo)
    code, out, err = cli_main(*ARGS, "--measurements", str(fifo))
    assert code == 2 and out == ""
    assert f"error: --measurements {str(fifo)!r} is not a regular file; give a CSV file" in err
    with pytest.raises(ValueError, match="is not a regular file"):  # before it reads
        append_module._append(fifo, None, None)  # type: ignore[arg-type]


def test_a_folder_that_cannot_be_written_is_refused_before_the_analysis(
    tmp_path: Path, cli_main: CliMain, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(os, "access", lambda path, mode: Path(path) != tmp_path)
    code, out, err = cli_main(*ARGS, "--measurements", str(tmp_path / "drops.csv"))
    assert code == 2 and out == ""
    assert "cannot be written (no permission for this user): choose another file" in err
