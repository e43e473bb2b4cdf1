"""A rename that fails after another file was renamed into place left a mixed folder while the
message said that nothing in it was written or removed: the files replaced are moved aside
first and put back."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from impactlab.experiment import saving


def _failing_second_rename(monkeypatch: pytest.MonkeyPatch) -> None:
    real = os.replace
    count = [0]

    def flaky(src: os.PathLike[str] | str, dst: os.PathLike[str] | str) -> None:
        if str(src).endswith(".new"):
            count[0] += 1
            if count[0] == 2:
                raise OSError(5, "Input/output error")
        real(src, dst)

    monkeypatch.setattr(saving.os, "replace", flaky)


def test_a_failed_rename_leaves_the_folder_as_it_was(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    a, b, c = tmp_path / "a.png", tmp_path / "b.png", tmp_path / "results.json"
    a.write_bytes(b"old a")
    b.write_bytes(b"old b")  # c is new
    _failing_second_rename(monkeypatch)
    with pytest.raises(saving._WriteError) as caught:
        saving._swap_in({a: b"new a", c: b"new c", b: b"new b"})
    assert caught.value.path == c and not caught.value.mixed
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png", "b.png"]
    assert a.read_bytes() == b"old a" and b.read_bytes() == b"old b"


def test_a_file_that_cannot_be_put_back_is_named(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    a, b = tmp_path / "a.png", tmp_path / "b.png"
    a.write_bytes(b"old a")
    b.write_bytes(b"old b")
    real = os.replace

    def flaky(src: os.PathLike[str] | str, dst: os.PathLike[str] | str) -> None:
        if str(src).endswith(".old") or (str(src).endswith(".new") and Path(dst) == b):
            raise OSError(5, "Input/output error")
        real(src, dst)

    monkeypatch.setattr(saving.os, "replace", flaky)
    with pytest.raises(saving._WriteError) as caught:
        saving._swap_in({a: b"new a", b: b"new b"})
    assert caught.value.path == b
    assert set(caught.value.mixed) == {a, b}
    assert a.read_bytes() == b"new a"  # replaced, and the error says so


def test_a_figure_that_cannot_be_staged_is_the_figures_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from impactlab.experiment.result import ExperimentResult

    res = ExperimentResult(None, None)
    monkeypatch.setattr(saving, "_drawn", lambda r: {"dent": b"png"})

    def refuse(path: Path, data: bytes) -> None:
        if "dent" in path.name:
            raise OSError(13, "Permission denied")
        path.write_bytes(data)

    monkeypatch.setattr(saving, "write_bytes_atomic", refuse)
    saving.save_outputs(res, tmp_path)
    assert "dent.png" in res.errors["figures"] and "Permission denied" in res.errors["figures"]
    assert "see figures" in res.errors["results"] and "dent.png" not in res.errors["results"]
    assert not list(tmp_path.iterdir())
