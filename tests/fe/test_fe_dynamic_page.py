"""docs/fe-dynamic.md shows what the code prints: each case's comparison table is
``comparison_markdown`` of its default laws, verbatim, and the example's quoted rows are
those its code prints (from the shipped tables: no CalculiX needed)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from impactlab.fe.impact_reference import IMPACT_CASES
from impactlab.verification.fe_impact import add_law, compare_impacts, comparison_markdown

PAGE = Path(__file__).resolve().parents[2] / "docs" / "fe-dynamic.md"


@pytest.fixture(scope="module")
def page() -> str:
    return PAGE.read_text()


@pytest.mark.parametrize("case", list(IMPACT_CASES))
def test_each_table_is_the_printed_one(page, case):
    assert comparison_markdown(compare_impacts(case)) in page


def test_the_example_prints_the_rows_it_quotes(page):
    block = page[page.index('comp = compare_impacts("paper-ball-on-aisi1010")') :]
    block = block[: block.index("```")]
    quoted = re.findall(r"^# (\| .+ \|)$", block, flags=re.M)
    assert len(quoted) == 2
    comp = compare_impacts("paper-ball-on-aisi1010")
    add_law(comp, "tabulated")
    printed = comparison_markdown(comp).splitlines()
    assert all(row in printed for row in quoted)
