"""The FE accuracy report, the shipped reference curves and the FE impact comparison print as
short summaries (counts, delta_c in um, the closest law), never as raw arrays; a case's
``_repr_html_`` is the table ``impactlab laws --accuracy`` prints (shipped data, no ccx)."""

from __future__ import annotations

import dataclasses
import math

import pytest

from impactlab._display import format_number
from impactlab.fe import accuracy_views
from impactlab.fe.accuracy import PLASTIC_FROM, CaseAccuracy, accuracy
from impactlab.fe.accuracy_display import table_rows
from impactlab.fe.curves import load_cases
from impactlab.verification.fe_impact import compare_impacts


@pytest.fixture(scope="module")
def results() -> list[CaseAccuracy]:
    return accuracy()


def _short(text: str, bound: int) -> None:
    assert len(text) <= bound, text
    assert "\n" not in text and "array(" not in text


def test_the_whole_report_is_a_few_lines(results: list[CaseAccuracy]) -> None:
    assert len(repr(results)) < 300 * len(results)
    assert "array(" not in repr(results)


def test_case_repr_names_the_pair_and_the_closest_law(results: list[CaseAccuracy]) -> None:
    for res in results:
        text = repr(res)
        _short(text, 300)
        c = res.case
        most = max(a.verified.upper for a in res.built)
        assert text.startswith(
            f"CaseAccuracy({c.name!r}, E*/S_y = {c.e_star_over_sy:.4g}, "
            f"delta_c = {c.delta_c * 1e6:.4g} um, {len(res.laws)} laws"
        )
        assert f"closest: {res.closest().law}" in text
        assert f"largest verified range {most:.3g} delta_c (" in text
        plastic = res.closest_fully_plastic()
        if plastic is not None:
            assert f"(from {PLASTIC_FROM:g} delta_c on: {plastic.law})" in text
    brake = [r for r in results if len(r.built) < len(r.laws)]
    assert brake and f"{len(brake[0].laws)} laws ({len(brake[0].built)} built)" in repr(brake[0])


def test_law_repr_gives_the_verified_range_and_errors(results: list[CaseAccuracy]) -> None:
    a = results[2].laws[0]
    text = repr(a)
    _short(text, 300)
    assert text == (
        f"LawAccuracy({a.law} on {a.case}, E*/S_y = {a.e_star_over_sy:.4g}: verified "
        f"{a.verified.text}; RMS force error {100 * a.rms_force_error():.3g} %, RMS "
        f"delta_r/delta_max error {a.rms_residual_error():.3g}; {a.force_ratio.size} force "
        f"points, {a.maxima_ratio.size} maxima)"
    )
    unbuilt = next(a for r in results for a in r.laws if not a.built)
    assert "not built for this pair: " in repr(unbuilt) and len(repr(unbuilt)) < 300


def test_case_html_is_the_command_s_table(results: list[CaseAccuracy]) -> None:
    assert accuracy_views.table_rows is table_rows  # the command's rows, one function
    res = results[1]
    page = res._repr_html_()
    _, rows = table_rows(res)
    assert page.count("<tr>") == len(rows) + 1
    assert "<th>verified range</th>" in page
    assert "&lt;= " in page and "<= " not in page.replace("&lt;= ", "")
    assert "recommendation: " in page and "delta_c = " in page and " um" in page


def test_case_html_escapes_names(results: list[CaseAccuracy]) -> None:
    res = results[0]
    law = dataclasses.replace(res.laws[0], law="<law & co>")
    odd = CaseAccuracy(dataclasses.replace(res.case, description="a <b> case"), (law,))
    page = odd._repr_html_()
    assert "&lt;law &amp; co&gt;" in page and "a &lt;b&gt; case" in page
    assert "<law" not in page and "<b>" not in page
    assert repr(odd).count("\n") == 0 and "closest: <law & co>" in repr(odd)


def test_reference_case_and_run_reprs() -> None:
    cases = load_cases()
    for c in cases:
        text = repr(c)
        _short(text, 250)
        ratios = [r.delta_max / c.delta_c for r in c.runs]
        assert text == (
            f"ReferenceCase({c.name!r}: R = {c.radius * 1e3:.4g} mm, delta_c = "
            f"{c.delta_c * 1e6:.4g} um, {len(c.runs)} runs to {format_number(min(ratios), 3)} .. "
            f"{format_number(max(ratios), 3)} delta_c ({sum(r.usable for r in c.runs)} usable), "
            f"mu = {c.mu:g})"
        )
    run = cases[2].runs[-1]
    text = repr(run)
    _short(text, 250)
    assert text.startswith(
        f"ReferenceRun(delta_max {run.delta_max * 1e6:.4g} um, F_max {run.max_force:.5g} N, "
        f"delta_r {run.residual_depth * 1e6:.4g} um, converged, {run.loading_delta.size} "
        "loading / "
    )
    failed = dataclasses.replace(run, converged=False, residual_depth=math.nan)
    assert "not converged (last " in repr(failed)
    odd = dataclasses.replace(cases[0], name="<x>", description="a & b")
    page = odd._repr_html_()
    assert "&lt;x&gt;: a &amp; b" in page and "<x>" not in page
    assert page.count("<tr>") == len(odd.runs) + 1 and " um</td>" in page


def test_impact_comparison_repr_and_html() -> None:
    comp = compare_impacts("paper-ball-on-aisi1010")
    text = repr(comp)
    _short(text, 400)
    e = [f"{r['e']:.4f}" for r in comp.columns["dynamic FE"]]
    assert text.startswith(
        f"ImpactComparison('paper-ball-on-aisi1010': 2 speeds 0.1, 1 m/s, mass "
        f"{comp.mass:.5g} kg, delta_c {comp.delta_c * 1e6:.4g} um; 7 columns: dynamic FE, "
    )
    assert f"; dynamic FE e {', '.join(e)}; 10 of 10 law rows extrapolated)" in text
    comp.columns["<mine>"] = comp.columns["ghaednia"]
    page = comp._repr_html_()
    assert "&lt;mine&gt;" in page and "<mine>" not in page
    assert page.count("<tr>") == 1 + len(comp.speeds) * len(comp.columns)
