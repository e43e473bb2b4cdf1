"""The rate-dependent flat is used only where it holds: a rate law carries the material its
constants were fitted for, one's own constants are validated, Brake's law scales its hardness
with the rate, and an elastic law refuses a rate (impactlab.contact.rate, simulate_drop)."""

from __future__ import annotations

import dataclasses
import math

import pytest

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact.rate import RATE_LAWS, RateLaw, check_rate_flat, rate_materials
from impactlab.dynamics.drop import simulate_drop
from impactlab.materials import AISI_201, AISI_1010

AL_6061 = dataclasses.replace(
    AISI_1010, name="6061-T6", E=68.9e9, nu=0.33, yield_strength=276e6, density=2700.0,
    brinell_hardness=95.0,
)  # fmt: skip
DROP = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}
ROD = FlexibleRod.paper(n_axial=2, n_bending=4)


@pytest.mark.parametrize("rate", ["cowper-symonds", "johnson-cook"])
def test_mild_steel_constants_refused_on_aluminium(rate: str) -> None:
    assert RATE_LAWS[rate].fitted_for is not None
    check_rate_flat(RATE_LAWS[rate], AISI_1010)  # the paper's flat: fitted for it
    with pytest.raises(ValueError, match=r"fitted for low-carbon .* E = 68.9 GPa outside"):
        simulate_drop(ROD, AL_6061, rate=rate, **DROP)


def test_custom_constants_run_on_any_flat() -> None:
    law = RateLaw.custom("cowper-symonds", D=6500.0, q=4.0)
    r = simulate_drop(ROD, AL_6061, rate=law, **DROP)
    assert r.rate_factor == pytest.approx(law.factor(r.strain_rate), rel=1e-3)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"name": "cowper-symonds", "D": 40.4, "q": 0.0}, r"q must be > 0, got 0"),
        ({"name": "cowper-symonds", "D": -40.4, "q": 5.0}, r"D must be > 0 1/s, got -40.4"),
        ({"name": "swift", "C": 0.02}, r"RateLaw name must be one of .* got 'swift'"),
        ({"name": "johnson-cook", "D": 1.0}, r"takes the parameters \('C', 'rate0'\)"),
    ],
)
def test_custom_constants_are_validated(kwargs: dict, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        RateLaw.custom(**kwargs)


def test_rate_with_an_elastic_law_is_refused() -> None:
    with pytest.raises(ValueError, match=r"'hertz' law is elastic"):
        simulate_drop(ROD, law="hertz", rate="cowper-symonds", **DROP)


def test_brake_with_a_rate_scales_the_hardness() -> None:
    """The rate raised S_y but not the hardness, so Brake's Eq. 24 failed for any rate."""
    body, flat = rate_materials(AISI_201, AISI_1010, 2.0)
    assert flat.brinell_hardness == 2.0 * AISI_1010.brinell_hardness
    assert body.brinell_hardness / AISI_201.brinell_hardness == pytest.approx(
        body.yield_strength / AISI_201.yield_strength
    )
    static = simulate_drop(ROD, law="brake", **DROP)
    r = simulate_drop(ROD, law="brake", rate="cowper-symonds", **DROP)
    assert r.rate_factor > 2.0 and r.dent_depth < static.dent_depth


def test_brake_rate_failure_names_the_rate() -> None:
    with pytest.raises(ValueError, match=r"rate 'cowper-symonds': .*k = .*hardness"):
        simulate_drop(ROD, law="brake", rate="cowper-symonds", law_params={"hardness": 40.0},
                      **DROP)  # fmt: skip
