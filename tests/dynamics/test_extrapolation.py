"""A result says whether its impact stayed inside the contact law's fitted range:
``ImpactResult.max_delta_ratio``, ``.extrapolated``, the flag ``LAW_EXTRAPOLATED`` with its
sentence (how far it went), on single results, batches (``run_arrays``' ``flags`` column) and
sweep stores. Outputs beyond the range stay finite and
energy-consistent: the flag is advisory (``ok`` stays True)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.contact import get_law
from impactlab.contact.ranges import law_extrapolated, law_range
from impactlab.dynamics import OUTPUT_FIELDS, simulate, simulate_batch
from impactlab.dynamics.batch import run_arrays
from impactlab.flags import ADVISORY_FLAGS, FLAG_LAW_EXTRAPOLATED, ResultFlag, messages
from impactlab.friction import FRICTION_IDS
from impactlab.materials import AISI_201, AISI_1010, ContactPair
from impactlab.sweep import Study, run_sweep

PAPER = {"law": "ghaednia", "friction": "coulomb", "mu": 0.2, "angle": math.radians(20)}
#: the paper's 20-degree impact at 1.41 m/s, and a gentle one (delta_max/delta_c about 45)
FAST, GENTLE = (0.0, -1.41), (0.0, -0.3)


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
    assert ratio > law_range("ghaednia").delta_ratio_max  # beyond the (provisional) 110
    assert r.extrapolated and ResultFlag.LAW_EXTRAPOLATED in r.flags
    assert r.ok  # advisory: the measures stay readable
    (text,) = r.warnings
    assert text.startswith("law extrapolated:")
    assert f"max delta/delta_c = {ratio:.4g}, provisional limit 110" in text
    assert "fitted up to" not in text and "energy-consistent" not in text
    assert "warning" in str(r) and "law extrapolated" in str(r)
    d = r.to_dict()
    assert d["flags"] == FLAG_LAW_EXTRAPOLATED and d["warnings"] == [text]


def test_outputs_beyond_the_range_are_finite_and_energy_consistent() -> None:
    r = simulate(PAPER_ROD, velocity=(0.0, -3.45), **PAPER)
    assert r.extrapolated and r.max_delta_ratio > 200.0
    values = [r.e, r.delta_max, r.delta_p, r.duration, r.max_force, r.energy_dissipated]
    assert np.all(np.isfinite(values)) and 0.0 < r.e < 1.0
    assert r.energy_dissipated > 0.0  # no energy gain beyond the range


def test_gentle_impact_is_not_flagged() -> None:
    r = simulate(PAPER_ROD, velocity=GENTLE, **PAPER)
    assert 1.0 < r.max_delta_ratio < law_range("ghaednia").delta_ratio_max
    assert not r.extrapolated and r.flags == ResultFlag.NONE and r.warnings == ()


@pytest.mark.parametrize("law", ["brake", "thornton"])
def test_analytical_laws_are_not_flagged(law: str) -> None:
    r = simulate(PAPER_ROD, velocity=FAST, **(PAPER | {"law": law}))
    assert r.max_delta_ratio > 100.0 and not r.extrapolated


def test_hertz_beyond_first_yield_is_flagged() -> None:
    """Hertz holds up to first yield (delta_c of the pair): the paper's impact is far past it."""
    r = simulate(PAPER_ROD, velocity=FAST, **(PAPER | {"law": "hertz"}))
    assert r.max_delta_ratio == pytest.approx(r.delta_max / _delta_c(), rel=1e-9)
    assert r.extrapolated and r.ok


def test_batch_and_run_arrays_carry_the_flag() -> None:
    b = simulate_batch(
        PAPER_ROD, law="ghaednia", friction="coulomb", mu=0.2, angle=PAPER["angle"],
        vy=[-1.41, -0.3, -1.41, -1.41], vx=[0.0, 0.0, 0.0, math.nan],
    )  # fmt: skip
    np.testing.assert_array_equal(b.flags, [4, 0, 4, 0])
    assert np.isnan(b["flags"][3])  # a failed case has no outputs
    single = simulate(PAPER_ROD, velocity=FAST, **PAPER)
    assert b.flags[0] == int(single.flags)
    model = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), PAPER_ROD.tip_radius)
    np.testing.assert_array_equal(law_extrapolated(model, b.delta_max[:3]), [True, False, True])
    # run_arrays directly, one parameter row for all cases and one per case
    init = np.array([[PAPER["angle"], 0.0, -1.41, 0.0], [PAPER["angle"], 0.0, -0.3, 0.0]])
    body = PAPER_ROD.to_params(AISI_1010)
    for lp in (model.params, np.stack([model.params] * 2)):
        out, st = run_arrays(model.law_id, FRICTION_IDS["coulomb"], lp, body, init, 0.2)
        assert list(st) == [0, 0]
        np.testing.assert_array_equal(out[:, OUTPUT_FIELDS.index("flags")], [4.0, 0.0])


def test_tiny_sweep_stores_the_flag(tmp_path: Path) -> None:
    study = Study.from_dict(
        {
            "study": {"name": "range", "chunk_size": 2},
            "fixed": {"law": "ghaednia", "angle": "20 deg", "mu": 0.2},
            "grid": {"vy": [-1.41, -0.3]},
            "outputs": {"keep": ["e", "delta_max"]},
        }
    )
    ds = run_sweep(study, tmp_path / "r.zarr", quiet=True).dataset.load()
    np.testing.assert_array_equal(ds["flags"].values, [4, 0])
    assert "law_extrapolated" in ds["flags"].attrs["flag_meanings"].split()


def test_flag_message_and_advisory_mask() -> None:
    assert ADVISORY_FLAGS == FLAG_LAW_EXTRAPOLATED
    (generic,) = messages(FLAG_LAW_EXTRAPOLATED)
    assert generic.startswith("law extrapolated: the largest interference exceeded")
    assert "max delta" not in generic  # how far is unknown without the numbers
    (far,) = messages(FLAG_LAW_EXTRAPOLATED, extrapolation=(312.4, 110.0), status="confirmed")
    assert "(max delta/delta_c = 312.4, fitted up to 110)" in far
    assert messages(4, extrapolation=(math.nan, math.inf)) == (generic,)


@pytest.mark.parametrize("status", [None, "confirmed", "provisional", "theory"])
def test_extrapolation_message_depends_on_the_range_status(status: str | None) -> None:
    """QA: the sentence never claims energy consistency, points to the docs and words the limit
    after the range's status (provisional: a stand-in; theory: first yield, not fitted)."""
    (text,) = messages(FLAG_LAW_EXTRAPOLATED, extrapolation=(5.0, 1.0), status=status)
    assert "energy-consistent" not in text and "impactlab.contact.ranges" not in text
    assert "see the docs' Contact laws > Fitted ranges" in text
    if status == "provisional":
        assert "provisional limit 1)" in text and "stand-in" in text
        assert "fitted up to" not in text
    elif status == "theory":
        assert "first yield" in text and "fitted" not in text
    elif status == "confirmed":
        assert "fitted up to 1)" in text


def test_hertz_warning_names_first_yield_not_a_fit() -> None:
    r = simulate(PAPER_ROD, velocity=FAST, **{**PAPER, "law": "hertz"})
    assert r.extrapolated
    (text,) = [w for w in r.warnings if w.startswith("law extrapolated")]
    assert "first yield" in text and "fitted" not in text


def test_rigid_outputs_carry_max_delta_ratio() -> None:
    """QA: to_dict and the batch's Dataset report max_delta_ratio (and to_dict extrapolated)."""
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
