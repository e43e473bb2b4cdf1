"""A store that cannot be written (a full disk mid-sweep or while the store is created, a quota,
a read-only file system) stops the sweep with one line that says how many chunks are stored
and what to do, never a traceback; the stored chunks are kept and the same run continues. A
system error elsewhere is one line too, with its errno's words and its file."""

from __future__ import annotations

import errno
import json
import os
import sys

import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.cli import _system_error_line
from impactlab.sweep import Study, open_sweep, run_sweep
from impactlab.sweep.backends import StoreWriteError
from impactlab.sweep.chunkfiles import ChunkWriter

STUDY = (
    '[study]\nname = "b"\nchunk_size = 4\n[fixed]\nangle = "20 deg"\nvy = -1.41\n'
    "[grid]\nmu = { start = 0.05, stop = 0.6, num = 20 }\n"
)


def _full_after(monkeypatch, chunks: int) -> None:
    """The chunk writer fails with ENOSPC from its (chunks+1)-th chunk on."""
    real = ChunkWriter.write
    calls = {"n": 0}

    def write(self, items):
        calls["n"] += 1
        if calls["n"] > chunks:
            path = os.path.join(self.root, "e", "c.9")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), path)
        return real(self, items)

    monkeypatch.setattr(ChunkWriter, "write", write)


@pytest.mark.parametrize("backend", ["threads", "processes"])
def test_a_full_disk_mid_sweep_is_one_line_and_the_run_resumes(
    tmp_path, monkeypatch, capsys, backend
) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FakeEvaluator())
    (tmp_path / "b.toml").write_text(STUDY)
    _full_after(monkeypatch, 2)
    args = ("sweep", "b.toml", "--out", "b.zarr", "-q", "--backend", backend, "--workers", "1")
    code, out, err = run_cli(monkeypatch, capsys, *args)
    assert code == 1 and out == ""
    assert err == (
        "error: no space left on the device writing 'b.zarr' (2 of 5 chunks stored; nothing "
        "stored is lost): free space and run the same command again\n"
    )
    monkeypatch.undo()  # space freed: the same command continues
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FakeEvaluator())
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "b.toml", "--out", "b.zarr", "--json")
    assert code == 0, err
    assert json.loads(out)["chunks_resumed"] == 2
    assert (open_sweep(tmp_path / "b.zarr")["status"].values == 0).all()


def test_the_python_error_is_an_os_error_naming_what_is_kept(tmp_path, monkeypatch) -> None:
    (tmp_path / "b.toml").write_text(STUDY)
    study = Study.from_toml(tmp_path / "b.toml")
    _full_after(monkeypatch, 3)
    with pytest.raises(StoreWriteError) as caught:
        run_sweep(study, tmp_path / "b.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert isinstance(caught.value, OSError) and caught.value.errno == errno.ENOSPC
    assert "(3 of 5 chunks stored; nothing stored is lost)" in str(caught.value)
    monkeypatch.undo()
    again = run_sweep(study, tmp_path / "b.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_before == 3 and again.stats.chunks_computed == 2


def test_a_full_disk_while_the_store_is_created_is_one_line(tmp_path, monkeypatch, capsys) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FakeEvaluator())
    (tmp_path / "b.toml").write_text(STUDY)

    def full(path, *args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path / "zarr.json"))

    monkeypatch.setattr("impactlab.sweep.store.build_store", full)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "b.toml", "--out", "b.zarr", "-q")
    assert code == 1 and out == ""
    assert err == (
        "error: no space left on the device writing 'b.zarr' (while creating it: nothing "
        "stored yet): free space and run the same command again\n"
    )


def test_a_programming_error_keeps_its_traceback(tmp_path, monkeypatch, capsys) -> None:
    """Only an OSError becomes one line: a bug in the writer stays visible."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FakeEvaluator())
    (tmp_path / "b.toml").write_text(STUDY)

    def broken(self, items):
        raise TypeError("a bug")

    monkeypatch.setattr(ChunkWriter, "write", broken)
    monkeypatch.setattr(sys, "argv", ["impactlab", "sweep", "b.toml", "--out", "b.zarr", "-q"])
    from impactlab.cli import main

    with pytest.raises(TypeError, match="a bug"):
        main()


@pytest.mark.parametrize(
    ("code", "line"),
    [
        (
            errno.ENOSPC,
            "no space left on the device writing 'x.csv': free space and run the command again",
        ),
        (
            errno.EDQUOT,
            "disk quota exceeded writing 'x.csv': free space (or raise the quota) and run the "
            "command again",
        ),
        (
            errno.EROFS,
            "read-only file system writing 'x.csv': make it writable (or write elsewhere) and "
            "run the command again",
        ),
        (errno.EIO, f"{os.strerror(errno.EIO)}: 'x.csv'"),
    ],
)
def test_a_system_error_is_one_line_with_its_file(code, line) -> None:
    assert _system_error_line(OSError(code, os.strerror(code), "x.csv")) == line


def test_the_cli_prints_a_system_error_in_one_line(tmp_path, monkeypatch, capsys) -> None:
    """An OSError outside a sweep (here: while the store is written) exits 1 with one line."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "b.toml").write_text(STUDY)

    def fail(*args, **kwargs):
        raise OSError(errno.EIO, os.strerror(errno.EIO), "b.zarr/zarr.json")

    monkeypatch.setattr("impactlab.sweep.runner.run_sweep", fail)
    monkeypatch.setattr("impactlab.sweep.run_sweep", fail)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "b.toml", "-q")
    assert code == 1 and out == ""
    assert err == f"error: {os.strerror(errno.EIO)}: 'b.zarr/zarr.json'\n"
