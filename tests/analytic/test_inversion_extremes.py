"""``invert`` at the edges of its inputs: a required input given as None is named, a sigma
below the value's rounding gives a finite first-order uncertainty (never NaN, no numpy
warning), |v_i| has a lower bound, and a rod or inputs whose results over- or underflow are
refused with the inputs named, never returned as inf or 0."""

from __future__ import annotations

import math
import types
import warnings
from typing import Any

import pytest
from inversion_cases import PAPER_20

from impactlab.analytic import invert
from impactlab.analytic._conditioning import check_finite_result
from impactlab.analytic._measurements import MIN_SPEED, PLAUSIBLE_MIN_SPEED
from impactlab.analytic.result import Measured

BASE: dict[str, Any] = {**PAPER_20, "n_samples": 500}
NUMBERS = ("duration", "mean_force", "sigma_T_linear", "sigma_F_linear", "T_mc", "F_mc",
           "sigma_T_mc", "sigma_F_mc")  # fmt: skip


def _quiet(**kw: Any) -> Any:
    """``invert(**BASE | kw)`` with any RuntimeWarning (numpy's 0/0, overflow) an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        return invert(**{**BASE, **kw})


@pytest.mark.parametrize("name", ["angle", "v_i", "mu", "delta_p", "sliding_length"])
def test_a_required_input_given_as_none_is_named(name: str) -> None:
    with pytest.raises(ValueError, match=rf"^{name} is required \(.+\), got None$"):
        invert(**{**BASE, name: None})


@pytest.mark.parametrize(
    "kw",
    [
        {"e": (0.5, 1e-13), "mu": (0.2, 0.01)},
        {"e": (0.5, 1e-310)},
        {"e": (0.5, 5e-324)},
        {"vt_in": (0.0, 5e-324)},
        {"vt_in": (-1e-300, 1e-310)},
        {"dv_cy": (0.6, 1e-300), "e": None},
        {"sliding_length": (1400e-6, 1e-25)},
    ],
)
def test_a_sigma_below_the_rounding_gives_finite_uncertainties(kw: dict[str, Any]) -> None:
    r = _quiet(**kw)
    for name in NUMBERS:
        assert math.isfinite(getattr(r, name)), name
    assert all(math.isfinite(v) for v in r.sensitivity_T.values())


def test_a_negligible_sigma_adds_nothing_to_the_first_order_sigma() -> None:
    alone = _quiet(mu=(0.2, 0.01))
    both = _quiet(mu=(0.2, 0.01), e=(0.5, 1e-13))
    assert both.sigma_T_linear == pytest.approx(alone.sigma_T_linear, rel=1e-9)
    assert both.sigma_F_linear == pytest.approx(alone.sigma_F_linear, rel=1e-6)
    # the derivative itself is right at the smallest step
    assert both.sensitivity_F["e"] == pytest.approx(_quiet(e=(0.5, 0.01)).sensitivity_F["e"])


@pytest.mark.parametrize("v_i", [1e-200, -1e-310, 0.99e-6])
def test_a_drop_speed_below_the_bound_is_refused(v_i: float) -> None:
    with pytest.raises(ValueError, match=rf"^v_i = .* m/s is below {MIN_SPEED:g} m/s"):
        invert(**{**BASE, "v_i": v_i})


def test_a_zero_drop_speed_keeps_its_own_error() -> None:
    with pytest.raises(ValueError, match="v_i must be non-zero"):
        invert(**{**BASE, "v_i": 0.0})


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")
@pytest.mark.parametrize("v_i", [MIN_SPEED, 1e-5, (1e-6, 1e-6)])
def test_a_slow_drop_warns_and_stays_finite(v_i: Any) -> None:
    r = _quiet(v_i=v_i)
    assert any(f"below {PLAUSIBLE_MIN_SPEED:g} m/s" in w for w in r.warnings)
    for name in NUMBERS:
        assert math.isfinite(getattr(r, name)) and getattr(r, name) >= 0.0, name
    assert r.mean_force > 0.0


def test_the_paper_drops_do_not_warn_of_a_slow_drop() -> None:
    assert not any("below" in w for w in _quiet().warnings)


@pytest.mark.parametrize(
    ("mass", "inertia", "name"), [(1e-310, None, "rod.mass"), (0.46, 1e-310, "rod.inertia")]
)
def test_a_rod_whose_coefficients_overflow_is_refused(
    mass: float, inertia: float | None, name: str
) -> None:
    """A rod object the body constructors' ranges do not guard (any object with a rod's
    attributes is read): its K_x, K_y overflow, refused with its values named."""
    rod = types.SimpleNamespace(mass=mass, length=0.3048, tip_radius=0.0088, inertia=inertia)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(ValueError, match=rf"impulse coefficients are not finite.*{name} ="):
            invert(**BASE, rod=rod)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("values", "named"),
    [
        ({"duration": math.inf}, "duration = inf"),
        ({"mean_force": 0.0}, "mean_force = 0.0"),
        ({"sigma_T_mc": math.nan}, "sigma_T_mc = nan"),
        ({"T_interval_mc": (1e-3, math.inf)}, "T_interval_mc = inf"),
    ],
)
def test_an_overflowing_result_is_refused_naming_the_inputs(
    values: dict[str, Any], named: str
) -> None:
    meas = {"v_i": Measured(1e-6, 0.0), "mu": Measured(0.2, 0.01)}
    rod = {"mass": 0.46, "length": 0.3048}
    with pytest.raises(ValueError, match=named) as info:
        check_finite_result(values, meas, rod)
    assert "v_i = 1e-06" in str(info.value) and "mu = 0.2 +- 0.01" in str(info.value)
    assert "rod.mass = 0.46 kg" in str(info.value)


def test_a_zero_sigma_or_count_is_no_underflow() -> None:
    check_finite_result({"sigma_T_mc": 0.0, "mc_rejected": 0.0, "mc_used": 0}, {}, {})
