"""A file written whole or not at all (impactlab._files)."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab._files import write_bytes_atomic, write_text_atomic


def test_writes_the_text_and_leaves_no_temporary_file(tmp_path: Path) -> None:
    target = tmp_path / "results.json"
    write_text_atomic(target, '{"e": 0.42}\n')
    assert target.read_text() == '{"e": 0.42}\n'
    assert [p.name for p in tmp_path.iterdir()] == ["results.json"]


def test_replaces_an_existing_file(tmp_path: Path) -> None:
    target = tmp_path / "m.csv"
    target.write_text("old\n")
    write_text_atomic(target, "new\n")
    assert target.read_text() == "new\n"


def test_a_failed_write_leaves_the_old_file_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "m.csv"
    target.write_text("label,e\nd1,0.4\n")

    def full_disk(*args: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr("impactlab._files.os.replace", full_disk)
    with pytest.raises(OSError, match="No space left"):
        write_bytes_atomic(target, b"label,e\nd1,0.4\nd2,0.")
    assert target.read_text() == "label,e\nd1,0.4\n"
    assert [p.name for p in tmp_path.iterdir()] == ["m.csv"]


def test_a_read_only_file_is_refused_as_open_would(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``os.replace`` would replace a write-protected file without asking; a file this user may
    not write (``os.access``, as ``open`` decides) is refused and kept."""
    target = tmp_path / "results.json"
    target.write_text("{}\n")
    monkeypatch.setattr("impactlab._files.os.access", lambda path, mode: False)
    with pytest.raises(PermissionError):
        write_text_atomic(target, '{"e": 1}\n')
    assert target.read_text() == "{}\n"
    assert [p.name for p in tmp_path.iterdir()] == ["results.json"]


def test_the_replaced_file_keeps_its_permissions(tmp_path: Path) -> None:
    target = tmp_path / "m.csv"
    target.write_text("old\n")
    target.chmod(0o640)
    write_text_atomic(target, "new\n")
    assert target.stat().st_mode & 0o777 == 0o640


def test_a_link_is_written_through(tmp_path: Path) -> None:
    """A measurements file kept as a link into a shared data folder: the data file is written
    and the link stays a link (``os.replace`` on the link would have split them)."""
    data = tmp_path / "data"
    data.mkdir()
    real = data / "drops.csv"
    real.write_text("label,e\nd1,0.4\n")
    link = tmp_path / "drops.csv"
    link.symlink_to(real)
    write_text_atomic(link, "label,e\nd1,0.4\nd2,0.5\n")
    assert link.is_symlink()
    assert real.read_text() == "label,e\nd1,0.4\nd2,0.5\n"
    assert sorted(p.name for p in data.iterdir()) == ["drops.csv"]
