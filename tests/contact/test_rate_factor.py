"""The self-consistent rate factor (``contact.rate_factor``): it converges where the map is
steep (plain steps crept there and stopped after 12 drops, silently unconverged), warns where
it still does not, refuses in one line a factor that would raise a yield strength above E
(naming the law, its constants, the strain rate and k) and warns where the rate law leaves the
drop without a dent; the paper's drops keep their factors bit for bit."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable

import pytest

from impactlab._validation import ImplausibleInputWarning
from impactlab.bodies import PAPER_ROD, FlexibleRod
from impactlab.contact.rate import (
    COWPER_SYMONDS_MILD_STEEL,
    RateFactor,
    RateFactorWarning,
    RateLaw,
    RateLimit,
    rate_materials,
    self_consistent_factor,
)
from impactlab.contact.rate_factor import warn_no_dent
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.materials import AISI_1010

#: The paper's 20 deg drop.
DROP = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2, "history": False}
#: A steep law: plain steps creep (slope about 0.6; after 12 drops the change of k was still
#: 9.7e-4, ten times the tolerance).
STEEP = RateLaw.custom("cowper-symonds", D="450 1/s", q=0.2)
#: A law and contact radius a(k) = 0.686 m exp(-k) whose map k -> law.factor(0.2 |v| / a(k))
#: at v = 1.41 m/s is 1 + 0.9 (ln(0.411) + k): slope 0.9, fixed point k = 2.0; plain steps
#: need about 80 drops to change k by less than 1e-4.
LINEAR = RateLaw.custom("johnson-cook", C=0.9, rate0="1 1/s")


def _drop(rate: str | RateLaw) -> DropResult:
    return simulate_drop(FlexibleRod.paper(), rate=rate, **DROP)  # type: ignore[arg-type]


def _radius(k: float) -> float:
    """The contact radius of :data:`LINEAR`'s map [m]."""
    return 0.686 * math.exp(-k)


def test_a_steep_map_converges_and_is_self_consistent() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", RateFactorWarning)
        f = self_consistent_factor(_radius, LINEAR, 1.41)
    assert f.converged and f.change <= 1e-4 and f.iterations < 12
    assert f.k == pytest.approx(LINEAR.factor(0.2 * 1.41 / _radius(f.k)), rel=2e-4)
    fixed = (1.0 + 0.9 * math.log(0.2 * 1.41 / 0.686)) / 0.1
    assert f.k == pytest.approx(fixed, rel=1e-6)


def test_a_factor_without_bound_is_refused() -> None:
    """A map with no fixed point (k grows as k^4.5): a one-line error, not an overflow."""
    with pytest.raises(ValueError, match=r"^rate 'cowper-symonds \(D = 450 1/s, q = 0.2\)'"):
        self_consistent_factor(lambda k: 6e-4 * k**-0.9, STEEP, 1.41)


def test_the_papers_drop_on_a_steep_law_converges() -> None:
    """Cowper-Symonds D = 450 1/s, q = 0.2 on the paper's 20 deg drop: k = 2.2022, k equal to
    the law's factor at the strain rate it reports (it stopped at 2.1989, unconverged)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RateFactorWarning)
        r = _drop(STEEP)
    assert r.rate_factor == pytest.approx(2.2022, abs=2e-4)
    assert r.rate_factor == pytest.approx(STEEP.factor(r.strain_rate), rel=1e-4)


def test_an_unconverged_factor_warns_naming_the_law_and_the_change() -> None:
    with pytest.warns(RateFactorWarning) as caught:
        f = self_consistent_factor(_radius, LINEAR, 1.41, max_iter=2)
    (w,) = caught
    text = str(w.message)
    assert not f.converged and f.iterations <= 2 and f.change > 1e-4
    assert text.startswith("rate 'johnson-cook (C = 0.9, rate0 = 1 1/s)': the self-consistent")
    assert "did not converge in 2 drops (last relative change of k " in text
    assert "tolerance 0.0001" in text and "\n" not in text


def test_max_iter_must_be_a_count() -> None:
    for bad in (0, 2.5, True):
        with pytest.raises(ValueError, match=r"max_iter must be an int >= 1"):
            self_consistent_factor(_radius, LINEAR, 1.41, max_iter=bad)  # type: ignore[arg-type]


def test_the_papers_factors_are_unchanged() -> None:
    """The flat map of the paper's drops takes plain steps: k as before, to round-off (the
    compiled drop's bits differ between processors by about 1e-13)."""
    assert _drop("cowper-symonds").rate_factor == pytest.approx(2.6445015516165498, rel=1e-11)
    assert _drop("johnson-cook").rate_factor == pytest.approx(1.1316113343361407, rel=1e-11)


def test_the_limit_of_the_papers_pair() -> None:
    """k S_y below the flat's E and the rod's raised yield strength (1.5 k S_y) below its E."""
    lim = RateLimit.of(PAPER_ROD.material, AISI_1010)
    sy = AISI_1010.yield_strength
    expected = min(AISI_1010.E / sy, PAPER_ROD.material.E / (1.5 * sy))
    assert lim.k_max == pytest.approx(expected, rel=1e-12)
    assert lim.yield_strength == sy
    body, flat = rate_materials(PAPER_ROD.material, AISI_1010, 0.999 * lim.k_max)
    assert flat.yield_strength < flat.E and body.yield_strength < body.E


def test_a_factor_above_the_limit_is_refused_in_one_line() -> None:
    """Cowper-Symonds D = 300 1/s, q = 0.1: the law gives k = 790 (S_y 241 GPa). It printed two
    "check the units" warnings on the rate-raised material and then "yield_strength (...)
    must be smaller than E", naming neither the rate law nor k."""
    law = RateLaw.custom("cowper-symonds", D="300 1/s", q=0.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        with pytest.raises(ValueError, match="must stay below") as info:
            _drop(law)
    text = str(info.value)
    assert text.startswith("rate 'cowper-symonds (D = 300 1/s, q = 0.1)': at the contact's ")
    assert "strain rate 584.6 1/s" in text and "the factor k = 790.2" in text
    assert "305 MPa to 241 GPa; k must stay below 437.2" in text
    assert "check the law's constants" in text and "\n" not in text


def test_the_command_line_names_rate(cli_main: Callable[..., tuple[int, str, str]]) -> None:
    code, _, err = cli_main(
        "drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2",
        "--rate", "cowper-symonds(D=300 1/s, q=0.1)",
    )  # fmt: skip
    assert code != 0
    assert err.startswith("error: --rate 'cowper-symonds (D = 300 1/s, q = 0.1)': at the ")
    assert "k = 790.2" in err and "warning" not in err and "check the units" not in err


def test_a_factor_that_leaves_no_dent_warns() -> None:
    """Cowper-Symonds D = 350 1/s, q = 0.15: the self-consistent k = 32.8 raises S_y to 10 GPa
    and the drop leaves no dent, where the rate-independent flat yields (it said nothing)."""
    law = RateLaw.custom("cowper-symonds", D="350 1/s", q=0.15)
    with pytest.warns(RateFactorWarning, match=r"so the drop leaves no dent") as caught:
        r = _drop(law)
    assert r.dent_depth == 0.0 and r.rate_factor == pytest.approx(32.83, abs=0.01)
    text = str(caught[0].message)
    assert text.startswith("rate 'cowper-symonds (D = 350 1/s, q = 0.15)': the self-consistent")
    assert "k = 32.83 (strain rate 588.2 1/s)" in text and "10.01 GPa" in text


def test_no_dent_warns_only_where_the_rate_removed_it() -> None:
    """No warning with a dent, nor where the rate-independent flat would not yield either."""
    f = RateFactor(2.6, 486.0, 5.8e-4, 4)
    onsets = (0.44e-6, 3.0e-6)  # rate-independent, rate-raised yield onsets [m]
    with warnings.catch_warnings():
        warnings.simplefilter("error", RateFactorWarning)
        warn_no_dent(COWPER_SYMONDS_MILD_STEEL, f, 305e6, onsets, 1e-6, 5e-6)  # a dent
        warn_no_dent(COWPER_SYMONDS_MILD_STEEL, f, 305e6, onsets, 0.0, 0.4e-6)  # elastic anyway
    with pytest.warns(RateFactorWarning, match=r"stays below the raised yield onset 3 um"):
        warn_no_dent(COWPER_SYMONDS_MILD_STEEL, f, 305e6, onsets, 0.0, 1e-6)


def test_rate_raised_materials_do_not_say_check_the_units() -> None:
    """The rate-raised copies are derived, not given: no plausibility warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        _, flat = rate_materials(PAPER_ROD.material, AISI_1010, 400.0)
    assert flat.yield_strength == pytest.approx(400.0 * AISI_1010.yield_strength)
    assert COWPER_SYMONDS_MILD_STEEL.text == "cowper-symonds (D = 40.4 1/s, q = 5)"
