"""Refusals of a store a run cannot continue, in one line that says why and what to do: a store
on a read-only file system (its lock cannot be created), a changed study over a partial store
(the differences named), a first word of ``impactlab sweep`` that is no subcommand and no
file (the subcommands listed)."""

from __future__ import annotations

import errno
import os

import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Study, run_sweep
from impactlab.sweep.repair import study_differences
from impactlab.sweep.store import StudyMismatchError

SUBCOMMANDS = "subcommands: run, uncertainty, info, plot, export (impactlab sweep --help)"


def _study(**changes) -> Study:
    args = {
        "name": "b",
        "chunk_size": 4,
        "fixed": {"angle": 0.35, "vy": -1.41},
        "grid": {"mu": [0.05 * (i + 1) for i in range(12)]},
    }
    return Study(**{**args, **changes})


@pytest.mark.parametrize(
    ("code", "why"),
    [
        (errno.EROFS, "read-only file system"),
        (errno.EACCES, "no permission for this user"),
    ],
)
def test_a_store_whose_lock_cannot_be_made_is_refused_naming_it(
    tmp_path, monkeypatch, capsys, code, why
) -> None:
    monkeypatch.chdir(tmp_path)
    run_sweep(_study(), "b.zarr", evaluator=FakeEvaluator(), quiet=True)

    def cannot(lock):
        raise OSError(code, os.strerror(code), str(lock))

    monkeypatch.setattr("impactlab.sweep.locking.write_lock", cannot)
    with pytest.raises(ValueError, match="a run cannot write it") as caught:
        run_sweep(_study(), "b.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert str(caught.value) == (
        f"store 'b.zarr': {why}, so a run cannot write it (not even its lock file "
        f"'b.zarr/.sweep/lock'); impactlab sweep info, export and plot read it as it is "
        f"(open_sweep in Python); to compute more, copy it to a writable place and run the "
        f"study there"
    )
    code_, out, err = run_cli(monkeypatch, capsys, "sweep", "info", "b.zarr")  # still read
    assert code_ == 0 and "chunks_done" in out, err


def test_a_changed_study_names_its_differences(tmp_path) -> None:
    store = tmp_path / "b.zarr"
    run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    mu = [0.05 * (i + 1) for i in range(11)] + [0.7]
    changed = _study(chunk_size=3, grid={"mu": mu}, description="now described")
    with pytest.raises(StudyMismatchError) as caught:
        run_sweep(changed, store, evaluator=FakeEvaluator(), quiet=True)
    assert str(caught.value) == (
        f"store {str(store)!r} holds a different study (chunk_size: 4 -> 3; grid.mu stop: 0.6 "
        "-> 0.7; the store's -> this study's, in SI units): its chunks cannot serve this study; "
        "undo the changes to resume it, run with --restart (restart=True in Python) to discard "
        "it and start fresh, or choose another --out (another store path)"
    )


def test_many_differences_are_cut_short() -> None:
    old = _study().to_dict()
    new = _study(
        name="c",
        chunk_size=5,
        fixed={"angle": 0.4, "vy": -1.5, "vx": 0.2, "law": "hertz"},
        grid={"mu": [0.1 * (i + 1) for i in range(7)]},
    ).to_dict()
    diff = study_differences(old, new)
    assert diff[:3] == ["chunk_size: 4 -> 5", "name: b -> c", "grid.mu: 12 -> 7 values"]
    assert "fixed.vx: not set -> 0.2" in diff and "fixed.vy: -1.41 -> -1.5" in diff
    assert len(diff) > 5  # the message names 4 of them, then "and N more"


def test_only_the_description_and_max_cases_differ_nothing(tmp_path) -> None:
    """Neither is part of the study's hash: the store resumes (no difference to name)."""
    store = tmp_path / "b.zarr"
    run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    again = run_sweep(_study(description="other words", max_cases=1000), store,
                      evaluator=FakeEvaluator(), quiet=True)  # fmt: skip
    assert again.stats.chunks_computed == 0
    assert study_differences(_study().to_dict(), _study(description="x").to_dict()) == []


def test_reordered_grid_is_named() -> None:
    a = _study(grid={"mu": [0.1, 0.2], "vy": [-1.0, -2.0]}, fixed={"angle": 0.35}).to_dict()
    b = _study(grid={"vy": [-1.0, -2.0], "mu": [0.1, 0.2]}, fixed={"angle": 0.35}).to_dict()
    assert study_differences(a, b) == ["grid order: mu, vy -> vy, mu"]


@pytest.mark.parametrize(
    ("word", "near"),
    [("summary", " (did you mean 'info'?)"), ("nosuch", ""), ("infoo", " (did you mean 'info'?)")],
)
def test_a_first_word_that_is_no_subcommand_and_no_file_lists_them(
    tmp_path, monkeypatch, capsys, word, near
) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", word, "big.zarr")
    assert code == 2 and out == ""
    assert err == (
        f"error: no subcommand {word!r}{near} and no study file of that name; {SUBCOMMANDS}\n"
    )
