"""The conditioning of T near mu_c and near 90 deg: a warning that names it, and the units hint of
a long T only where the conditioning does not explain it."""

from __future__ import annotations

import math
import warnings

import pytest

from impactlab import analytic as an
from impactlab.analytic.inversion import CONDITION_LIMIT

DENT = dict(v_i=-1.41, e=0.5, delta_p=22e-6, sliding_length=1400e-6, n_samples=100)


def _warnings(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return an.invert(**{**DENT, **kw})


def test_near_mu_c_the_warning_names_mu_c_and_the_long_t_is_not_a_units_problem():
    r = _warnings(angle="20 deg", mu=0.75)
    assert r.duration == pytest.approx(0.1601, rel=1e-3)
    compliance, cond, long_t = r.warnings
    assert "tangentially compliant" in compliance  # mu = 0.98 mu_c
    assert cond.startswith("T is ill-conditioned here: a 1 % error in mu moves T by about 63.5 %")
    assert "mu = 0.75 lies 1.54 % below mu_c = 0.7618 at angle = 20 deg" in cond
    assert long_t.startswith("the inverted duration T = 0.1601 s exceeds 0.1 s")
    assert "units" not in long_t and "alpha is near 0" in long_t


def test_near_90_deg_the_angle_is_named():
    r = _warnings(angle="89.5 deg", mu=0.0)
    assert r.duration == pytest.approx(35.88e-3, rel=1e-3)
    (cond,) = r.warnings
    assert "an error of 0.1 deg in the angle moves T by about 20 %" in cond
    assert "0.5 deg from vertical" in cond


def test_a_long_t_of_a_well_conditioned_inversion_keeps_the_units_hint():
    r = _warnings(angle="20 deg", mu=0.2, v_i=-0.01)
    (long_t,) = r.warnings
    assert long_t.endswith("check the units of the inputs (SI)")


@pytest.mark.parametrize(
    ("deg", "v_i", "mu", "delta_p", "ls", "e"),
    [
        (20, 1.41, 0.2, 22e-6, 1400e-6, 0.5),
        (45, 2.18, 0.13, 26e-6, 1650e-6, 0.49),
        (70, 3.45, 0.10, 105e-6, 200e-6, 0.05),
    ],
)
def test_the_papers_drops_are_well_conditioned(deg, v_i, mu, delta_p, ls, e):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = an.invert(
            angle=math.radians(deg), v_i=v_i, mu=mu, delta_p=delta_p, sliding_length=ls, e=e
        )
    th = math.radians(deg)
    worst = max(
        abs(r.sensitivity_T["mu"] * mu / r.duration),
        abs(r.sensitivity_T["angle"] * th / r.duration),
    )
    assert worst < 3.0 < CONDITION_LIMIT
