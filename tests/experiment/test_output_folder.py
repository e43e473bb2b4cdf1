"""The output folder of :func:`analyze`: only files that an analysis wrote are removed or
written over; a user's file of the same name is left as it is, with a warning or the stage's
error."""

from __future__ import annotations

import json
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab.experiment import FileFormatError, analyze
from impactlab.experiment.saving import MARK, written_by_analyze

from .conftest import GEOMETRY_TOML

CliMain = Callable[..., tuple[int, str, str]]
PHOTO = b"my photo"


def test_a_users_figure_is_never_removed(
    tmp_path: Path, drops: dict, junk: dict[str, Path]
) -> None:
    """'removed dent.png, left by an earlier run' deleted a file that no run had written."""
    (tmp_path / "dent.png").write_bytes(PHOTO)
    d = drops[20]
    res = analyze(d.c3d, junk["x3p"], geometry=d.geometry, out_dir=tmp_path)
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


@pytest.fixture(scope="module")
def earlier_run(analysed_drop: Callable[[int], tuple[Any, Path]]) -> Path:
    """The output folder of one analysis of drop 20 and its dent (both figures, results.json;
    conftest.py), shared by the tests below, which work on copies of it."""
    first, out = analysed_drop(20)
    assert set(first.figures) == {"kinematics", "dent"} and "results" in first.files
    return out


def _first_run(out: Path, earlier_run: Path) -> dict[str, bytes]:
    """Copy the earlier run's folder to ``out``; return its files' contents by name."""
    shutil.copytree(earlier_run, out, dirs_exist_ok=True)
    return {p.name: p.read_bytes() for p in out.iterdir()}


def test_a_figure_of_an_earlier_run_is_still_removed(
    tmp_path: Path, drops: dict, earlier_run: Path, cli_main: CliMain, junk: dict[str, Path]
) -> None:
    d = drops[20]
    assert set(_first_run(tmp_path, earlier_run)) == {"kinematics.png", "dent.png", "results.json"}
    assert written_by_analyze(tmp_path / "dent.png")
    assert MARK.encode() in (tmp_path / "dent.png").read_bytes()[:4096]
    assert written_by_analyze(tmp_path / "results.json")
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    code, _, err = cli_main("analyze", str(d.c3d), str(junk["x3p"]), "--geometry", str(geo),
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


# -- damaged files of an earlier run, a folder checked before anything is written ----------------


def test_a_results_json_cut_short_by_an_earlier_run_is_replaced(
    tmp_path: Path, drops: dict, scans: dict, earlier_run: Path
) -> None:
    """A results.json cut short (an interrupted run) blocked re-analysis as 'not written by
    impactlab analyze', after the new figures had been written."""
    before = _first_run(tmp_path, earlier_run)
    (tmp_path / "results.json").write_bytes(before["results.json"][:300])
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], geometry=d.geometry, out_dir=tmp_path)
    assert res.ok, res.errors
    saved = json.loads((tmp_path / "results.json").read_text())
    assert saved["summary"]["sliding_length"]["value"] > 0
    (note,) = [w for w in res.warnings if "results.json" in w]
    assert note.startswith("results: ") and "is replaced: it is cut short" in note
    (tmp_path / "results.json").write_bytes(b"")  # empty: nothing to lose either
    res = analyze(d.c3d, None, geometry=d.geometry, out_dir=tmp_path)
    assert "results" in res.files and any("it is empty" in w for w in res.warnings)


def test_a_users_results_json_leaves_the_whole_folder_as_it_was(
    tmp_path: Path, drops: dict, scans: dict, earlier_run: Path
) -> None:
    before = _first_run(tmp_path, earlier_run)
    (tmp_path / "results.json").write_text('{"mine": 1}')
    before["results.json"] = b'{"mine": 1}'
    d = drops[45]
    res = analyze(d.c3d, None, geometry=d.geometry, out_dir=tmp_path)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before
    assert "not written" in res.errors["results"] and not res.figures
    figures = res.errors["figures"]
    assert "results.json" in figures and "nothing in the folder" in figures


def test_a_misspelt_input_path_leaves_the_folder_as_it_was(
    tmp_path: Path, drops: dict, scans: dict, earlier_run: Path, cli_main: CliMain
) -> None:
    """A scan path that names no file removed the earlier run's dent figure and rewrote
    results.json without delta_p, L_s, T and F."""
    out = tmp_path / "out"
    before = _first_run(out, earlier_run)
    d = drops[20]
    with pytest.raises(FileFormatError) as caught:
        analyze(d.c3d, tmp_path / "dnet.x3p", geometry=d.geometry, out_dir=out)
    assert "dnet.x3p: no such file (scan_path); nothing was read or written" in str(caught.value)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    for args, name in (((str(d.c3d), "dnet.x3p"), "SCAN"), (("drpo.c3d", str(d.c3d)), "MARKERS")):
        code, _, err = cli_main("analyze", *args, "--geometry", str(geo), "--out", str(out))
        assert code == 2 and f"no such file ({name}); nothing was read or written" in err
        assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    code, _, _ = cli_main("analyze", str(d.c3d), "dnet.x3p", "--out", str(tmp_path / "new"))
    assert code == 2 and not (tmp_path / "new").exists()
    with pytest.raises(FileFormatError, match=r"not a file \(markers_path\)"):
        analyze(tmp_path, None)


def test_results_json_is_written_whole_or_not_at_all(
    tmp_path: Path, drops: dict, scans: dict, earlier_run: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    before = _first_run(tmp_path, earlier_run)

    def full_disk(fd: int) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr("impactlab._files.os.fsync", full_disk)
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], geometry=d.geometry, out_dir=tmp_path)
    assert "No space left on device" in res.errors["figures"]  # the first file staged
    assert "see figures" in res.errors["results"]
    assert (tmp_path / "results.json").read_bytes() == before["results.json"]
    assert not [p.name for p in tmp_path.iterdir() if p.name not in before]  # nothing partial


def _full_disk_for(monkeypatch: pytest.MonkeyPatch, names: tuple[str, ...]) -> None:
    """Make every write of a file whose name holds one of ``names`` fail as on a full disk."""
    from impactlab.experiment import saving

    real = saving.write_bytes_atomic

    def write(path: Path, data: bytes) -> None:
        if any(n in Path(path).name for n in names):
            raise OSError(28, "No space left on device")
        real(path, data)

    monkeypatch.setattr(saving, "write_bytes_atomic", write)


def test_a_full_disk_leaves_the_folder_as_it_was(
    tmp_path: Path, drops: dict, scans: dict, earlier_run: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The figures fitted on the disk and results.json did not: the folder held the new figures
    beside the old results.json of another drop."""
    before = _first_run(tmp_path, earlier_run)
    _full_disk_for(monkeypatch, ("results.json",))
    d = drops[45]
    res = analyze(d.c3d, scans[45].files["x3p"], geometry=d.geometry, out_dir=tmp_path)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before
    assert "No space left on device" in res.errors["results"]
    assert "nothing in the folder was written or removed" in res.errors["results"]
    assert "could not be (see results)" in res.errors["figures"]
    assert not res.figures and "results" not in res.files
    assert res.kinematics is not None and res.dent is not None  # what was measured is kept


def test_a_rerun_on_a_full_disk_removes_no_figure(
    tmp_path: Path,
    drops: dict,
    scans: dict,
    earlier_run: Path,
    junk: dict[str, Path],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """It deleted both earlier figures, saying 'this run drew no kinematics figure' of one it
    drew but could not write."""
    before = _first_run(tmp_path, earlier_run)
    _full_disk_for(monkeypatch, ("kinematics.png",))
    d = drops[20]
    res = analyze(d.c3d, junk["x3p"], geometry=d.geometry, out_dir=tmp_path)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before
    assert "kinematics.png" in res.errors["figures"] and "No space left" in res.errors["figures"]
    assert "see figures" in res.errors["results"]
    assert not [w for w in res.warnings if "removed" in w]


def test_every_figure_error_is_kept(tmp_path: Path, drops: dict, scans: dict) -> None:
    """Only the last figure's error was kept."""
    (tmp_path / "dent.png").write_bytes(PHOTO)
    (tmp_path / "kinematics.png").mkdir()
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], geometry=d.geometry, out_dir=tmp_path)
    error = res.errors["figures"]
    assert "dent.png" in error and "kinematics.png" in error and "a folder" in error
    assert (tmp_path / "dent.png").read_bytes() == PHOTO and not res.figures
    assert written_by_analyze(tmp_path / "results.json")
