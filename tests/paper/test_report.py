"""The report's document model: one number formatter, a self-contained HTML page that fits
1280 px (tables scroll in their own box, images embedded and shrinkable), and Section 5 as one
table with each explanation written once."""

from __future__ import annotations

import base64
import dataclasses
import math
import re

import numpy as np
import pandas as pd
import pytest

from impactlab.paper import data as D
from impactlab.paper.analytic_rows import invert_case
from impactlab.paper.report import Figure, Para, Table, fmt, fmt_number, to_html, to_markdown
from impactlab.paper.report_reasons import not_reproduced

# the smallest valid PNG (1 x 1 pixel)
PNG = base64.b64decode(
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg=="
)


@pytest.mark.parametrize(
    ("x", "digits", "text"),
    [
        (10943.7, 4, "10940"),  # was 1.094e+04
        (0.12254, 4, "0.1225"),
        (-74.0, 4, "-74"),
        (0.25, 4, "0.25"),
        (2153.0, 4, "2153"),
        (9.99996, 4, "10"),
        (0.001, 4, "0.001"),
        (123456.7, 4, "123500"),
        (2e11, 4, "2\u00d710\u00b9\u00b9"),
        (7.6e8, 4, "7.6\u00d710\u2078"),
        (6.2051e-5, 3, "6.21\u00d710\u207b\u2075"),
        (999999.7, 4, "1\u00d710\u2076"),
        (0.0, 4, "0"),
        (math.nan, 4, "-"),
    ],
)
def test_one_number_format(x: float, digits: int, text: str) -> None:
    assert fmt_number(x, digits) == text
    assert fmt(x, digits) == text


def test_dois_are_links() -> None:
    page = to_html([Para("Source: the paper, doi:10.1007/s00419-015-1108-2. Everything")], "t")
    link = '<a href="https://doi.org/10.1007/s00419-015-1108-2">doi:10.1007/s00419-015-1108-2</a>.'
    assert link in page


def test_cells() -> None:
    assert (fmt(None), fmt(True), fmt(3), fmt("Table 2")) == ("-", "yes", "3", "Table 2")


def test_html_is_self_contained_and_fits(tmp_path) -> None:
    (tmp_path / "fig.png").write_bytes(PNG)
    wide = pd.DataFrame({f"column {i}": [1.0e4 + i, 0.5] for i in range(30)})
    blocks = [Para("text"), Table(wide, "wide"), Figure("fig.png", "a figure")]
    page = to_html(blocks, "t", base=tmp_path)
    srcs = re.findall(r'src="([^"]+)"', page)
    assert srcs == ["data:image/png;base64," + base64.b64encode(PNG).decode()]
    assert not re.search(r"(?:src|href)=\"(?:https?:)?//", page)  # nothing from the network
    assert "<script" not in page
    # a wide table scrolls inside its own box; images never exceed the text width
    assert '<div class="table-wrap"><table>' in page
    assert re.search(r"\.table-wrap \{[^}]*overflow-x: auto", page)
    assert re.search(r"img \{[^}]*max-width: 100%", page)
    assert "e+0" not in page and "10000" in page
    # without a base folder the figure is linked (the Markdown report does the same)
    assert 'src="fig.png"' in to_html(blocks, "t")
    assert "![a figure](fig.png)" in to_markdown(blocks, "t")


def _comparison() -> pd.DataFrame:
    """Four numbers not reproduced: two share an explanation up to their numbers, one comes from
    both friction models, one is explained differently; and one reproduced row."""
    why = "the published row is not self-consistent: its F T is {} times P"
    rows = [
        ("Table 2", ang, "ghaednia", fr, "T [ms]", pub, ours, ours / pub - 1, False, why.format(r))
        for ang, pub, ours, r in ((20, 0.25, 0.1225, 2.39), (45, 0.3, 0.1424, 2.44))
        for fr in ("impulse_ratio", "coulomb")
    ]
    rows.append(
        (
            "Table 3",
            45,
            "ghaednia",
            "impulse_ratio",
            "delta_p, paper's sign [um]",
            -67.0,
            -111.1,
            0.658,
            False,
            "copy error in the paper: Table 3 repeats Table 2",
        )
    )
    rows.append(("Table 2", 20, "brake", "coulomb", "e", 0.46, 0.441, -0.04, True, ""))
    cols = ["source", "angle [deg]", "model", "friction", "quantity", "published", "impactlab"]
    return pd.DataFrame(rows, columns=[*cols, "rel. diff", "reproduced", "reason"])


def test_section_5_is_a_table_with_each_explanation_once() -> None:
    blocks = not_reproduced(_comparison())
    tables = [b for b in blocks if isinstance(b, Table)]
    assert len(tables) == 1
    df = tables[0].df
    # one row per number (the two friction models' identical numbers once)
    assert len(df) == 3 and list(df["why"]) == ["A", "A", "B"]
    assert df["friction"].iloc[0] == "impulse_ratio, coulomb"
    assert list(df["rel. diff"]) == ["-51.0%", "-52.5%", "+65.8%"]
    text = to_markdown(blocks, "t")
    assert text.count("not self-consistent") == 1 and text.count("copy error") == 1
    assert (
        "A (2 rows: Table 2, 20 deg, ghaednia, T [ms]; Table 2, 45 deg, ghaednia, T [ms]; the "
        "numbers quoted are those of the first, each row's own are in comparison.csv)"
    ) in text  # it names every row it covers, not the first alone
    assert "B (1 row): " in text
    assert "2.39 times" in text


def test_section_5_without_misses() -> None:
    comp = _comparison()
    blocks = not_reproduced(comp[comp["reproduced"]])
    assert [b.text for b in blocks if isinstance(b, Para)] == ["None."]


@pytest.mark.parametrize(
    ("T_ms", "verdict"),
    [
        (1.382, "PASS"),
        (1.46, "PASS"),
        (1.466, "UNDECIDED"),
        (1.470005, "UNDECIDED"),
        (1.476, "FAIL"),
        (1.32, "FAIL"),
    ],
)
def test_a_duration_check_is_decided_over_the_published_rounding(T_ms, verdict) -> None:
    """1.40 ms stands for 1.395-1.405 ms: a T within 5 % of some of it and not of the rest is
    neither a PASS nor a FAIL."""
    from impactlab.paper.quantities import DurationCheck

    check = DurationCheck(45, T_ms, 1.40, T_ms / 1.40 - 1)
    assert check.verdict == verdict and check.ok == (verdict == "PASS")
    assert check.text().endswith(f"tolerance 5%): {verdict}")
    if T_ms == 1.470005:  # the overall-length reading's 45 deg T, its inputs taken as exact
        assert "(+5.0%; +4.6% to +5.4% over the printed digits, tolerance 5%)" in check.text()


def test_the_inputs_rounding_decides_the_verdict_too() -> None:
    """mu = 0.20 stands for 0.195-0.205 (and so on for every printed input): over that box the
    20 deg T lies -5.7 % to -3.3 % from the published 4.30 ms, across the 5 % tolerance, so the
    check is UNDECIDED, not PASS; the 45 deg one stays within it (PASS)."""
    from impactlab.paper.analytic_rows import INPUT_ROUNDING, duration_range, experimental_rows
    from impactlab.paper.quantities import duration_checks

    assert INPUT_ROUNDING["mu"] == 0.005
    c20, c45 = duration_checks(experimental_rows())
    assert c20.range == pytest.approx((-0.0568, -0.0332), abs=5e-4)
    assert c20.verdict == "UNDECIDED" and not c20.ok
    assert c20.text() == (
        "20 deg: T = 4.106 ms vs published 4.30 ms (-4.5%; -5.7% to -3.3% over the printed "
        "digits, tolerance 5%): UNDECIDED"
    )
    assert c45.verdict == "PASS"
    # the extremes lie at the corners: no T inside the box falls outside them
    rng = np.random.default_rng(1)
    x = D.EXPERIMENTS[20]
    lo, hi = duration_range(x)
    for _ in range(40):
        moved = {k: getattr(x, k) + h * rng.uniform(-1, 1) for k, h in INPUT_ROUNDING.items()}
        T = invert_case(dataclasses.replace(x, **moved)).duration
        assert lo <= T <= hi
    mu_only = [
        invert_case(dataclasses.replace(x, mu=m)).duration / 4.30e-3 - 1 for m in (0.195, 0.205)
    ]
    assert min(mu_only) == pytest.approx(-0.052, abs=1e-3)  # the spread mu alone gives
    assert max(mu_only) == pytest.approx(-0.038, abs=1e-3)
