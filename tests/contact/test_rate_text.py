"""``rate=`` in Python takes the text forms the command line's ``--rate`` takes and a result
prints (``contact.rate.get_rate_law``, the one parser of both): ``result.rate`` given back as
``rate=`` runs the same law, bit for bit; ``"none"`` is no rate law; an unknown rate names
``rate``, the forms and ``RateLaw.custom``."""

from __future__ import annotations

import math

import pytest

from impactlab.bodies import FlexibleRod
from impactlab.cli._common import UserError, rate_name
from impactlab.contact.rate import JOHNSON_COOK_1006_STEEL, RateLaw, get_rate_law
from impactlab.dynamics.drop import simulate_drop
from impactlab.materials import get_material

ALU = get_material("al-6061-t6")
DROP = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2, "history": False}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("none", None),
        (" None ", None),
        ("Johnson-Cook", JOHNSON_COOK_1006_STEEL),
        ("cowper-symonds(D=6500 1/s, q=4)", {"D": 6500.0, "q": 4.0}),
        ("cowper-symonds (D = 6500 1/s, q = 4)", {"D": 6500.0, "q": 4.0}),
        ("johnson-cook(C=0.03, rate0=2e-3 /ms)", {"C": 0.03, "rate0": 2.0}),
    ],
)
def test_the_text_forms(text, expected) -> None:
    law = get_rate_law(text)
    if not isinstance(expected, dict):
        assert law is expected
        return
    assert isinstance(law, RateLaw) and law.fitted_for is None
    assert dict(law.parameters) == pytest.approx(expected, rel=1e-12)


def test_the_printed_rate_runs_the_same_drop_bit_for_bit() -> None:
    own = RateLaw.custom("cowper-symonds", D="6500 1/s", q=4)
    first = simulate_drop(FlexibleRod.paper(), ALU, rate=own, **DROP)
    assert first.rate == "cowper-symonds (D = 6500 1/s, q = 4)"
    for rate in (first.rate, "cowper-symonds(D=6500 1/s, q=4)"):
        again = simulate_drop(FlexibleRod.paper(), ALU, rate=rate, **DROP)
        assert again.rate == first.rate and again.rate_factor == first.rate_factor > 1.0
        assert again.e == first.e and again.dent_depth == first.dent_depth
        assert again.contacts == first.contacts
        assert again.input == first.input


def test_none_is_no_rate_law() -> None:
    plain = simulate_drop(FlexibleRod.paper(), **DROP)
    none = simulate_drop(FlexibleRod.paper(), rate="none", **DROP)
    assert none.rate is None and none.rate_factor == 1.0
    assert none.e == plain.e and none.contacts == plain.contacts
    assert none.input == plain.input


@pytest.mark.parametrize("rate", ["cowper", 5, "none(D=1)"])
def test_an_unknown_rate_names_the_forms_and_rate_law_custom(rate) -> None:
    with pytest.raises(ValueError, match=r"^rate must be one of none, cowper-symonds") as exc:
        simulate_drop(FlexibleRod.paper(), rate=rate, **DROP)
    text = str(exc.value)
    assert "RateLaw.custom" in text and f"got {rate!r}" in text and "\n" not in text


def test_the_command_line_keeps_its_option_in_the_errors() -> None:
    with pytest.raises(UserError, match=r"^--rate must be one of none") as exc:
        rate_name("cowper")
    assert "RateLaw" not in str(exc.value)
    with pytest.raises(UserError, match=r"^--rate D must be > 0 1/s"):
        rate_name("cowper-symonds(D=-1, q=4)")
    with pytest.raises(ValueError, match=r"^rate 'cowper-symonds\(D=1\)': cowper-symonds takes"):
        get_rate_law("cowper-symonds(D=1)")
    assert rate_name(" Cowper-Symonds ") == "cowper-symonds" and rate_name("NONE") is None
