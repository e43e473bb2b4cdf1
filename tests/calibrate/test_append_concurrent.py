"""Drops appended to one measurements file by several processes at once are all kept (each read,
check and replace holds an exclusive lock on the file's folder), and a duplicate label is still
refused under the lock."""

from __future__ import annotations

import multiprocessing
import sys
from pathlib import Path

import pytest

from impactlab.calibrate import read_measurements
from impactlab.calibrate.measurement_append import append_record

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="fcntl locks (POSIX)")

PROCESSES, EACH = 6, 4


def _drop(label: str) -> dict[str, object]:
    return {"label": label, "angle": "20 deg", "vy": -1.4, "e": 0.5, "e_sigma": 0.01}


def _appender(path: str, who: int, start: object) -> None:
    start.wait()  # type: ignore[attr-defined]
    for i in range(EACH):
        append_record(path, _drop(f"p{who}-{i}"))


def test_concurrent_appends_keep_every_drop(tmp_path: Path) -> None:
    """Four analyses appending at once kept three drops, each reporting success."""
    path = tmp_path / "drops.csv"
    ctx = multiprocessing.get_context("fork")
    start = ctx.Barrier(PROCESSES)
    procs = [ctx.Process(target=_appender, args=(str(path), n, start)) for n in range(PROCESSES)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(120)
    assert [p.exitcode for p in procs] == [0] * PROCESSES
    labels = read_measurements(path).labels
    assert sorted(labels) == sorted(f"p{n}-{i}" for n in range(PROCESSES) for i in range(EACH))
    assert [p.name for p in tmp_path.iterdir()] == ["drops.csv"]  # no lock or partial file left


def test_the_label_check_runs_under_the_lock(tmp_path: Path) -> None:
    path = tmp_path / "drops.csv"
    append_record(path, _drop("d1"))
    append_record(path, _drop("d2"))
    with pytest.raises(ValueError, match="a drop labelled 'd1' is there already"):
        append_record(path, _drop("d1"))
    assert read_measurements(path).labels == ("d1", "d2")


def test_a_link_locks_the_folder_of_the_file_it_names(tmp_path: Path) -> None:
    (tmp_path / "data").mkdir()
    path = tmp_path / "data" / "drops.csv"
    (tmp_path / "link.csv").symlink_to(path)
    append_record(tmp_path / "link.csv", _drop("d1"))
    assert (tmp_path / "link.csv").is_symlink() and read_measurements(path).labels == ("d1",)
    assert [p.name for p in (tmp_path / "data").iterdir()] == ["drops.csv"]
