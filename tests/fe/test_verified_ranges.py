"""The laws' verified ranges (``impactlab.contact.verified_ranges``) are what
``impactlab.fe.accuracy`` measures from the shipped FE curves, and the hardened paper's pair
(``fe/data/hardening``, AISI 1010 with a cited strain hardening) is a sound FE reference.
No ccx needed: the shipped data files are read."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from impactlab.contact import get_law
from impactlab.contact.ranges import range_status
from impactlab.contact.verified_ranges import (
    BEYOND_FE,
    VERIFIED_PATH,
    e_star_over_sy_span,
    verified_cases,
    verified_upper,
)
from impactlab.fe.accuracy import accuracy, measured_laws
from impactlab.fe.curves import HARDENED_DIR, case_names, load_case
from impactlab.fe.problem import check_hardening
from impactlab.fe.reference import (
    FLAT_HARDENING,
    HARDENED_CASES,
    case_ratios,
)
from impactlab.fe.tabulated import HARDENED_PAPER_CASE, hardened_curves, hardened_law
from impactlab.fe.verified_ranges import verified_range_table
from impactlab.materials import AISI_201, AISI_1010, ContactPair
from impactlab.materials.hardening import AISI_1010_HARDENING, SwiftHardening
from impactlab.materials.library import AISI_52100, BRITTLE, PRESETS

R = 8.8e-3


def test_shipped_table_equals_what_the_accuracy_measures() -> None:
    """The data file is generated, never typed: it equals fe.accuracy over the shipped curves."""
    shipped = json.loads(VERIFIED_PATH.read_text())
    fresh = json.loads(json.dumps(verified_range_table()))
    assert shipped == fresh
    assert set(shipped["laws"]) == set(measured_laws())
    measured = accuracy()
    for law, rows in shipped["laws"].items():
        built = [ca for ca in measured if next(a for a in ca.laws if a.law == law).built]
        assert len(verified_cases(law)) == len(rows) == len(built)
        # Brake's law needs both bodies' Brinell hardness: not PMMA's nor the 52100 ball's
        assert len(built) == len(case_names()) - (3 if law == "brake" else 0)
        for c in verified_cases(law):
            assert c.upper >= 0.0 and c.limited_by in ("force", "delta_r", "end of data")
            p = np.full(64, np.nan)  # a parameter vector with the case's inputs beyond FE
            for name, value in c.inputs:
                p[BEYOND_FE[law][name]] = value
            assert verified_upper(law, c.e_star_over_sy, p) == c.upper


def test_every_ductile_library_flat_is_verified_against_a_common_ball() -> None:
    """The FE cases span E*/S_y of every ductile flat of the library (PMMA 28 to OFHC copper
    1731) against an AISI 52100 or AISI 201 ball: each such pair has a verified range."""
    lo, hi = e_star_over_sy_span()
    assert lo == pytest.approx(28.04, abs=0.01) and hi == pytest.approx(1731.3, abs=0.1)
    for name, flat in PRESETS.items():
        if name in BRITTLE:
            continue
        for ball in (AISI_52100, AISI_201):
            for law in ("ghaednia", "jackson-green", "kogut-komvopoulos", "hertz", "thornton"):
                model = get_law(law).build(ContactPair(ball, flat), R)
                assert range_status(model.law_id, model.params) == "verified", (name, ball, law)


def test_hardening_law_and_its_table() -> None:
    """The hardened case's flat: AISI 1010's own Swift law (its table as the FE program reads
    it); the law itself: tests/core/test_hardening_laws.py."""
    h = AISI_1010_HARDENING
    assert isinstance(h, SwiftHardening)
    assert h.yield_strength == pytest.approx(AISI_1010.yield_strength, rel=1e-12)
    rows = check_hardening("flat_hardening", h.table())  # starts at strain 0, monotonic
    assert tuple(rows) == FLAT_HARDENING[HARDENED_PAPER_CASE]
    s, e = np.array(rows).T
    assert s[0] == AISI_1010.yield_strength and e[-1] == h.max_strain
    np.testing.assert_allclose(s, h.stress(e), rtol=1e-6)


def test_hardened_case_is_stored_apart_and_complete() -> None:
    assert HARDENED_PAPER_CASE in HARDENED_CASES and HARDENED_PAPER_CASE not in case_names()
    case = load_case(HARDENED_PAPER_CASE, HARDENED_DIR)
    assert (case.flat.name, case.sphere_material.name) == (AISI_1010.name, AISI_201.name)
    record = json.loads((HARDENED_DIR / f"{HARDENED_PAPER_CASE}.v1.json").read_text())
    assert [tuple(r) for r in record["inputs"]["flat_hardening"]] == list(
        FLAT_HARDENING[HARDENED_PAPER_CASE]
    )
    ratios = [r.delta_max / case.delta_c for r in case.runs]
    assert ratios == pytest.approx(case_ratios("paper-aisi201-on-aisi1010"), rel=1e-6)
    assert all(r.converged for r in case.runs)
    assert all(abs(r.force_balance) < 1e-4 for r in case.runs)


def test_hardening_raises_the_force_and_lowers_the_permanent_depth() -> None:
    """Against the elastic-perfectly plastic paper's pair (same mesh, same maxima): the same
    force up to first yield, a larger one beyond, growing with the depth (cold-drawn 1010
    hardens little: 2 % at 10 delta_c, 17 % at 1000); delta_r / delta_max no larger."""
    hard = load_case(HARDENED_PAPER_CASE, HARDENED_DIR)
    epp = load_case("paper-aisi201-on-aisi1010")
    assert hard.delta_c == pytest.approx(epp.delta_c, rel=1e-12)
    d_h, f_h = hard.loading_curve()
    d_e, f_e = epp.loading_curve()
    dc = epp.delta_c
    for ratio in (0.3, 0.8):
        x = ratio * dc
        assert np.interp(x, d_h, f_h) == pytest.approx(np.interp(x, d_e, f_e), rel=0.01)
    gain = [
        np.interp(r * dc, d_h, f_h) / np.interp(r * dc, d_e, f_e) for r in (10.0, 100.0, 1000.0)
    ]
    assert min(gain) > 1.01 and gain[-1] > gain[0] + 0.1  # 1.018, 1.046, 1.167
    for rh, re in zip(hard.runs, epp.runs, strict=True):
        if rh.delta_max > 3 * dc:
            assert rh.residual_ratio <= re.residual_ratio + 0.01


def test_hardened_law_builds_for_the_papers_pair_only() -> None:
    curves = hardened_curves()
    assert curves.e_star_over_sy == pytest.approx(360.3, rel=1e-3)
    model = hardened_law(ContactPair(AISI_201, AISI_1010), R)
    dc = model.critical_interference
    assert model.max_interference == pytest.approx(1000 * dc, rel=1e-3)
    assert math.isfinite(float(model.force(500 * dc)))
    soft = ContactPair(AISI_201, AISI_1010.__class__("soft", 200e9, 0.3, 150e6, 50.0))
    with pytest.raises(ValueError, match="no indentation curves for E\\*/S_y"):
        hardened_law(soft, R)


def test_hardened_law_reproduces_its_fe_points_within_the_tabulated_bounds() -> None:
    """The report row's law, built from the hardened case, stays within the tabulated law's
    stated bounds (docs/laws/tabulated.md): loading within 2.5 % of every FE point past
    delta_c (1.1 % rms), leave-one-out 3 % (force) and 0.015 (delta_r / delta_max), and the FE
    delta_r of every maximum within 0.001 delta_max."""
    from impactlab.contact.tabulated import interpolation_error

    case = load_case(HARDENED_PAPER_CASE, HARDENED_DIR)
    model = hardened_law(case.pair, case.radius)
    d, f = case.loading_curve()
    inside = (d > case.delta_c) & (d <= model.max_interference)
    rel = model.force(d[inside]) / f[inside] - 1.0
    assert np.max(np.abs(rel)) <= 0.025
    assert np.sqrt(np.mean(rel**2)) <= 0.011
    loo_force, loo_residual = interpolation_error(hardened_curves())
    assert 0.0 < loo_force <= 0.03 and 0.0 < loo_residual <= 0.015
    for run in case.runs:
        assert abs(model.unload(run.delta_max).delta_r - run.residual_depth) <= (
            1e-3 * run.delta_max
        )
