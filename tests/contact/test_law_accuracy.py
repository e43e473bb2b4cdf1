"""Measured accuracy of the contact laws against the shipped FE curves (``impactlab.fe.accuracy``).

Reads the data files of ``impactlab/fe/data``: no ccx or gmsh needed. The verified-range logic
is checked on synthetic errors and on a synthetic "FE" case made from a law's own curves,
where the answer is known.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from impactlab._json import shape_problems
from impactlab.cli import laws as laws_cli
from impactlab.contact import get_law
from impactlab.contact.verified_ranges import verified_cases
from impactlab.fe import accuracy as acc
from impactlab.fe.accuracy_views import markdown
from impactlab.fe.curves import DATA_VERSION, FORMAT, case_from_record, case_names, load_cases
from impactlab.fe.reference import CASES, case_ratios
from impactlab.materials import AISI_201, AISI_1010, ContactPair

R = 8.8e-3


# --- the verified range on synthetic errors -------------------------------------------------


def test_everything_inside_is_verified_to_the_end_of_the_data() -> None:
    r = np.geomspace(0.1, 1000.0, 50)
    v = acc.verified_range(r, 0.05 * np.ones(50), [1.0, 10.0, 300.0], [0.0, 0.01, -0.04])
    assert v.end_of_data and v.upper == pytest.approx(300.0) and math.isnan(v.first_failure)
    assert v.text == ">= 300 delta_c (end of data)"


def test_force_error_crossing_the_tolerance() -> None:
    # error = 0.04 log10(delta/delta_c) + 0.02: crosses 10 % at delta/delta_c = 100
    r = np.array([0.1, 1.0, 10.0, 50.0, 99.0, 101.0, 200.0, 1000.0])
    e = 0.04 * np.log10(r) + 0.02
    v = acc.verified_range(r, e, [1.0, 1000.0], [0.0, 0.0])
    assert (v.upper, v.limited_by, v.first_failure) == (99.0, "force", 101.0)
    # the order of the points does not matter, and a later return inside does not extend it
    e2 = e.copy()
    e2[-1] = 0.0
    v2 = acc.verified_range(r[::-1], e2[::-1], [1000.0, 1.0], [0.0, 0.0])
    assert v2.upper == 99.0


def test_residual_failing_first_limits_the_range() -> None:
    r = np.geomspace(0.1, 1000.0, 41)
    maxima = [0.3, 1.0, 3.0, 10.0, 30.0, 100.0]
    res_err = [0.0, 0.01, 0.03, 0.049, 0.051, 0.2]
    v = acc.verified_range(r, np.zeros(41), maxima, res_err)
    assert (v.upper, v.limited_by, v.first_failure) == (10.0, "delta_r", 30.0)
    assert v.text == "<= 10 delta_c (delta_r fails at 30)"


def test_first_point_outside_means_no_verified_range() -> None:
    v = acc.verified_range([0.1, 1.0], [0.2, 0.0], [1.0], [0.0])
    assert v.upper == 0.0 and v.limited_by == "force" and v.text.startswith("none")


def test_nan_counts_as_outside_and_the_tolerances_are_named() -> None:
    v = acc.verified_range([0.1, 1.0, 10.0], [0.0, 0.0, math.nan], [1.0, 10.0], [0.0, 0.0])
    assert (v.upper, v.limited_by) == (1.0, "force")
    assert acc.FORCE_TOLERANCE == 0.10 and acc.RESIDUAL_TOLERANCE == 0.05
    tight = acc.verified_range([1.0, 10.0], [0.0, 0.03], [1.0], [0.0], force_tolerance=0.02)
    assert tight.upper == 1.0
    with pytest.raises(ValueError, match="2 ratios but 1 errors"):
        acc.verified_range([1.0, 2.0], [0.0], [1.0], [0.0])


# --- a synthetic "FE" case: a law's own curves, whose errors are known ----------------------


def _synthetic_case(law: str, maxima_ratio: list[float]) -> dict:
    """A data-file record whose 'FE' curves are ``law``'s, for the paper's pair (elastic-plastic
    sphere: the pair the laws are built with)."""
    pair = ContactPair(AISI_201, AISI_1010)
    model = get_law(law).build(pair, R)
    dc = get_law("hertz").build(pair, R).critical_interference
    d = np.geomspace(0.05 * dc, max(maxima_ratio) * dc, 60)
    f = model.force(d)

    def mat(m):
        return {
            "name": m.name,
            "E": m.E,
            "nu": m.nu,
            "yield_strength": m.yield_strength,
            "brinell_hardness": m.brinell_hardness,
            "meyer_index": m.meyer_index,
            "density": m.density,
        }

    runs = []
    for k in maxima_ratio:
        dm = k * dc
        keep = d <= dm * (1 + 1e-12)
        runs.append(
            {
                "delta_max": dm,
                "loading": {
                    "delta": d[keep].tolist(),
                    "force": f[keep].tolist(),
                    "contact_radius": [0.0] * int(keep.sum()),
                },
                "unloading": {"delta": [dm, 0.0], "force": [1.0, 0.0]},
                "residual_depth": model.unload(dm).delta_r,
                "max_force": float(model.force(dm)),
                "pile_up": 0.0,
                "converged": True,
                "last_converged_delta": 0.0,
                "message": "",
                "increments": 1,
                "cutbacks": 0,
                "iterations": 1,
                "run_time": 0.0,
                "n_elements": 1,
                "force_balance": 0.0,
            }
        )
    return {
        "format": FORMAT,
        "version": DATA_VERSION,
        "case": f"synthetic-{law}",
        "description": f"{law}'s own curves",
        "ccx_version": "none",
        "gmsh_version": "none",
        "delta_c": dc,
        "inputs": {
            "radius": R,
            "flat": mat(AISI_1010),
            "sphere_material": mat(AISI_201),
            "sphere": "elastic-plastic",
            "mu": 0.0,
            "mesh_level": 1,
        },
        "runs": runs,
    }


def test_a_law_against_its_own_curves_is_exact_and_verified_to_the_end() -> None:
    case = case_from_record(_synthetic_case("jackson-green", [0.3, 3.0, 30.0, 300.0]))
    a = acc.law_accuracy("jackson-green", case)
    assert np.max(np.abs(a.force_error)) < 1e-12
    assert np.max(np.abs(a.residual_error)) < 1e-12
    assert a.verified.end_of_data and a.verified.upper == pytest.approx(300.0)
    assert a.score() < 1e-9


def test_hertz_against_an_elastic_plastic_curve_fails_where_known() -> None:
    """'FE' = Jackson-Green: Hertz's force error is JG's known departure from Hertz, and Hertz
    (delta_r = 0) fails delta_r where JG's delta_r/delta_max passes 0.05."""
    case = case_from_record(_synthetic_case("jackson-green", [0.3, 1.0, 3.0, 10.0, 30.0]))
    a = acc.law_accuracy("hertz", case)
    pair = ContactPair(AISI_201, AISI_1010)
    jg, hz = (get_law(n).build(pair, R) for n in ("jackson-green", "hertz"))
    d = a.force_ratio * case.delta_c
    assert np.allclose(a.force_error, hz.force(d) / jg.force(d) - 1.0, rtol=1e-12, atol=1e-12)
    res = np.array(
        [jg.unload(k * case.delta_c).delta_r / (k * case.delta_c) for k in a.maxima_ratio]
    )
    expect = acc.verified_range(a.force_ratio, a.force_error, a.maxima_ratio, -res)
    assert a.verified == expect and not a.verified.end_of_data


# --- the shipped data ------------------------------------------------------------------------


@pytest.fixture(scope="module")
def results() -> list[acc.CaseAccuracy]:
    return acc.accuracy()


def test_every_case_is_shipped_with_its_inputs_and_convergence() -> None:
    assert set(case_names()) == set(CASES)
    for case in load_cases():
        assert case.ccx_version and case.gmsh_version and case.mesh_level == 1
        ratios = [r.delta_max / case.delta_c for r in case.runs]
        assert ratios == pytest.approx(case_ratios(case.name), rel=1e-6)
        assert case.runs[0].converged
        for run in case.runs:
            assert run.force_balance < 2e-4  # largest: AISI 304 at 1000 delta_c, 1.6e-4
            if not run.converged:  # shipped as it stopped: the curve to its last converged point
                assert math.isnan(run.residual_depth) and "ERROR" in run.message
                assert run.loading_delta[-1] == pytest.approx(run.last_converged_delta)
                assert run.last_converged_delta < run.delta_max
                continue
            if math.isnan(run.residual_depth):  # below the contact's resolution: one run
                assert (case.name, round(run.delta_max / case.delta_c, 6)) == (
                    "paper-aisi201-on-aisi1010",
                    1.5,
                )
                continue  # tests/fe/test_fe_residual_depth.py
            assert 0.0 <= run.residual_ratio < 1.0
            # delta_r (the final gap between the surfaces) lies between the last unloading
            # point that still carries force and the first one that does not
            carries = run.unloading_force > 1e-6 * run.max_force
            k = int(np.argmin(carries))
            lo, hi = run.unloading_delta[k], run.unloading_delta[k - 1]
            tol = 2e-3 * run.delta_max
            assert lo - tol <= run.residual_depth <= hi + tol, (case.name, run.delta_max)
        # the permanent depth grows with the maximum (physics, not a fit)
        res = [r.residual_ratio for r in case.runs if r.converged and r.residual_ratio >= 0]
        assert np.all(np.diff(res) > -0.01), res


def test_shipped_cases_span_soft_to_hard(results) -> None:
    ratios = [r.case.e_star_over_sy for r in results]
    assert ratios == sorted(ratios, reverse=True) and len(ratios) >= 3
    assert ratios[0] > 300 and ratios[-1] < 100


def test_fe_starts_on_hertz(results) -> None:
    """Below 0.3 delta_c every case is elastic: FE within 2 % of Hertz (mesh level 1 is about
    1 % stiff, docs/fe.md)."""
    for res in results:
        hz = next(a for a in res.laws if a.law == "hertz")
        low = hz.force_ratio <= 0.3
        assert low.sum() >= 3
        assert np.max(np.abs(hz.force_error[low])) < 0.02, res.case.name


def test_paper_pair_at_1000_delta_c_matches_docs_fe() -> None:
    case = next(c for c in load_cases() if c.name == "paper-aisi201-on-aisi1010")
    top = case.runs[-1]
    assert top.delta_max / case.delta_c == pytest.approx(1000.0)
    assert top.max_force == pytest.approx(25.6e3, rel=0.01)
    assert top.residual_ratio == pytest.approx(0.888, abs=0.002)


def test_the_recommendation_names_the_closest_law_of_the_fully_plastic_regime(results) -> None:
    """The paper's pair: over the whole span Brake scores best (its delta_r), but its force is
    35-39 % low from 100 delta_c on, where the paper's impacts lie; there Ghaednia's law is the
    closest, and the recommendation says so. A case that stops at 100 delta_c has no such
    clause (one FE maximum there)."""
    paper = next(r for r in results if r.case.name == "paper-aisi201-on-aisi1010")
    assert paper.closest().law == "brake"
    plastic = paper.closest_fully_plastic()
    assert plastic is not None and plastic.law == "ghaednia"
    force, residual = plastic.errors_from(acc.PLASTIC_FROM)
    brake = next(a for a in paper.laws if a.law == "brake")
    assert np.max(np.abs(force)) < 0.1 < np.max(np.abs(brake.errors_from(acc.PLASTIC_FROM)[0]))
    assert residual.size >= 2
    assert "from 100 delta_c on (fully plastic" in paper.recommendation()
    assert paper.describe()["closest_fully_plastic"] == "ghaednia"
    hard = next(r for r in results if r.case.e_star_over_sy < 100)
    assert hard.closest_fully_plastic() is None and "fully plastic" not in hard.recommendation()


def test_every_law_is_measured_on_every_case(results) -> None:
    """Every law is built for every pair, but Brake's where a body has no Brinell hardness
    (PMMA, the hardened AISI 52100 ball): it is then left out of the case's recommendation and
    verified ranges."""
    for res in results:
        assert [a.law for a in res.laws] == list(acc.measured_laws())
        for a in res.laws:
            if not a.built:
                hb = (res.case.flat.brinell_hardness, res.case.sphere_material.brinell_hardness)
                assert a.law == "brake" and any(math.isnan(h) for h in hb)
                assert "Brinell hardness" in a.message and a not in res.built
                assert res.case.name not in [c.case for c in verified_cases("brake")]
                continue
            resolved = np.isfinite(a.residual_fe)  # FE's delta_r below its resolution: nan
            assert np.all(np.isfinite(a.force_error))
            assert np.all(np.isfinite(a.residual_error[resolved]))
            assert a.verified.upper >= 0.3 or a.verified.limited_by != "end of data"
        assert res.closest().law in acc.measured_laws()
        line = res.recommendation()
        assert "\n" not in line and res.closest().law in line


def test_report_json_has_the_documented_shape(results) -> None:
    from impactlab._json import to_json

    data = json.loads(json.dumps(to_json(acc.report(results), acc.UNITS)))
    assert shape_problems(data) == []
    assert data["tolerances"]["force_relative"] == {"value": 0.1, "unit": "1"}


def test_docs_page_tables_are_the_computed_ones(results) -> None:
    from pathlib import Path

    page = Path(__file__).resolve().parents[2] / "docs" / "laws" / "accuracy.md"
    text = page.read_text()
    for line in markdown(results).splitlines():
        if line.startswith(("|", "**Recommendation")):
            assert line in text, f"docs/laws/accuracy.md is out of date: {line}"


# --- impactlab laws --accuracy ----------------------------------------------------------------


@pytest.fixture(scope="module")
def app() -> typer.Typer:
    a = typer.Typer()
    laws_cli.register(a)

    @a.command("noop")
    def noop() -> None:  # a second command so that "laws" stays a sub-command
        pass

    return a


def test_cli_table(app) -> None:
    res = CliRunner().invoke(app, ["laws", "--accuracy"], env={"COLUMNS": "250"})
    assert res.exit_code == 0, res.output
    for name in acc.measured_laws():
        assert name in res.stdout
    assert res.stdout.count("recommendation:") == len(CASES)
    assert "within 10 % in force and 0.05 in delta_r/delta_max" in res.stdout


def test_cli_json_one_law(app) -> None:
    res = CliRunner().invoke(app, ["laws", "jackson-green", "--accuracy", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert shape_problems(data) == []
    assert len(data["cases"]) == len(CASES)
    for case in data["cases"]:
        assert list(case["laws"]) == ["jackson-green"]
        assert case["laws"]["jackson-green"]["verified_delta_ratio"]["unit"] == "1"


def test_cli_pair_options_are_refused_with_accuracy(app) -> None:
    """--flat, --body and --radius choose an example pair, not an FE case: refused, not
    silently ignored."""
    res = CliRunner().invoke(app, ["laws", "ghaednia", "--accuracy", "--flat", "al-6061-t6"])
    assert res.exit_code == 2 and "--flat with --accuracy" in res.output


def test_cli_unknown_law_is_one_line(app) -> None:
    res = CliRunner().invoke(app, ["laws", "nope", "--accuracy"])
    assert res.exit_code == 2
