"""An uncertain incoming tangential velocity ``vt_in``: Monte Carlo samples that reach the pole
of Eq. 12 (vt_in >= |alpha| |v_i|) draw the heavy-tail warning, samples with vt_in > 0 (T only
an upper bound) draw a warning with both bounds' medians and intervals where they move them,
inputs far from both stay as they were; and the conditioning's words near 90 deg quote an
absolute angle error, never a 1 % that would pass 90 deg."""

from __future__ import annotations

import math
import warnings

import pytest

from impactlab import analytic as an
from impactlab.analytic.inversion import REVERSAL_LEAN

BASE = dict(angle="20 deg", v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1400e-6)
#: |alpha| |v_i| at 20 deg, mu = 0.2 (the paper's rod): the pole of Eq. 12 in vt_in [m/s]
POLE = abs(an.alpha(math.radians(20), 0.2)) * 1.41


def _run(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return an.invert(**{**BASE, **kw})


def _pole_words(res) -> list[str]:
    return [w for w in res.warnings if "the pole of Eq. 12" in w]


def _reversal_words(res) -> list[str]:
    return [w for w in res.warnings if "of the Monte Carlo samples have vt_in > 0" in w]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_samples_past_the_pole_draw_the_heavy_tail_warning(seed: int) -> None:
    res = _run(vt_in=(-0.2, 0.3), seed=seed)
    assert POLE == pytest.approx(0.3423, abs=1e-4)
    # under the 5 % of discarded samples that alone would warn
    assert res.mc_rejected < 0.05
    (pole,) = _pole_words(res)
    assert "reached vt_in >= |alpha| |v_i|, the pole of Eq. 12 (0.3423 m/s" in pole
    assert "vt_in = -0.2 +- 0.3 m/s was given" in pole
    assert "grows without limit: a heavy tail" in pole
    assert "sigma_T_mc and T_mc (and F's) depend on the seed" in pole
    assert "narrow the sigma of vt_in" in pole
    # the median and interval hold; the mean and spread do not
    assert res.T_median_mc == pytest.approx(2.53e-3, rel=0.02)
    assert res.sigma_T_mc > 10 * res.sigma_T_linear


def test_the_pole_reached_through_alpha_is_warned_with_gravity_in_its_own_words() -> None:
    # vt_in exact, 0.3 m/s (within the nominal pole), mu uncertain: |alpha| |v_i| varies
    res = _run(vt_in=0.3, mu=(0.2, 0.03), gravity=True)
    (pole,) = _pole_words(res)
    assert "vt_in = 0.3 m/s was given" in pole and "grows steeply" in pole
    assert "without a finite variance" not in pole


def test_a_vt_in_two_sigma_above_0_is_warned_as_an_upper_bound() -> None:
    res = _run(vt_in=(0.1, 0.05))
    assert res.duration == pytest.approx(5.8007e-3, rel=1e-4)
    assert not _pole_words(res)
    (rev,) = _reversal_words(res)
    assert rev.startswith("97.8% of the Monte Carlo samples have vt_in > 0 (vt_in = 0.1 +- 0.05")
    lower = an.invert(**BASE).duration  # vt_in = 0: the lower bound
    assert f"they are {lower:.4g} s" in rev
    assert f"T_median_mc = {res.T_median_mc:.4g} s" in rev
    assert "the duration given, at vt_in = 0.1 m/s, is an upper bound too" in rev
    # the nominal warning with T's bounds stays for beyond 3 sigma only: one warning, not two
    assert not any("T lies between" in w for w in res.warnings)


def test_beyond_three_sigma_only_the_nominal_bounds_are_warned() -> None:
    res = _run(vt_in=(0.1, 0.02))
    assert [w for w in res.warnings if "T lies between" in w]
    assert not _reversal_words(res)


def test_a_small_positive_share_that_moves_nothing_is_not_warned() -> None:
    # the shipped example's measured vt_in beside its other uncertainties
    res = _run(
        vt_in=(0.0023, 0.0013),
        angle=(math.radians(20.05), 0.0007),
        v_i=(-1.4136, 0.0024),
        mu=(0.197, 0.0041),
        sliding_length=(1406e-6, 9.3e-6),
        e=(0.501, 0.007),
    )
    assert not res.warnings
    assert REVERSAL_LEAN == 0.25


@pytest.mark.parametrize("vt", [(-0.3, 0.01), (-0.1, 0.02), 0.0, -0.2])
def test_far_from_the_pole_nothing_is_warned(vt) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = an.invert(**BASE, vt_in=vt, n_samples=2000)
    assert res.warnings == () and res.mc_rejected == 0.0


def test_near_90_deg_the_angle_error_is_absolute() -> None:
    res = _run(angle="89.5 deg", mu=0.0, n_samples=100)
    (cond,) = res.warnings
    assert "an error of 0.1 deg in the angle moves T by about 20 %" in cond
    assert "1 % error in the angle" not in cond
    closer = _run(angle="89.9 deg", mu=0.0, n_samples=100)
    assert (
        "an error of 0.1 deg in the angle is over half its distance to 90 deg (0.1 deg)"
        in (closer.warnings[0])
    )
    near_mu_c = _run(angle="20 deg", mu=0.75, n_samples=100)
    assert "tangentially compliant" in near_mu_c.warnings[0]  # mu = 0.98 mu_c
    assert "a 1 % error in mu moves T by about 63.5 %" in near_mu_c.warnings[1]
