"""A distribution built in Python takes numbers in its input's SI unit: text or a Quantity is
refused with where text with units is read (it was "low must be a real number")."""

from __future__ import annotations

import pytest

from impactlab import sweep as sw
from impactlab.units import registry


@pytest.mark.parametrize(
    ("build", "said"),
    [
        (lambda: sw.Uniform("10 deg", "30 deg"), "uniform distribution: low = '10 deg' is text"),
        (lambda: sw.Normal("20 deg", 0.1), "normal distribution: mean = '20 deg' is text"),
        (lambda: sw.LogNormal(1.0, 0.1, high="2 m"), "lognormal distribution: high = '2 m' is"),
        (
            lambda: sw.Uniform(registry().Quantity(1.0, "m"), 2.0),
            "uniform distribution: low = <Quantity(1.0, 'meter')> is a Quantity",
        ),
    ],
)
def test_text_in_a_python_distribution_is_refused_with_the_way(build, said) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match="in its input's SI unit") as caught:
        build()
    assert str(caught.value).startswith(said)
    assert "[sample] table and by Study.from_dict" in str(caught.value)


def test_numbers_are_taken_as_before() -> None:
    assert sw.Uniform(0.1, 0.3).to_dict() == {"dist": "uniform", "low": 0.1, "high": 0.3}
