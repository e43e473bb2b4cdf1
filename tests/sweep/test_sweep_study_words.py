"""What a study and the sweep tutorial tell a reader: a study's counts in the singular where
there is one case or one chunk, an input spelt as ``simulate`` spells it, and the tutorial's
(and the example's) filter of the cases not to read as plain success, which an advisory flag
alone does not select."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from impactlab.flags import ResultFlag
from impactlab.sweep import Study

ROOT = Path(__file__).resolve().parents[2]


def test_a_study_counts_one_case_and_one_chunk_in_the_singular() -> None:
    one = Study(name="one", grid={"angle": [0.3]}, fixed={"vy": -1.41, "mu": 0.2})
    assert "Study('one', grid, 1 case in 1 chunk; " in repr(one)
    assert "grid: 1 case in 1 chunk; " in one._repr_html_()
    two = Study(name="two", grid={"angle": [0.3, 0.4]}, fixed={"vy": -1.41, "mu": 0.2})
    assert "2 cases in 1 chunk; " in repr(two)


def _tutorial_filter() -> str:
    """The tutorial's lines that build ``ok`` from the DataFrame of a store."""
    text = (ROOT / "docs" / "tutorials" / "sweep.md").read_text(encoding="utf-8")
    assert 'df["flags"] > 0]' not in text  # selects every law-extrapolated case
    code = (ln.split("#")[0] for ln in text.splitlines() if "ADVISORY_FLAGS" in ln)
    lines = [ln for ln in code if ln.startswith(("from impactlab.flags import", "ok = "))]
    assert len(lines) == 2, lines
    return "\n".join(lines)


def test_the_tutorial_filters_the_cases_not_ok() -> None:
    extrapolated, gain = int(ResultFlag.LAW_EXTRAPOLATED), int(ResultFlag.ENERGY_GAIN)
    beyond = int(ResultFlag.BEYOND_TIP)
    df = pd.DataFrame(
        {
            "status": np.array([0, 0, 0, 0, 7], dtype=np.int32),
            "flags": np.array(
                [0, extrapolated, gain | extrapolated, beyond | extrapolated, -1], dtype=np.int16
            ),
        }
    )
    scope: dict[str, object] = {"df": df}
    exec(_tutorial_filter(), scope)
    not_ok = df[~scope["ok"]]  # type: ignore[operator]
    assert not_ok.index.tolist() == [2, 3, 4]


def test_the_example_leaves_the_cases_not_ok_out_of_its_boundary() -> None:
    text = (ROOT / "examples" / "sweep_study.py").read_text(encoding="utf-8")
    assert re.search(r"ok = .*status.* == 0\).*ADVISORY_FLAGS", text)
    assert "(regime[i] == stick) & ok[i]" in text and "not ok" in text


@pytest.mark.parametrize(
    ("name", "hint"),
    [("velocity", "as vx and vy (or speed and incidence)"), ("spin_in", "name for it is spin")],
)
def test_an_input_spelt_as_simulate_spells_it_says_the_study_name(name, hint) -> None:
    """simulate(velocity=...) is a study's vx and vy: the refusal says so, not only the list."""
    with pytest.raises(ValueError, match=rf"unknown input '{name}': .*{re.escape(hint)}"):
        Study(name="x", grid={"mu": [0.1]}, fixed={name: (0.0, -1.41), "vy": -1.41})
