"""A derived output's unit (``schema.register_output``) is parsed by the package's pint registry
when it is registered and must be SI, as every value of a result is; a derived output is in
``to_pint`` of an impact, a batch and a drop, in its unit."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

import impactlab as il
from impactlab import schema

NAME = "delta_p_again"


@pytest.fixture
def dent_depth() -> Iterator[str]:
    """delta_p again, as a derived output in m."""
    schema.register_output(NAME, "m", "the dent depth again", ("delta_p",), lambda delta_p: delta_p)
    yield NAME
    schema.unregister_output(NAME)


@pytest.mark.parametrize(
    ("unit", "said"),
    [
        ("furlongs", "'furlongs', which is 201.168 m (values are SI: give 'm'"),
        ("mm", "'mm', which is 0.001 m"),
        ("deg", "'deg', which is 0.0174533 rad"),
        ("percent", "'percent', which is 0.01 (values are SI: give '1'"),
        ("kgf/mm^2", "'kgf/mm^2', which is 9.80665e+06 kg / m / s ** 2 (values are SI: give 'Pa' "),
        ("lbf", "(values are SI: give 'N' and compute in it)"),
        ("kgf*cm", "(values are SI: give 'J' or 'N m' and compute in it)"),
        ("MPa*s", "(values are SI: give 'Pa s' and compute in it)"),
        (
            "degC",
            "'degC', a scale with an offset (0 degC is 273.15 K, not 0); values are SI: give 'K'",
        ),
        ("degF", "'degF', a scale with an offset (0 degF is 255.372 K, not 0)"),
        ("bananas", "'bananas' ('bananas' is not defined in the unit registry)"),
        ("m/", "'m/' (not a unit expression)"),
        ("", "got ''"),
        (3, "got 3"),
    ],
)
def test_a_unit_that_is_not_si_is_refused_in_one_line(unit: object, said: str) -> None:
    with pytest.raises(ValueError, match="must be an SI unit pint parses") as err:
        schema.register_output("zz_unit", unit, "d", ("e",), lambda e: e)  # type: ignore[arg-type]
    text = str(err.value)
    assert "\n" not in text and "unit of output 'zz_unit'" in text and said in text
    assert "zz_unit" not in schema.DERIVED_FIELDS and "zz_unit" not in schema.FIELDS


@pytest.mark.parametrize("unit", ["1", "m", "N s", "J/m", "rad/s", "1/m", "kg m^2", "Pa", "K"])
def test_si_units_are_accepted(unit: str) -> None:
    schema.register_output("zz_si", unit, "d", ("e",), lambda e: e)
    try:
        assert schema.unit("zz_si") == unit
    finally:
        schema.unregister_output("zz_si")


def test_to_pint_of_an_impact_a_batch_and_a_drop_has_the_derived_output(dent_depth: str) -> None:
    kw = {"law": "ghaednia", "angle": math.radians(40), "mu": 0.2}
    r = il.simulate(il.Rod.paper(), velocity=(0.0, -1.4), **kw)
    q = r.to_pint()[dent_depth]
    assert q.to("um").magnitude == pytest.approx(r.delta_p * 1e6, rel=1e-12)
    b = il.simulate_batch(il.Rod.paper(), vy=[-1.0, -1.4], **kw)
    qb = b.to_pint()[dent_depth]
    assert str(qb.units) == "meter"
    np.testing.assert_array_equal(qb.magnitude, b["delta_p"])
    assert b.to_pint()["max_delta_ratio"].magnitude.tolist() == b.max_delta_ratio.tolist()
    d = il.simulate_drop(il.Rod.paper(), velocity=(0.0, -1.4), **kw)
    qd = d.to_pint()[dent_depth]  # a drop has no delta_p of one unloading: NaN, in m
    assert str(qd.units) == "meter" and math.isnan(qd.magnitude)
