"""A flexible rod's drop defines no regime: its finished cases hold -1 in a store's ``regime``,
the integer outputs' "no result" value, so the sweep's page says -1 means "no result, or no
regime" (it said a status != 0 only; ``test_sweep_flexible`` checks the values)."""

from __future__ import annotations

import re
from pathlib import Path

SWEEP_PAGE = Path(__file__).resolve().parents[2] / "docs" / "sweep.md"


def _text() -> str:
    return re.sub(r"\s+", " ", SWEEP_PAGE.read_text(encoding="utf-8"))


def test_the_page_says_minus_one_is_no_result_or_no_regime() -> None:
    text = _text()
    assert "-1: no result, or no regime: a flexible rod's drop, finished with status 0" in text
    assert '`regime == -1` means "no result, or no regime"; tell them apart by `status`' in text
