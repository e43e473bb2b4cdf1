"""FlexibleRod's default mode counts by frequency: every rod's defaults reach the band that the
paper's rod's 8 axial + 12 bending modes cover (``AXIAL_CUTOFF_HZ``, ``BENDING_CUTOFF_HZ``),
the paper's rod keeps exactly 8 + 12, and the axial residual pseudo-modes follow n_axial."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab import ImplausibleInputWarning
from impactlab.bodies import FlexibleRod
from impactlab.bodies.beam_modes import axial_frequencies, eb_frequencies
from impactlab.bodies.flexible_rod import (
    AXIAL_CUTOFF_HZ,
    BENDING_CUTOFF_HZ,
    DEFAULT_N_AXIAL,
    DEFAULT_N_BENDING,
    MAX_MODES,
)
from impactlab.bodies.timoshenko import timoshenko_frequencies
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.provenance import decode, encode
from impactlab.sweep.flexible import evaluate_flexible, flexible_body
from impactlab.sweep.inputs import INPUTS
from impactlab.sweep.models import Statics

#: The rod of the paper's section, twice as long (L = 0.6 m, d = 15.7 mm).
LONG = {"length": 0.6, "tip_radius": 0.0088, "diameter": 0.0157}


def _hz(om: np.ndarray) -> np.ndarray:
    return np.asarray(om) / (2.0 * math.pi)


def test_the_papers_rod_keeps_8_and_12() -> None:
    """The cutoffs lie between the paper's rod's 7th and 8th axial and 11th and 12th bending
    modes, so its defaults are the former fixed ones, with either beam theory."""
    rod = FlexibleRod.paper()
    sec = rod.section
    ax = _hz(axial_frequencies(sec, DEFAULT_N_AXIAL))
    be = _hz(timoshenko_frequencies(sec, DEFAULT_N_BENDING))
    assert ax[-2] < AXIAL_CUTOFF_HZ <= ax[-1]
    assert be[-2] < BENDING_CUTOFF_HZ <= be[-1]
    assert (rod.n_axial, rod.n_bending, rod.axial_residual) == (8, 12, True)
    assert rod == FlexibleRod.paper(n_axial=8, n_bending=12, axial_residual=True)
    eb = FlexibleRod.paper(theory="euler-bernoulli")
    assert (eb.n_axial, eb.n_bending) == (DEFAULT_N_AXIAL, DEFAULT_N_BENDING)
    short = FlexibleRod(length=0.15, tip_radius=0.0088, diameter=0.0157)
    assert (short.n_axial, short.n_bending) == (DEFAULT_N_AXIAL, DEFAULT_N_BENDING)  # the floor


def test_a_longer_rod_gets_the_modes_of_the_same_band() -> None:
    rod = FlexibleRod(**LONG)
    assert (rod.n_axial, rod.n_bending, rod.axial_residual) == (16, 25, True)
    f = rod.frequencies_hz
    ax, be = f[: rod.n_axial], f[rod.n_axial : rod.n_axial + rod.n_bending]
    assert ax[-2] < AXIAL_CUTOFF_HZ <= ax[-1]
    assert be[-2] < BENDING_CUTOFF_HZ <= be[-1]
    assert "n_axial=16, n_bending=25" in repr(rod)
    assert "n_axial = 16, n_bending = 25" in str(rod)
    data = encode(rod)  # the JSON of a drop's record: the counts used
    assert (data["n_axial"], data["n_bending"], data["axial_residual"]) == (16, 25, True)
    assert decode(data) == rod


def test_one_family_given_the_other_by_frequency() -> None:
    rod = FlexibleRod(**LONG, n_bending=12)
    assert (rod.n_axial, rod.n_bending) == (16, 12)
    rod = FlexibleRod(**LONG, n_axial=4, axial_residual=False)
    assert (rod.n_axial, rod.n_bending, rod.axial_residual) == (4, 25, False)


@settings(max_examples=12, deadline=None)
@given(
    diameter=st.floats(0.003, 0.025),
    slenderness=st.floats(12.0, 60.0),
    theory=st.sampled_from(["timoshenko", "euler-bernoulli"]),
)
def test_the_default_is_the_fewest_that_reach_the_band(
    diameter: float, slenderness: float, theory: str
) -> None:
    """Per family: at least the paper's rod's count; the highest mode reaches the cutoff (or
    MAX_MODES are used); one mode fewer would not reach it."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImplausibleInputWarning)
        rod = FlexibleRod(
            length=diameter * slenderness, tip_radius=diameter, diameter=diameter, theory=theory
        )
    sec = rod.section
    bending: Callable[..., np.ndarray] = (
        timoshenko_frequencies if theory == "timoshenko" else eb_frequencies
    )
    for n, fewest, cutoff, freqs in (
        (rod.n_axial, DEFAULT_N_AXIAL, AXIAL_CUTOFF_HZ, axial_frequencies),
        (rod.n_bending, DEFAULT_N_BENDING, BENDING_CUTOFF_HZ, bending),
    ):
        assert isinstance(n, int) and fewest <= n <= MAX_MODES
        f = _hz(freqs(sec, n))
        assert f[-1] >= cutoff or n == MAX_MODES
        assert n == fewest or f[-2] < cutoff


def test_a_thick_rods_basis_reaches_the_band() -> None:
    """L/d = 8, d = 74 mm: the shear cut-off (25 kHz) lies inside the band, where the bending
    spectrum has near-double roots; the count is that of the basis's own highest root."""
    rod = FlexibleRod(length=0.59375, tip_radius=0.0742, diameter=0.0742)
    f = rod.frequencies_hz[rod.n_axial : rod.n_axial + rod.n_bending]
    assert rod.n_bending > DEFAULT_N_BENDING and f[-1] >= BENDING_CUTOFF_HZ


def test_a_rod_beyond_max_modes_warns_and_gets_max_modes() -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rod = FlexibleRod(length=5.0, tip_radius=0.0088, diameter=0.0157)
    texts = [str(w.message) for w in caught if w.category is ImplausibleInputWarning]
    assert len(texts) == 2
    assert texts[0].startswith("n_axial: the rod's 128 axial modes (MAX_MODES) reach 64.8 kHz")
    assert texts[1].startswith("n_bending: the rod's 128 bending modes (MAX_MODES) reach 17.6")
    assert (rod.n_axial, rod.n_bending) == (MAX_MODES, MAX_MODES)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        FlexibleRod(length=5.0, tip_radius=0.0088, diameter=0.0157, n_axial=8, n_bending=12)


def test_axial_residual_follows_n_axial() -> None:
    """As the command line and study files have it: no axial mode, no residual pseudo-modes;
    asked for with no axial mode, one line naming both and the fix."""
    rod = FlexibleRod.paper(n_axial=0)
    assert rod.axial_residual is False and rod.basis().n_modes == 12
    assert FlexibleRod.paper(n_axial=1).axial_residual is True
    assert FlexibleRod.paper(axial_residual=False).basis().n_modes == 20
    with pytest.raises(
        ValueError, match=r"axial_residual=True needs n_axial >= 1, got n_axial=0 \(leave"
    ):
        FlexibleRod.paper(n_axial=0, axial_residual=True)


def test_a_sweep_row_without_counts_gets_the_defaults_by_frequency() -> None:
    row = {k: math.nan for k in ("inertia", "radius", "tip_radius", "n_axial", "n_bending")}
    row |= {"length": math.nan, "mass": math.nan, "damping": math.nan}
    paper = FlexibleRod.paper()
    assert flexible_body(row, paper.material) == paper
    long = flexible_body(row | {"length": 0.6, "mass": 2 * 0.4607}, paper.material)
    assert (long.n_axial, long.n_bending, long.axial_residual) == (16, 25, True)
    zero = flexible_body(row | {"n_axial": 0.0}, paper.material)
    assert (zero.n_axial, zero.n_bending, zero.axial_residual) == (0, 12, False)


def test_the_long_rods_default_finds_the_converged_contacts() -> None:
    """The 0.6 m rod at 20 deg: 8 + 12 modes gave 18 contacts and e 0.719; the band's
    16 + 25 give the 9 contacts of 24 + 36 modes and of the finite-element reference, and e
    within 0.5 % of 24 + 36 (0.692)."""
    kw = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2, "history": False}
    r = simulate_drop(FlexibleRod(**LONG), **kw)
    assert r.ok and r.n_contacts == 9
    assert r.e == pytest.approx(0.692, rel=5e-3)
    assert r.dent_depth == pytest.approx(31.7e-6, rel=5e-3)


def test_the_cli_names_its_option_for_a_count_beyond_max_modes(
    cli_main: Callable[..., tuple[int, str, str]],
) -> None:
    code, _, err = cli_main(
        "drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--modes-bending", "500"
    )
    assert code == 2
    assert (
        "--modes-bending must be an integer in [0, 128], got 500" in err and "n_bending" not in err
    )


def test_the_docs_state_the_cutoffs() -> None:
    text = " ".join((Path(__file__).parents[2] / "docs" / "flexible.md").read_text().split())
    assert f"`AXIAL_CUTOFF_HZ` = {AXIAL_CUTOFF_HZ / 1e3:g} kHz" in text
    assert f"`BENDING_CUTOFF_HZ` = {BENDING_CUTOFF_HZ / 1e3:g} kHz" in text


def test_a_sweep_over_length_runs_each_body_with_its_own_counts() -> None:
    """The chunk's cases group by body (the length among the inputs), each group one batch
    with its own default counts: equal to the drop of the same FlexibleRod."""
    n = 2
    cases = {
        k: np.full(n, np.nan if s.default is None else float(s.default))
        for k, s in INPUTS.items()
        if s.kind == "float"
    }
    cases |= {"length": np.array([np.nan, 0.6]), "angle": np.radians([20.0, 20.0])}
    cases |= {"vy": np.full(n, -1.41), "vx": np.zeros(n), "spin": np.zeros(n)}
    cases["mu"] = np.full(n, 0.2)
    cat = {k: str(s.default) for k, s in INPUTS.items() if s.kind == "category"}
    cat |= {"body": "flexible_rod", "friction": "coulomb", "law": "ghaednia"}
    res, status = evaluate_flexible(cases, Statics(cat), ("e", "dent_depth"))
    assert (status == 0).all()
    paper = FlexibleRod.paper()
    long = FlexibleRod(length=0.6, tip_radius=paper.tip_radius, mass=paper.mass)
    assert (long.n_axial, long.n_bending) == (16, 28)  # d = 11.2 mm from the mass
    for i, body in enumerate((paper, long)):
        r = simulate_drop(body, mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))
        assert (res["e"][i], res["dent_depth"][i]) == (r.e, r.dent_depth)
