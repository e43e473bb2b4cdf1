"""A sampled input is checked by the values its distribution can draw (its quantiles at the
extreme uniforms of the draws), against what the input allows, when the study is built: a
distribution that can leave the range is refused, naming the bound to add, as a grid's values
outside it are."""

from __future__ import annotations

import math

import pytest

from impactlab.sweep import Study
from impactlab.sweep.dimensions import Sample
from impactlab.sweep.distributions import LogNormal, Normal, Uniform, uniforms
from impactlab.sweep.study_rules import UNIFORM_EXTREMES

_FIXED = {"vy": -1.41, "angle": 0.35, "mu": 0.2}


def _study(**inputs) -> Study:
    fixed = {k: v for k, v in _FIXED.items() if k not in inputs}
    return Study(name="mc", sample=Sample(size=10, seed=1, inputs=inputs), fixed=fixed)


@pytest.mark.parametrize(
    ("inputs", "message"),
    [
        (
            {"mu": Normal(0.05, 0.1)},
            r"sample input 'mu': mu must lie in \[0, 1000\], but its normal distribution draws "
            r"values down to -0\.7\d*; truncate it: low = 0$",
        ),
        (
            {"vy": Normal(-1.41, 0.3)},
            r"sample input 'vy': the contact point must approach the flat \(vy < 0 m/s with "
            r"spin = 0\), but .* up to 1\.05\d* m/s; truncate it: high below 0 m/s$",
        ),
        (
            {"angle": Uniform(0.1, 1.6)},
            r"angle must lie in \(0, 90\] deg, but its uniform distribution draws values up "
            r"to 91\.6\d* deg; keep high at most 90 deg$",
        ),
        ({"flat_E": LogNormal(200e9, 0.1), "flat_nu": Normal(0.3, 0.1)}, "flat_nu must lie in"),
        ({"n_axial": Uniform(2, 6)}, r"n_axial must be an integer >= 0, .*put it on the \[grid\]"),
    ],
)
def test_a_distribution_that_leaves_the_range_is_refused(inputs, message) -> None:
    fixed_flex = {"body": "flexible_rod"} if "n_axial" in inputs else {}
    flat = {"flat_yield_strength": 300e6} if "flat_E" in inputs else {}
    fixed = {k: v for k, v in _FIXED.items() if k not in inputs} | fixed_flex | flat
    with pytest.raises(ValueError, match=message) as caught:
        Study(name="mc", sample=Sample(size=10, seed=1, inputs=inputs), fixed=fixed)
    assert "\n" not in str(caught.value)


def test_the_named_bound_makes_it_valid() -> None:
    study = _study(mu=Normal(0.05, 0.1, low=0.0))
    assert study.sample is not None
    assert (study.sample.draw("mu", 0, 10_000) >= 0).all()
    _study(vy=Normal(-1.41, 0.3, high=-0.1), angle=Uniform(0.1, 0.5 * math.pi))


def test_a_spin_lifts_the_approach_rule() -> None:
    fixed = {"angle": 0.35, "mu": 0.2, "spin": -40.0}
    Study(name="s", sample=Sample(10, 1, {"vy": Normal(-1.41, 0.3)}), fixed=fixed)


def test_the_checked_extremes_bound_every_draw() -> None:
    """The quantiles checked bound what the draws give (the uniforms of a stream lie within
    the extremes)."""
    u = uniforms(7, "mu", 0, 200_000)
    assert u.min() >= UNIFORM_EXTREMES[0] and u[u < 1.0].max() <= UNIFORM_EXTREMES[1]
    low, high = Normal(0.2, 0.03).ppf(UNIFORM_EXTREMES)
    assert -0.05 < low < 0.0 < 0.4 < high < 0.5  # about 8.3 standard deviations


def test_a_study_file_names_the_bound_too(tmp_path) -> None:
    f = tmp_path / "mc.toml"
    f.write_text(
        "[fixed]\nvy = -1.41\nangle = '20 deg'\n[sample]\nsize = 10\nseed = 1\n"
        "mu = { dist = 'normal', mean = 0.05, std = 0.1 }\n"
    )
    with pytest.raises(ValueError, match="truncate it: low = 0"):
        Study.from_toml(f)
    f.write_text(f.read_text().replace("std = 0.1 }", "std = 0.1, low = 0 }"))
    study = Study.from_toml(f)
    assert study.sample is not None and (study.sample.draw("mu", 0, 10) >= 0).all()


@pytest.mark.parametrize(
    ("inputs", "message"),
    [
        (  # the upper limit broken: named, with the truncation that keeps below it
            {"mu": Normal(500.0, 100.0)},
            r"mu must lie in \[0, 1000\], but its normal distribution draws values down to "
            r"-329\.\d*; truncate it: low = 0$",
        ),
        (
            {"mu": Normal(900.0, 20.0)},
            r"draws values up to 1064\.\d*; truncate it: high = 1000$",
        ),
        (  # every draw past the upper limit: no truncation can help
            {"mu": Normal(2000.0, 1.0)},
            r"draws values from 1991\.7 to 2008\.\d*; move it inside: every value it draws lies "
            r"above 1000$",
        ),
        (
            {"vy": Uniform(1.0, 5.0)},
            r"vy < 0 m/s with spin = 0\), but its uniform distribution draws values from 1 to "
            r"5 m/s; keep low and high below 0 m/s$",
        ),
        ({"vy": Uniform(-1.0, 5.0)}, r"draws values up to 5 m/s; keep high below 0 m/s$"),
        (
            {"angle": Uniform(-0.1, 1.0)},
            r"draws values down to -5\.7\d* deg; keep low above 0 deg$",
        ),
        (  # degrees given as radians: the hint a grid or fixed angle gets
            {"angle": Uniform(20.0, 30.0)},
            r"angle must lie in \(0, 90\] deg, but its uniform distribution draws values from "
            r"1145\.9 to 1718\.9 deg; keep low and high at most 90 deg; if 20\.0 is meant in "
            r"degrees, pass math\.radians\(20\.0\) = 0\.349066 rad or the string '20 deg'$",
        ),
        (
            {"angle": Normal(45.0, 1.0)},
            r"every value it draws lies above 90 deg; if 45\.0 is meant in degrees, pass "
            r"math\.radians\(45\.0\) = 0\.785398 rad or the string '45 deg'$",
        ),
    ],
)
def test_the_message_names_the_bound_the_draws_break(inputs, message) -> None:
    with pytest.raises(ValueError, match=message) as caught:
        _study(**inputs)
    assert "\n" not in str(caught.value)


def test_a_study_file_angle_in_degrees_gets_the_hint(tmp_path) -> None:
    """An angle distribution written with unit = "rad" but meant in degrees: the hint a grid
    value gets, the same as in Python."""
    f = tmp_path / "deg.toml"
    f.write_text(
        "[fixed]\nvy = -1.41\nmu = 0.3\n[sample]\nsize = 5\nseed = 1\n"
        "angle = { dist = 'uniform', low = 20, high = 30, unit = 'rad' }\n"
    )
    with pytest.raises(ValueError, match=r"keep low and high at most 90 deg; if 20\.0 is meant"):
        Study.from_toml(f)
