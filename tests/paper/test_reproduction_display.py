"""A reproduction's repr and notebook summary: the folder, the report, the published numbers
reproduced / undecided / not reproduced and the simulated impacts beyond their law's range,
never the tables (conftest.py: one run of each kind)."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

from impactlab.paper import reproduction as R
from impactlab.paper.quantities import comparison_counts, count_extrapolated, verdict_counts


def _counts(res: R.ReproductionResult) -> str:
    bad, _ = comparison_counts(res.comparison)
    good, undecided = verdict_counts(res.comparison)
    return f"published numbers: {good} reproduced, {undecided} undecided, {bad} not reproduced"


def test_full_reproduction_repr_is_a_short_summary(full_reproduction) -> None:
    res = full_reproduction
    text = repr(res)
    n, m = count_extrapolated(res.simulations)
    assert m > 0 and text.startswith(f"ReproductionResult({res.out_dir}: report.html; ")
    assert f"{_counts(res)}; " in text
    assert f"simulated impacts: {n} of {m} beyond their law's verified range; " in text
    assert re.search(r"; time: [\d.]+ s\)$", text) and f"files: {len(res.files)};" in text
    assert len(text) < 300 and "\n" not in text and "DataFrame" not in text
    assert "[3 rows" not in text and "array(" not in text and "mappingproxy" not in text


def test_analytic_reproduction_says_what_was_not_compared(analytic_reproduction) -> None:
    res = analytic_reproduction
    _, skipped = comparison_counts(res.comparison)
    text = repr(res)
    assert skipped > 0 and f"{_counts(res)}, {skipped} not compared; " in text
    assert "simulated impacts: none (simulations not run)" in text and len(text) < 300


def test_reproduction_html_links_the_report_and_escapes(analytic_reproduction) -> None:
    res = analytic_reproduction
    page = res._repr_html_()
    assert f"<a href='{res.report_html.as_uri()}'>report.html</a>" in page
    assert "published numbers</th><td>" in page and "<table>" in page and len(page) < 1500
    odd = replace(res, out_dir=Path("a<b>&c"), report_html=Path("a<b>&c/report.html"))
    page = odd._repr_html_()
    assert "<td>a&lt;b&gt;&amp;c</td>" in page and "<b>" not in page
    assert "<a href='a&lt;b&gt;&amp;c/report.html'>report.html</a>" in page  # relative: as given
