"""The output folder of :func:`analyze`: only files that an analysis wrote are removed or
written over; a user's file of the same name is left as it is, with a warning or the stage's
error."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

from impactlab.experiment import analyze
from impactlab.experiment.saving import MARK, written_by_analyze

from .conftest import GEOMETRY_TOML

CliMain = Callable[..., tuple[int, str, str]]
PHOTO = b"my photo"


def test_a_users_figure_is_never_removed(tmp_path: Path, drops: dict) -> None:
    """'removed dent.png, left by an earlier run' deleted a file that no run had written."""
    (tmp_path / "dent.png").write_bytes(PHOTO)
    d = drops[20]
    res = analyze(d.c3d, tmp_path / "nonexist.x3p", geometry=d.geometry, out_dir=tmp_path)
    assert (tmp_path / "dent.png").read_bytes() == PHOTO
    (note,) = [w for w in res.warnings if "dent.png" in w]
    assert "was not written by impactlab analyze: it is left as it is" in note
    assert "removed" not in note


def test_a_users_figure_is_never_written_over(tmp_path: Path, drops: dict, scans: dict) -> None:
    (tmp_path / "dent.png").write_bytes(PHOTO)
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], geometry=d.geometry, out_dir=tmp_path)
    assert (tmp_path / "dent.png").read_bytes() == PHOTO
    assert res.dent is not None and "dent" not in res.figures
    assert "not written" in res.errors["figures"] and "dent.png" in res.errors["figures"]
    assert not [w for w in res.warnings if "dent.png" in w]  # said once, as the error
    assert written_by_analyze(tmp_path / "kinematics.png")


def test_a_users_results_json_is_never_written_over(tmp_path: Path, drops: dict) -> None:
    (tmp_path / "results.json").write_text('{"mine": 1}')
    d = drops[20]
    res = analyze(d.c3d, None, geometry=d.geometry, out_dir=tmp_path)
    assert json.loads((tmp_path / "results.json").read_text()) == {"mine": 1}
    assert "not written" in res.errors["results"] and "results" not in res.files


def test_a_figure_of_an_earlier_run_is_still_removed(
    tmp_path: Path, drops: dict, scans: dict, cli_main: CliMain
) -> None:
    d = drops[20]
    first = analyze(d.c3d, scans[20].files["x3p"], geometry=d.geometry, out_dir=tmp_path)
    assert set(first.figures) == {"kinematics", "dent"}
    assert written_by_analyze(tmp_path / "dent.png")
    assert MARK.encode() in (tmp_path / "dent.png").read_bytes()[:4096]
    assert written_by_analyze(tmp_path / "results.json")
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    code, _, err = cli_main("analyze", str(d.c3d), "nonexist.x3p", "--geometry", str(geo),
                            "--out", str(tmp_path))  # fmt: skip
    assert code == 2 and not (tmp_path / "dent.png").exists()
    assert "removed" in err and "dent.png" in err and "left by an earlier run" in err


def test_an_unreadable_or_other_file_is_not_taken_for_a_run(tmp_path: Path) -> None:
    png = tmp_path / "dent.png"
    png.write_bytes(b"\x89PNG\r\n\x1a\n" + b"\x00" * 30)
    assert not written_by_analyze(png)
    assert not written_by_analyze(tmp_path / "absent.png")
    folder = tmp_path / "kinematics.png"
    folder.mkdir()
    assert not written_by_analyze(folder)
