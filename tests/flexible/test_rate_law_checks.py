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


def test_a_soft_rod_stays_soft_and_a_factor_of_one_is_no_rate() -> None:
    """A copper rod on steel: the rate raised the rod's S_y 10.8 times (to 1.5 times the
    flat's) and the rod's flattening came back as a dent in the flat; a law whose factor is
    exactly 1 gives the drop without a rate law."""
    import warnings

    from impactlab.materials import COPPER_OFHC

    rod = FlexibleRod.paper(material=COPPER_OFHC, mass=None, diameter=0.0176, n_axial=2,
                            n_bending=4)  # fmt: skip
    static = simulate_drop(rod, law="ghaednia", **DROP, history=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fast = simulate_drop(rod, law="ghaednia", rate="johnson-cook", **DROP, history=False)
        one = simulate_drop(rod, law="brake", rate=RateLaw.custom("johnson-cook", C=0.0, rate0=1.0),
                            **DROP, history=False)  # fmt: skip
    assert static.body_yields_first and fast.body_yields_first and fast.rate_factor > 1.0
    assert fast.dent_depth == static.dent_depth  # the rod's flattening, with its own S_y
    plain = simulate_drop(rod, law="brake", **DROP, history=False)
    assert one.rate_factor == 1.0 and one.dent_depth == plain.dent_depth and one.e == plain.e


def test_an_unconverged_rate_factor_is_not_ok(monkeypatch: pytest.MonkeyPatch) -> None:
    import functools

    import impactlab.dynamics.drop as D
    from impactlab.contact.rate import RateFactorWarning

    monkeypatch.setattr(D, "self_consistent_factor",
                        functools.partial(D.self_consistent_factor, max_iter=1))  # fmt: skip
    with pytest.warns(RateFactorWarning, match="did not converge in 1 drops"):
        r = simulate_drop(ROD, rate="cowper-symonds", **DROP, history=False)
    assert not r.ok
    (said,) = [w for w in r.warnings if w.startswith("rate factor not converged: ")]
    assert "the result rests on an unconverged yield strength" in said
    assert said in r.to_dict()["warnings"]
