"""docs/fe.md's level-1 figures of the paper's pair at 1000 delta_c are the shipped run's: F,
the final gap, the bracket of the force's zero crossing, and (level 1 first in the mesh study)
delta_r read at the first unloading point of zero force."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "src" / "impactlab" / "fe" / "data" / "paper-aisi201-on-aisi1010.v1.json"


def _run() -> dict:
    runs = json.loads(DATA.read_text())["runs"]
    return next(r for r in runs if r["delta_max_over_delta_c"] == 1000.0)


def _text() -> str:
    return " ".join((ROOT / "docs" / "fe.md").read_text().split())


def _groups(pattern: str, text: str) -> tuple[str, ...]:
    found = re.search(pattern, text)
    assert found is not None, pattern
    return found.groups()


def test_level_1_final_gap_and_bracket() -> None:
    run, text = _run(), _text()
    d = np.array(run["unloading"]["delta"]) / run["delta_max"]
    F = np.array(run["unloading"]["force"])
    zero = int(np.argmax(np.abs(F) < 1e-6 * run["max_force"]))  # first point of zero force
    gap, lo, hi = _groups(
        r"= ([\d.]+) \(the final gap; the unloading force's zero crossing bracketed it between "
        r"([\d.]+) and ([\d.]+)\)",
        text,
    )
    assert float(gap) == round(run["residual_ratio"], 3)
    assert float(lo) == round(d[zero], 3) and float(hi) == round(d[zero - 1], 3)
    assert float(lo) <= float(gap) <= float(hi)


def test_mesh_study_gives_level_1_first() -> None:
    run, text = _run(), _text()
    d = np.array(run["unloading"]["delta"]) / run["delta_max"]
    F = np.array(run["unloading"]["force"])
    zero = int(np.argmax(np.abs(F) < 1e-6 * run["max_force"]))
    f1, _f2, r1, r2, pct = _groups(
        r"F\(\\delta_\{max\}\)\$ ([\d.]+) kN against ([\d.]+) kN \(\*\*1\.4 %\*\*\), "
        r"\$\\delta_r/\\delta_\{max\}\$ ([\d.]+) against ([\d.]+) \(\*\*([\d.]+) %\*\*",
        text,
    )
    assert float(f1) == round(run["max_force"] / 1e3, 2)  # level 1 first: the shipped run
    assert run["n_elements"] == 2324 and "(2 324 elements) against level 2" in text
    assert float(r1) == round(d[zero], 4)  # 0.8828, not the 0.8795 it used to say
    assert float(pct) == round(100 * abs(float(r1) / float(r2) - 1), 1)
