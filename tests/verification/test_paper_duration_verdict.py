"""The verification page's paper-T row gives the reproduction's verdict over the printed digits
(20 deg UNDECIDED), and says that its pass checks the nominal value only."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab import verification as V
from impactlab.paper.analytic_rows import experimental_rows
from impactlab.paper.quantities import PASS, UNDECIDED, duration_checks
from impactlab.verification.page import anchor

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def table() -> V.VerificationTable:
    return V.verify_paper_durations(200)


def test_rows_carry_the_reproductions_range_and_verdict(table: V.VerificationTable) -> None:
    by_angle = {int(r["angle"]): r for r in table.records}
    for check in duration_checks(experimental_rows()):
        row = by_angle[check.angle_deg]
        assert row["verdict"] == check.verdict
        assert (row["low"], row["high"]) == pytest.approx(check.range, rel=1e-9)
    assert by_angle[20]["verdict"] == UNDECIDED and by_angle[45]["verdict"] == PASS
    assert by_angle[20]["low"] < -0.05 < by_angle[20]["err_T"] < by_angle[20]["high"]
    assert by_angle[70]["verdict"] is None  # the paper prints no T at 70 deg


def test_the_nominal_check_says_so(table: V.VerificationTable) -> None:
    assert table.passed  # nominal -4.5 % within 5 %, and no verdict FAIL
    assert "at the printed values" in table.metric and "20 deg UNDECIDED" in table.metric
    text = " ".join(table.text.split())
    assert "**This row checks the nominal value only**" in text
    assert "At 20 deg it is **UNDECIDED**" in text
    md = table.to_markdown()
    assert "| 20 |" in md and "| -5.7% | -3.3% | UNDECIDED |" in md


def test_a_fail_verdict_fails_the_row(monkeypatch: pytest.MonkeyPatch) -> None:
    import impactlab.verification.durations as D

    # a T 20 % too short at the extremes of the rounding: FAIL, though the nominal T is used
    monkeypatch.setattr(D, "duration_range", lambda x: (0.5e-3, 0.6e-3))
    assert not D.verify_paper_durations(200).passed


def test_published_page_and_analytic_md_agree(table: V.VerificationTable) -> None:
    page = (ROOT / "docs" / "verification" / "index.md").read_text()
    assert table.to_markdown() in page
    assert f"| [{table.title}](#{anchor(table.title)}) | {table.metric} |" in page
    analytic = " ".join((ROOT / "docs" / "analytic.md").read_text().split())
    r20 = next(r for r in table.records if r["angle"] == 20.0)
    r45 = next(r for r in table.records if r["angle"] == 45.0)
    assert f"it spans {r20['low'] * 100:.1f} % to {r20['high'] * 100:.1f} % at 20 deg" in analytic
    assert f"{r45['low'] * 100:.1f} % to {r45['high'] * 100:+.1f} % at 45 deg (PASS)" in analytic
    assert "whether 20 deg meets 5 % is UNDECIDED" in analytic
    assert "meets both within 5 %" not in analytic
