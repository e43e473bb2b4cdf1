"""A changed study's differences print two different values so that they read differently
(0.13 -> 0.1300001, not 0.13 -> 0.13), and values that read differently at 6 significant
digits keep their short form."""

from __future__ import annotations

from pathlib import Path

import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import Study, run_sweep
from impactlab.sweep.repair import study_differences
from impactlab.sweep.store import StudyMismatchError


def _study(mu: float, grid: list[float] | None = None) -> Study:
    return Study(name="d", chunk_size=4, fixed={"angle": 0.35, "vy": -1.41, "mu": mu},
                 grid={"vx": grid or [0.0, 0.1]})  # fmt: skip


@pytest.mark.parametrize(
    ("old", "new", "text"),
    [
        (0.13, 0.1300001, "fixed.mu: 0.13 -> 0.1300001"),
        (0.1, 0.1 + 2**-55, "fixed.mu: 0.1 -> 0.10000000000000003"),
        (0.13, 0.14, "fixed.mu: 0.13 -> 0.14"),
        (1e-7, 1.0000001e-7, "fixed.mu: 1e-07 -> 1.0000001e-07"),
    ],
)
def test_close_values_read_differently(old: float, new: float, text: str) -> None:
    diff = study_differences(_study(old).to_dict(), _study(new).to_dict())
    assert diff == [text]
    a, b = diff[0].split(": ")[1].split(" -> ")
    assert a != b


def test_grid_ends_and_short_lists_too() -> None:
    many = [0.1 * i for i in range(6)]
    moved = [*many[:-1], many[-1] + 1e-9]
    diff = study_differences(_study(0.2, many).to_dict(), _study(0.2, moved).to_dict())
    assert diff == ["grid.vx stop: 0.5 -> 0.500000001"]
    diff = study_differences(_study(0.2, [0.0, 0.13]).to_dict(),
                             _study(0.2, [0.0, 0.1300001]).to_dict())  # fmt: skip
    assert diff == ["grid.vx: 0, 0.13 -> 0, 0.1300001"]


def test_the_refusal_names_them(tmp_path: Path) -> None:
    store = tmp_path / "d.zarr"
    run_sweep(_study(0.13), store, evaluator=FakeEvaluator(), quiet=True)
    with pytest.raises(StudyMismatchError, match=r"\(fixed\.mu: 0\.13 -> 0\.1300001; "):
        run_sweep(_study(0.1300001), store, evaluator=FakeEvaluator(), quiet=True)
