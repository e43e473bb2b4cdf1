"""The inversion's refusals name the input to check: a mu so large that K_y < 0 (the tip
sticks) names mu, not the rod; an e outside [0, 1] says how to give its sigma on the command
line and in Python."""

from __future__ import annotations

import math

import pytest

from impactlab.analytic import invert
from impactlab.analytic._conditioning import check_coefficients

MEASURED = {"angle": math.radians(20), "v_i": -1.41, "e": 0.5, "delta_p": 22e-6,
            "sliding_length": 1.4e-3}  # fmt: skip


@pytest.mark.parametrize("mu", [4.0, 20.0])
def test_a_mu_that_makes_k_y_negative_is_named(mu: float) -> None:
    with pytest.raises(ValueError, match=r"^mu lies far above the critical mu_c") as err:
        invert(**MEASURED, mu=mu)
    assert "rod's impulse coefficients" not in str(err.value)


def test_coefficients_that_overflow_still_name_the_rod() -> None:
    with pytest.raises(ValueError, match="the rod's impulse coefficients are not finite"):
        check_coefficients(math.inf, 1.0, math.nan, {"mass": 1e-30})
    with pytest.raises(ValueError, match="the rod's impulse coefficients are not finite"):
        check_coefficients(1.0, 0.0, 1.0, {"mass": 1e30})  # underflowed to 0: not mu's


def test_an_e_above_one_says_how_to_give_its_sigma() -> None:
    with pytest.raises(ValueError, match=r"^e must lie in \[0, 1\]") as err:
        invert(**{**MEASURED, "e": 1.5}, mu=0.2)
    text = str(err.value)
    assert "--sigma-e on the command line" in text and "e=(value, sigma) in Python" in text
