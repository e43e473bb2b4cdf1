"""An engine option or the law's parameters given to a study as an input (``fixed={"gravity":
False}``, as ``simulate_batch`` takes it) is refused with where it goes instead; a
dimensionless input's error says "a plain number" (formerly "unknown input 'gravity'" alone,
and "a number in 1")."""

from __future__ import annotations

import re
from typing import Any

import pytest

from impactlab.sweep import EngineOptions, Study

BASE: dict[str, Any] = {"mu": 0.1, "angle": 0.3}


@pytest.mark.parametrize(
    ("option", "value"),
    [("gravity", False), ("rtol", 1e-8), ("constant_angle", True), ("partial_slip_cells", 8)],
)
@pytest.mark.parametrize("where", ["fixed", "grid"])
def test_an_engine_option_points_to_engine_options(option: str, value: object, where: str) -> None:
    table: dict[str, Any] = {"fixed": {**BASE, option: value}, "grid": {"vy": [-1.0]}}
    if where == "grid":
        table = {"fixed": BASE, "grid": {"vy": [-1.0], option: [value]}}
    with pytest.raises(ValueError, match=(
        rf"unknown input '{option}': {option} is an engine option of the whole study, not an "
        rf"input: Study\(engine=EngineOptions\({option}=\.\.\.\)\) in Python, {option} under "
        r"\[engine\] in a study file; known inputs: angle, "
    )):  # fmt: skip
        Study(name="s", **table)


def test_the_hinted_spelling_runs() -> None:
    study = Study(name="s", grid={"vy": [-1.0]}, fixed=BASE, engine=EngineOptions(gravity=False))
    assert study.engine.gravity is False


def test_law_params_point_to_the_study_argument() -> None:
    fixed: dict[str, Any] = {**BASE, "law_params": {}}
    with pytest.raises(ValueError, match=(
        r"unknown input 'law_params': a study takes the contact law's parameters as "
        r"Study\(law_params=\{\.\.\.\}\) in Python, the \[law_params\] table in a study file"
    )):  # fmt: skip
        Study(name="s", grid={"vy": [-1.0]}, fixed=fixed)


def test_a_study_file_names_the_engine_table() -> None:
    with pytest.raises(ValueError, match=r"\[fixed\] unknown input 'gravity': .* \[engine\]"):
        Study.from_dict({"study": {"name": "s"}, "grid": {"vy": [-1.0]},
                         "fixed": {"mu": 0.1, "angle": "20 deg", "gravity": 0}})  # fmt: skip


@pytest.mark.parametrize("value", [True, None, [0.1]])
def test_a_dimensionless_input_asks_for_a_plain_number(value: Any) -> None:
    with pytest.raises(
        ValueError, match=re.escape(f"input 'mu' must be a plain number, got {value!r}")
    ):
        Study(name="s", grid={"vy": [-1.0]}, fixed={"angle": 0.3, "mu": value})


def test_an_input_with_a_unit_still_names_it() -> None:
    with pytest.raises(ValueError, match=r"input 'vy' must be a number in m/s, got True"):
        Study(name="s", grid={"mu": [0.1]}, fixed={"angle": 0.3, "vy": True})
