"""``invert``'s sign rules as its docstring and docs/api/analytic.md state them: the
magnitudes of the tip velocity v_i and of sliding_length are taken (the paper prints both
negative), a negative delta_p is refused."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pytest

from impactlab import invert

PAPER = {"angle": math.radians(20), "e": 0.5, "mu": 0.2, "n_samples": 200}
API = Path(__file__).resolve().parents[2] / "docs" / "api" / "analytic.md"


def _run(**kw: float) -> tuple[float, float]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = invert(**PAPER, **kw)  # type: ignore[arg-type]
    return r.duration, r.mean_force


def test_the_signs_of_v_i_and_sliding_length_are_ignored() -> None:
    base = _run(v_i=-1.41, delta_p=22e-6, sliding_length=1400e-6)
    assert _run(v_i=-1.41, delta_p=22e-6, sliding_length=-1400e-6) == base
    assert _run(v_i=1.41, delta_p=22e-6, sliding_length=-1400e-6) == base
    with pytest.raises(ValueError, match="delta_p must be >= 0"):
        _run(v_i=-1.41, delta_p=-22e-6, sliding_length=1400e-6)


def test_the_docstring_and_the_api_page_state_that_rule() -> None:
    doc = " ".join((invert.__doc__ or "").split())
    line = doc[doc.index("sliding_length : ") : doc.index(" e : coefficient")]
    assert "> 0" not in line
    assert "sign ignored" in line and "the magnitude is taken" in line
    page = " ".join(API.read_text(encoding="utf-8").split())
    assert "takes the magnitudes of `v_i` and `sliding_length`" in page
    assert "the paper's -22e-6 is refused" in page
