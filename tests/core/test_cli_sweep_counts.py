"""``impactlab sweep run/info --json`` write counts as integers (docs/json-schema.md):
``"flagged": {"total": N, "<flag>": n}``, ``"chunks_done"``/``"chunks_total"``; the tables keep
their texts. A cheap evaluator stands in for the engine."""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab._json import shape_problems
from impactlab.cli.sweep_summary import flagged_json, run_summary
from impactlab.sweep import Study, run_sweep
from impactlab.sweep.summary import flagged_text, format_flag_counts

CliMain = Callable[..., tuple[int, str, str]]


class FlagEvaluator:
    """e = 0.5 everywhere; energy gain (flag 1) where mu > 0.4, law extrapolated (flag 4)
    everywhere."""

    identity = "flag-counts-evaluator/1"

    def output_fields(self) -> tuple[str, ...]:
        return ("e", "flags")

    def status_messages(self) -> dict[int, str]:
        return {0: "ok"}

    def regimes(self) -> dict[int, str]:
        return {0: "slip"}

    def integer_outputs(self) -> tuple[str, ...]:
        return ("flags",)

    def validate(self, categories: Mapping[str, Sequence[str]]) -> None:
        return None

    def __call__(self, cases: Any, statics: Any, outputs: Sequence[str]) -> Any:
        mu = np.asarray(cases["mu"], dtype=float)
        out = {"e": np.full(mu.shape, 0.5), "flags": (np.where(mu > 0.4, 1, 0) | 4).astype(float)}
        return {k: out[k] for k in outputs}, np.zeros(mu.shape, dtype=np.int32)


@pytest.fixture
def finished(tmp_path: Path) -> Any:
    """A finished sweep of 7 cases in one chunk: 2 with energy gain, all law-extrapolated."""
    study = Study(
        name="counts",
        chunk_size=10,
        grid={"mu": np.linspace(0.0, 0.6, 7)},
        fixed={"angle": 0.4, "vy": -1.41},
        outputs=["e"],
    )
    return run_sweep(study, tmp_path / "counts.zarr", evaluator=FlagEvaluator(), quiet=True)


def test_info_json_counts_are_integers(cli_main: CliMain, finished: Any) -> None:
    code, out, err = cli_main("sweep", "info", str(finished.path), "--json")
    assert code == 0, err
    data = json.loads(out)
    assert shape_problems(data) == []
    assert data["chunks_done"] == 1 and data["chunks_total"] == 1
    assert data["flagged"] == {"total": 7, "not_ok": 2, "energy_gain": 2, "law_extrapolated": 7}
    code, table, _ = cli_main("sweep", "info", str(finished.path))
    assert code == 0 and "1 of 1" in table and "2 case(s) not ok" in table


def test_run_summary_json_counts_are_integers(finished: Any) -> None:
    summary = run_summary(finished, finished.dataset, None, [], as_json=True)
    assert summary["flagged"] == {"total": 7, "not_ok": 2, "energy_gain": 2, "law_extrapolated": 7}
    assert summary["throughput"] == pytest.approx(7 / finished.stats.wall_s)
    assert summary["cases_computed"] == 7
    text = run_summary(finished, finished.dataset, None, [], as_json=False)
    assert text["flagged"] == (
        "2 case(s) not ok (energy gain: 2); advisory (the result stays ok): "
        "law extrapolated: 7; 7 flagged in all"
    )


@pytest.mark.parametrize(
    "counts",
    [
        {"flagged": 0, "energy gain": 0},
        {"flagged": 1234, "energy gain": 1000, "gravity-dominated": 234, "other end": 0},
    ],
)
def test_flag_text_is_that_of_the_counts_json(counts: dict[str, int]) -> None:
    assert flagged_text(flagged_json(counts)) == format_flag_counts(counts)


def test_flag_counts_in_json_use_the_result_flag_names() -> None:
    """The same names as ``ResultFlag``, ``flag_names`` and a store's ``flag_meanings``."""
    counts = {"flagged": 3, "gravity-dominated": 1, "beyond the tip": 2, "law extrapolated": 3}
    want = {"total": 3, "gravity_dominated": 1, "beyond_tip": 2, "law_extrapolated": 3}
    assert flagged_json(counts) == want
