"""A drop's rtol has a range of its own, [1e-13, 1e-5], whatever its friction model: a study
with a flexible rod and a looser rtol is refused, as ``simulate_drop`` refuses it, and the
engine page says so (not that a drop takes the rigid engine's whole range)."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab.dynamics.input_checks import DROP_RTOL_MAX
from impactlab.sweep import Study, run_sweep

ENGINE_PAGE = Path(__file__).resolve().parents[2] / "docs" / "engine" / "index.md"


def test_a_drop_study_looser_than_the_drop_range_is_refused(tmp_path: Path) -> None:
    table = {
        "fixed": {"body": "flexible_rod", "angle": "20 deg", "vy": -1.41, "mu": 0.2},
        "grid": {"friction": ["coulomb", "mindlin"]},
        "engine": {"rtol": 1e-4},
    }
    loose = r"\[engine\] rtol 0\.0001 is too loose for a flexible rod's drop \(allowed: up to 1e-05"
    with pytest.raises(ValueError, match=loose):
        run_sweep(Study.from_dict(table), tmp_path / "d.zarr", quiet=True)


def test_the_engine_page_gives_the_drop_range_for_every_friction_model() -> None:
    text = " ".join(ENGINE_PAGE.read_text().split())
    assert DROP_RTOL_MAX == 1e-5
    said = "and so has a drop with any other friction model: a drop's range is [1e-13, 1e-5]"
    assert said in text
    assert "takes the whole range" not in text
