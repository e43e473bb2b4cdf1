"""A result says whether its impact stayed inside the contact law's range (verified against FE
for the pair's E*/S_y, else the stand-in):
``ImpactResult.max_delta_ratio``, ``.extrapolated``, the flag ``LAW_EXTRAPOLATED`` with its
sentence (how far it went), on single results, batches (``run_arrays``' ``flags`` column) and
sweep stores. Outputs beyond the range stay finite and
energy-consistent: the flag is advisory (``ok`` stays True)."""

from __future__ import annotations

import html
import math
from pathlib import Path

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.contact import get_law
from impactlab.contact.ranges import law_extrapolated
from impactlab.contact.verified_ranges import e_star_over_sy_span
from impactlab.dynamics import OUTPUT_FIELDS, simulate, simulate_batch
from impactlab.dynamics.batch import run_arrays
from impactlab.flags import ADVISORY_FLAGS, FLAG_LAW_EXTRAPOLATED, ResultFlag, messages
from impactlab.friction import FRICTION_IDS
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material
from impactlab.sweep import Study, run_sweep

PAPER = {"law": "ghaednia", "friction": "coulomb", "mu": 0.2, "angle": math.radians(20)}
#: the paper's 20-degree impact at 1.41 m/s, a gentle one (delta_max/delta_c about 45) and a
#: tiny one inside the verified range (below 1 delta_c; without gravity, which would dominate)
FAST, GENTLE, TINY = (0.0, -1.41), (0.0, -0.3), (0.0, -0.001)
#: a flat whose E*/S_y (about 2200) lies beyond the FE cases' span (28-1731): unverified
SOFT_FLAT = Material("soft low-carbon steel", 200e9, 0.3, 50e6, 30.0)
#: a gentle impact on the soft flat (delta_max/delta_c about 40), without gravity, which would
#: dominate it
SOFT_GENTLE = (0.0, -0.003)
#: a tiny impact on the soft flat, below 1 delta_c (its smallest verified range): unflagged
SOFT_TINY = (0.0, -1e-5)


def _delta_c() -> float:
    """Jackson-Green's delta_c = (pi C S_y / (2 E*))^2 R of the paper's pair, by hand: the
    weaker material (the flat) gives S_y and nu."""
    pair = ContactPair(AISI_201, AISI_1010)
    c = 1.295 * math.exp(0.736 * AISI_1010.nu)
    return (math.pi * c * AISI_1010.yield_strength / (2.0 * pair.E_star)) ** 2 * 8.8e-3


def test_paper_impact_is_flagged_with_how_far_it_went() -> None:
    r = simulate(PAPER_ROD, velocity=FAST, **PAPER)
    ratio = r.delta_max / _delta_c()
    assert r.max_delta_ratio == pytest.approx(ratio, rel=1e-9)
    assert ratio > 110.0  # beyond even Kogut & Etsion's FEM range, the former stand-in
    assert r.extrapolated and ResultFlag.LAW_EXTRAPOLATED in r.flags
    assert r.ok  # advisory: the measures stay readable
    (text,) = r.warnings
    assert text.startswith("law extrapolated:")
    assert f"max delta/delta_c = {ratio:.4g}, verified up to 1)" in text
    assert "10 % in force or 0.05 in delta_r/delta_max" in text and "(advisory;" in text
    assert "fitted up to" not in text and "energy-consistent" not in text
    assert "warning" in str(r) and "law extrapolated" in str(r)
    d = r.to_dict()
    assert d["flags"] == FLAG_LAW_EXTRAPOLATED and d["warnings"] == [text]


@pytest.mark.parametrize("law", ["kogut-komvopoulos", "brake"])
def test_a_law_measured_in_its_own_delta_y_says_so(law: str) -> None:
    """Kogut-Komvopoulos and Brake measure their ranges in their own delta_y: the warning's
    ratio and limit say delta_y (the law_range line gives both), for an impact and a drop."""
    from impactlab.dynamics import simulate_drop

    for result in (simulate(PAPER_ROD, velocity=FAST, **{**PAPER, "law": law}),
                   simulate_drop(PAPER_ROD, velocity=FAST, **{**PAPER, "law": law})):  # fmt: skip
        (text,) = result.warnings
        assert f"max delta/delta_y = {result.max_delta_ratio:.4g}, verified up to " in text
        assert "delta/delta_c" not in text


def test_outputs_beyond_the_range_are_finite_and_energy_consistent() -> None:
    r = simulate(PAPER_ROD, velocity=(0.0, -3.45), **PAPER)
    assert r.extrapolated and r.max_delta_ratio > 200.0
    values = [r.e, r.delta_max, r.delta_p, r.duration, r.max_force, r.energy_dissipated]
    assert np.all(np.isfinite(values)) and 0.0 < r.e < 1.0
    assert r.energy_dissipated > 0.0  # no energy gain beyond the range


def test_impact_inside_the_verified_range_is_not_flagged() -> None:
    r = simulate(PAPER_ROD, velocity=TINY, gravity=False, **PAPER)
    assert 0.1 < r.max_delta_ratio < 1.0  # Ghaednia's law is verified to 1 delta_c here
    assert not r.extrapolated and r.flags == ResultFlag.NONE and r.warnings == ()


def test_gentle_impact_is_flagged_by_the_verified_range() -> None:
    """45 delta_c: inside Kogut & Etsion's FEM range (110, the former stand-in) but beyond
    the verified range (1)."""
    r = simulate(PAPER_ROD, velocity=GENTLE, **PAPER)
    assert 1.0 < r.max_delta_ratio < 110.0
    assert r.extrapolated and r.ok


def test_unverified_pair_is_held_to_the_smallest_verified_range_and_says_so() -> None:
    """A pair outside the FE cases' E*/S_y span is trusted no further than every measured one:
    the law's smallest verified range (1 delta_c for Ghaednia's), not the former stand-in 110
    (under which this 40 delta_c impact went unflagged)."""
    tiny = simulate(PAPER_ROD, SOFT_FLAT, velocity=SOFT_TINY, gravity=False, **PAPER)
    assert 0.0 < tiny.max_delta_ratio < 1.0 and not tiny.extrapolated
    r = simulate(PAPER_ROD, SOFT_FLAT, velocity=SOFT_GENTLE, gravity=False, **PAPER)
    assert 1.0 < r.max_delta_ratio < 110.0 and r.extrapolated and r.ok
    (text,) = r.warnings
    assert "stand-in limit 1)" in text and "no FE case covers the pair's E*/S_y" in text


def test_an_unflagged_impact_still_says_whether_its_pair_was_verified() -> None:
    """Below the stand-in no flag is set, so the result's ``law_range`` line says it: in
    ``print(result)``, ``summary()`` and ``to_dict()`` (the CLI's table and ``--json``)."""
    soft = simulate(PAPER_ROD, SOFT_FLAT, velocity=SOFT_TINY, gravity=False, **PAPER)
    assert not soft.extrapolated and not soft.warnings
    lo, hi = e_star_over_sy_span()
    line = soft.law_range
    assert line is not None and line.startswith("unverified: E*/S_y = 2198")
    assert f"outside the FE cases' {lo:.0f}-{hi:.0f}" in line and "stand-in limit 1 delta_c" in line
    assert soft.to_dict()["law_range"] == line and soft.summary()["law_range"] == line
    assert f"law_range           {line}" in str(soft)
    paper = simulate(PAPER_ROD, velocity=TINY, gravity=False, **PAPER)
    assert not paper.extrapolated
    assert paper.law_range == (
        f"verified against FE up to 1 delta_c (E*/S_y = 360.3; FE cases {lo:.0f}-{hi:.0f})"
    )
    assert paper.to_dict()["law_range"] == paper.law_range


def test_a_drop_carries_the_law_range_line_too() -> None:
    """``DropResult.law_range``: the same line as an impact's, in its summary and to_dict."""
    from impactlab.bodies.flexible_rod import FlexibleRod
    from impactlab.dynamics.drop import simulate_drop

    drop = simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0, -1.41))
    impact = simulate(PAPER_ROD, velocity=FAST, **PAPER)
    assert drop.law_range == impact.law_range and drop.law_range is not None
    assert drop.summary()["law_range"] == drop.to_dict()["law_range"] == drop.law_range
    assert "law_range" in str(drop)


def test_a_batch_carries_the_law_range_line_of_its_pair() -> None:
    """``BatchResult.law_range``: the line of an impact of the same pair, in the xarray
    attributes and the notebook view."""
    soft = simulate_batch(PAPER_ROD, SOFT_FLAT, vy=[-0.01, -0.02], gravity=False, **PAPER)
    one = simulate(PAPER_ROD, SOFT_FLAT, velocity=SOFT_GENTLE, gravity=False, **PAPER)
    assert soft.law_range == one.law_range and soft.law_range.startswith("unverified")
    assert soft.to_xarray().attrs["law_range"] == soft.law_range
    assert html.escape(soft.law_range) in soft._repr_html_()
    paper = simulate_batch(PAPER_ROD, vy=[-1.41], **PAPER)
    assert paper.law_range == simulate(PAPER_ROD, velocity=TINY, **PAPER).law_range


@pytest.mark.parametrize("law", ["brake", "thornton"])
def test_analytical_laws_are_flagged_beyond_their_verified_range(law: str) -> None:
    """No fitted range, but a verified one (1-2 delta_c); outside the FE span the stand-in is
    first yield, so a plastic impact there is marked too (it was not before)."""
    r = simulate(PAPER_ROD, velocity=FAST, **(PAPER | {"law": law}))
    assert r.max_delta_ratio > 100.0 and r.extrapolated
    unverified = simulate(PAPER_ROD, SOFT_FLAT, velocity=FAST, **(PAPER | {"law": law}))
    assert unverified.extrapolated and unverified.ok  # advisory
    (text,) = [w for w in unverified.warnings if w.startswith("law extrapolated")]
    assert "stand-in limit 1)" in text


def test_hertz_beyond_first_yield_is_flagged() -> None:
    """Hertz holds up to first yield (delta_c of the pair): the paper's impact is far past it."""
    r = simulate(PAPER_ROD, velocity=FAST, **(PAPER | {"law": "hertz"}))
    assert r.max_delta_ratio == pytest.approx(r.delta_max / _delta_c(), rel=1e-9)
    assert r.extrapolated and r.ok


def test_batch_and_run_arrays_carry_the_flag() -> None:
    b = simulate_batch(
        PAPER_ROD, law="ghaednia", friction="coulomb", mu=0.2, angle=PAPER["angle"],
        vy=[-1.41, -0.001, -1.41, -1.41], vx=[0.0, 0.0, 0.0, math.nan], gravity=False,
    )  # fmt: skip
    np.testing.assert_array_equal(b.flags, [4, 0, 4, 0])
    assert np.isnan(b["flags"][3])  # a failed case has no outputs
    single = simulate(PAPER_ROD, velocity=FAST, **PAPER)
    assert b.flags[0] == int(single.flags)
    model = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), PAPER_ROD.tip_radius)
    np.testing.assert_array_equal(law_extrapolated(model, b.delta_max[:3]), [True, False, True])
    # run_arrays directly, one parameter row for all cases and one per case
    init = np.array([[PAPER["angle"], 0.0, -1.41, 0.0], [PAPER["angle"], 0.0, -0.001, 0.0]])
    body = PAPER_ROD.to_params(AISI_1010)
    for lp in (model.params, np.stack([model.params] * 2)):
        out, st = run_arrays(model.law_id, FRICTION_IDS["coulomb"], lp, body, init, 0.2)
        assert list(st) == [0, 0]
        flags = out[:, OUTPUT_FIELDS.index("flags")].astype(np.int64)
        np.testing.assert_array_equal(flags & FLAG_LAW_EXTRAPOLATED, [4, 0])


def test_tiny_sweep_stores_the_flag(tmp_path: Path) -> None:
    study = Study.from_dict(
        {
            "study": {"name": "range", "chunk_size": 2},
            "fixed": {"law": "ghaednia", "angle": "20 deg", "mu": 0.2},
            "grid": {"vy": [-1.41, -0.001]},
            "engine": {"gravity": False},
            "outputs": {"keep": ["e", "delta_max"]},
        }
    )
    ds = run_sweep(study, tmp_path / "r.zarr", quiet=True).dataset.load()
    np.testing.assert_array_equal(ds["flags"].values, [4, 0])
    assert "law_extrapolated" in ds["flags"].attrs["flag_meanings"].split()


def test_flag_message_and_advisory_mask() -> None:
    assert ADVISORY_FLAGS == FLAG_LAW_EXTRAPOLATED
    (generic,) = messages(FLAG_LAW_EXTRAPOLATED)
    assert generic.startswith("law extrapolated: the largest interference passed")
    assert "max delta" not in generic  # how far is unknown without the numbers
    (far,) = messages(FLAG_LAW_EXTRAPOLATED, extrapolation=(312.4, 110.0), status="confirmed")
    assert "(max delta/delta_c = 312.4, fitted up to 110)" in far
    assert messages(4, extrapolation=(math.nan, math.inf)) == (generic,)


@pytest.mark.parametrize(
    "status", [None, "confirmed", "provisional", "theory", "verified", "unverified"]
)
def test_extrapolation_message_depends_on_the_range_status(status: str | None) -> None:
    """The sentence never claims energy consistency, says it is advisory, points to the command
    that measures each law and words the limit after the range's status (provisional: a
    stand-in; theory: first yield, not fitted)."""
    (text,) = messages(FLAG_LAW_EXTRAPOLATED, extrapolation=(5.0, 1.0), status=status)
    assert "energy-consistent" not in text and "impactlab.contact.ranges" not in text
    assert "(advisory; `impactlab laws --accuracy` measures each law)" in text
    if status == "provisional":
        assert "provisional limit 1)" in text and "stand-in" in text
        assert "fitted up to" not in text
    elif status == "theory":
        assert "first yield" in text and "fitted" not in text
    elif status == "confirmed":
        assert "fitted up to 1)" in text
    elif status == "verified":
        assert "verified up to 1)" in text and "FE" in text
    elif status == "unverified":
        assert "stand-in limit 1)" in text and "no FE case covers the pair's E*/S_y" in text


def test_hertz_warning_names_the_verified_range_or_first_yield() -> None:
    """Hertz for the paper's pair: verified against FE to 1 delta_c (FE's delta_r at 1.5 is
    unresolved, at 2 it fails); for a pair outside the FE span its stand-in, first yield
    (never 'fitted')."""
    r = simulate(PAPER_ROD, velocity=FAST, **{**PAPER, "law": "hertz"})
    assert r.extrapolated
    (text,) = [w for w in r.warnings if w.startswith("law extrapolated")]
    assert "verified up to 1)" in text and "fitted" not in text
    soft = simulate(PAPER_ROD, SOFT_FLAT, velocity=FAST, **{**PAPER, "law": "hertz"})
    (text,) = [w for w in soft.warnings if w.startswith("law extrapolated")]
    assert "stand-in limit 1)" in text and "fitted" not in text


def test_rigid_outputs_carry_max_delta_ratio() -> None:
    """to_dict and the batch's Dataset report max_delta_ratio (and to_dict extrapolated)."""
    r = simulate(PAPER_ROD, velocity=FAST, **PAPER)
    d = r.to_dict()
    assert d["max_delta_ratio"] == r.max_delta_ratio and d["extrapolated"] is True
    assert "max_delta_ratio" in r.summary()
    b = simulate_batch(PAPER_ROD, vy=[-1.41, -0.3], **PAPER)
    ds = b.to_xarray()
    assert ds["max_delta_ratio"].attrs["units"] == "1"
    np.testing.assert_allclose(
        ds["max_delta_ratio"].values, [r.max_delta_ratio, b.max_delta_ratio[1]], rtol=1e-12
    )


def test_an_impact_and_a_drop_report_their_law_range_under_the_same_keys() -> None:
    """to_dict of an impact and of a drop both carry max_delta_ratio, fitted_delta_ratio_max,
    fitted_range_status and extrapolated (one result family)."""
    from impactlab.bodies import FlexibleRod
    from impactlab.dynamics.drop import simulate_drop

    keys = ("max_delta_ratio", "fitted_delta_ratio_max", "fitted_range_status", "extrapolated")
    impact = simulate(PAPER_ROD, velocity=FAST, **PAPER).to_dict()
    drop = simulate_drop(FlexibleRod.paper(), velocity=FAST, history=False, **PAPER).to_dict()
    for d in (impact, drop):
        assert all(k in d for k in keys)
    assert impact["fitted_range_status"] == drop["fitted_range_status"] == "verified"
    assert impact["fitted_delta_ratio_max"] == drop["fitted_delta_ratio_max"] == 1.0
