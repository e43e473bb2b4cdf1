"""How an inversion shows itself: Jupyter's table carries what ``print(result)`` says (the
Monte Carlo's intervals, the force method, the note on discarded samples) and the result's
``warnings``; ``repr`` is one line with units."""

from __future__ import annotations

import dataclasses
import html
import warnings

import pytest
from inversion_cases import WIDE

import impactlab as il
from impactlab.analytic import InversionResult


@pytest.fixture(scope="module")
def wide() -> InversionResult:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", il.ImplausibleInputWarning)
        return il.invert(**WIDE)


def test_the_notebook_table_shows_the_intervals_the_method_and_the_note(
    wide: InversionResult,
) -> None:
    page = wide._repr_html_()
    for name in ("T_interval_mc", "F_interval_mc", "T_median_mc", "force_method", "mc_used"):
        assert f"<td>{name}</td>" in page, name
    assert "rigid-body identity" in page and "95 %" in page
    lo, hi = (f"{v * 1e3:.5g}" for v in wide.T_interval_mc)  # ms, as print(result) shows it
    assert f"({lo}, {hi})" in page and f"95 % in [{lo}, {hi}]" in str(wide)
    note = "discarded (17857 used)"
    assert wide.mc_used == 17857 and note in str(wide) and note in page


def test_the_warnings_are_a_field_shown_everywhere(wide: InversionResult) -> None:
    assert wide.warnings == tuple(wide.warnings) and "warnings" in wide.to_dict()
    texts = ("more than 5 % were discarded", "T has a heavy tail")
    flagged = dataclasses.replace(wide, warnings=list(texts))  # type: ignore[arg-type]
    assert flagged.warnings == texts and flagged.to_dict()["warnings"] == list(texts)
    page = flagged._repr_html_()
    cells = [f"<td>warning</td><td style='text-align:right'>{html.escape(t)}" for t in texts]
    assert all(cell in page for cell in cells)
    assert all(f"  warning: {t}" in str(flagged).splitlines() for t in texts)
    assert repr(flagged).endswith(", 2 warnings)")


def test_repr_is_one_short_line_with_units(wide: InversionResult) -> None:
    text = repr(wide)
    assert "\n" not in text and len(text) < 200, text
    assert text.startswith(
        "InversionResult(duration=0.0311001 ± 0.025 s, mean_force=10.954 ± 8.4 N"
    )
    assert "force_method='rigid-body identity'" in text and "mc_used=17857 of 20000" in text
    exact = il.invert(**{**WIDE, "mu": 0.2})  # no sigma: no Monte Carlo, no ±
    assert repr(exact) == (
        "InversionResult(duration=0.00410595 s, mean_force=69.3142 N, "
        "force_method='rigid-body identity')"
    )
    assert "<td>T_mc</td>" not in exact._repr_html_()  # the Monte Carlo did not run
