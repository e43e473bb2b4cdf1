"""The paper's data module: transcription, corrections and recorded inconsistencies."""

from __future__ import annotations

import math

import pytest

from impactlab.materials import AISI_201, AISI_1010
from impactlab.paper import data as D


def test_table1_corrections():
    by = {(t.body, t.symbol): t for t in D.TABLE1}
    assert by[("rod", "S_yr")].value == 760e6 and "GPa" in by[("rod", "S_yr")].printed
    assert by[("rod", "H_r")].unit == "kgf/mm^2" and by[("rod", "H_r")].value == 327
    assert by[("flat", "H_f")].value == 105
    # the presets agree with the corrected table
    assert AISI_201.yield_strength == by[("rod", "S_yr")].value
    assert AISI_1010.yield_strength == by[("flat", "S_yf")].value
    assert D.ROD_MATERIAL is AISI_201 and D.FLAT_MATERIAL is AISI_1010


def test_mass_claim_of_table1():
    """m = 0.4607 kg is not a solid rod of diameter 2R = 17.6 mm, but fits a 5/8 in rod with
    hemispherical ends (volume pi r^2 (L - 2r/3))."""
    L, rho = 0.3048, 7800.0
    solid = math.pi * 0.0088**2 * L * rho
    r = 0.625 * 0.0254 / 2
    capsule = math.pi * r**2 * (L - 2 * r / 3) * rho
    assert solid == pytest.approx(0.578, abs=1e-3)
    assert capsule == pytest.approx(D.PAPER_ROD.mass, rel=0.01)


def test_paper_rod():
    rod = D.PAPER_ROD
    assert (rod.mass, rod.length, rod.tip_radius) == (0.4607, 0.3048, 0.0088)
    assert rod.inertia == pytest.approx(0.4607 * 0.3048**2 / 12)
    assert rod.inertia_ratio == pytest.approx(1 / 12)


def test_experiments():
    assert set(D.EXPERIMENTS) == {20, 45, 70}
    x70 = D.EXPERIMENTS[70]
    assert (x70.v_i, x70.v_rebound, x70.e, x70.mu) == (-3.45, 0.19, 0.05, 0.10)
    assert (x70.delta_p, x70.L_s) == (-105e-6, -200e-6)
    for x in D.EXPERIMENTS.values():
        assert x.v_i < 0 and x.delta_p < 0 and x.L_s < 0
        # printed e vs v_Of/|v_i|: within the rounding of two-digit velocities
        assert x.e_from_velocities == pytest.approx(x.e, abs=0.006)
    assert D.get_case("paper-45") is D.EXPERIMENTS[45]
    with pytest.raises(ValueError, match="paper-20"):
        D.get_case("paper-30")


def test_published_rows_as_printed():
    t2 = {r.model: r for r in D.published_rows(20)}
    t3 = {r.model: r for r in D.published_rows(45)}
    assert D.published_rows(70) == () and D.published_row(70, "ghaednia") is None
    assert t2["experiment"].T == 4.30e-3 and t2["experiment"].F == 79.0
    assert t3["experiment"].T == 1.40e-3 and t3["experiment"].F == 595.0
    assert (t2["ghaednia"].F, t2["brake"].F, t2["kogut-komvopoulos"].F) == (2571, 2153, 2568)
    assert (t2["brake"].T, t2["brake"].L_s) == (0.29e-3, -75e-6)
    assert (t3["brake"].delta_p, t3["kogut-komvopoulos"].L_s) == (-150e-6, -638e-6)
    # Table 3's Ghaednia dent repeats Table 2's (kept as printed)
    assert (t3["ghaednia"].delta_p, t3["ghaednia"].L_s) == (
        t2["ghaednia"].delta_p,
        t2["ghaednia"].L_s,
    )
    assert len(D.TABLE_ROWS) == 8


def test_text_versus_table_is_kept():
    text = {r.model: r for r in D.TEXT_ROWS}
    assert text["ghaednia"].F == 2153 and D.published_row(20, "ghaednia").F == 2571
    assert text["brake"].T == 0.256e-3 and D.published_row(20, "brake").T == 0.29e-3
    assert text["brake"].L_s == -74e-6 and D.published_row(20, "brake").L_s == -75e-6
    keys = {d.key for d in D.DISCREPANCIES}
    assert {
        "ghaednia-20-F",
        "brake-20-T",
        "brake-20-Ls",
        "ghaednia-45-repeat",
        "table-4-missing",
        "exp-45-T",
        "exp-45-e",
        "exp-70-e",
        "alpha-sign",
    } <= keys
    f = next(d for d in D.DISCREPANCIES if d.key == "ghaednia-20-F")
    assert f.values == {"Table 2": 2571.0, "Sec. 5.2 text": 2153.0}


def test_data_are_immutable():
    with pytest.raises(TypeError):
        D.EXPERIMENTS[20] = D.EXPERIMENTS[45]  # type: ignore[index]
    with pytest.raises(AttributeError):
        D.EXPERIMENTS[20].mu = 0.3  # type: ignore[misc]
