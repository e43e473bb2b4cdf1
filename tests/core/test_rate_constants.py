"""A rate law's constants: the printed form reads back to the same law bit for bit, the Python
API takes each constant with its unit under the package's unit rules and names the constant in
its errors, and the command line's errors quote the text as typed."""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.cli._common import UserError, rate_name
from impactlab.contact.rate import RateLaw, constants_text, shortest

POSITIVE = st.floats(min_value=5e-324, max_value=1.7976931348623157e308, allow_nan=False)
AWKWARD = [40.43217, 5.1234567, 0.1 + 0.2, 1 / 3, 1e-20, 6.02214076e23, 5e-324, 2.0**-1074 * 3]


def _read_back(law: RateLaw) -> None:
    again = rate_name(law.label)
    assert isinstance(again, RateLaw)
    assert again.parameters == law.parameters and again.label == law.label


@pytest.mark.parametrize("x", AWKWARD)
def test_awkward_constants_print_and_read_back_exactly(x) -> None:
    _read_back(RateLaw.custom("cowper-symonds", D=x, q=x))
    _read_back(RateLaw.custom("johnson-cook", C=x, rate0=x))


@settings(max_examples=150, deadline=None)
@given(D=POSITIVE, q=POSITIVE, C=st.floats(min_value=0.0, max_value=1e300), rate0=POSITIVE)
def test_any_constants_print_and_read_back_exactly(D, q, C, rate0) -> None:
    _read_back(RateLaw.custom("cowper-symonds", D=D, q=q))
    _read_back(RateLaw.custom("johnson-cook", C=C, rate0=rate0))


def test_the_printed_form_and_description_carry_every_digit_and_the_units() -> None:
    law = rate_name("cowper-symonds(D=40.43217 1/s, q=5.1234567)")
    assert isinstance(law, RateLaw)
    assert law.label == "cowper-symonds (D = 40.43217 1/s, q = 5.1234567)"
    assert law.description == "cowper-symonds, user constants D = 40.43217 1/s, q = 5.1234567"
    assert shortest(6500.0) == "6500" and shortest(0.03) == "0.03" and shortest(1e-20) == "1e-20"
    assert constants_text("johnson-cook", {"C": 0.03, "rate0": 1.0}) == "C = 0.03, rate0 = 1 1/s"


@pytest.mark.parametrize(
    "kwargs",
    [
        {"D": "6500 1/s", "q": 4},
        {"D": "6.5 kHz", "q": "4"},
        {"D": "6500 s^-1", "q": 4.0},
        {"D": 6500, "q": "4.0"},
    ],
)
def test_the_api_takes_constants_with_their_units(kwargs) -> None:
    assert RateLaw.custom("cowper-symonds", **kwargs) == RateLaw.custom(
        "cowper-symonds", D=6500.0, q=4.0
    )


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"D": "6500", "q": 4}, "D: the string '6500' has no unit; pass a number in 1/s"),
        ({"D": "6500 m", "q": 4}, "D: '6500 m' has the wrong dimension"),
        ({"D": None, "q": 4}, "D must be a number in 1/s or text with its unit, e.g. '6500 1/s'"),
        ({"D": 6500, "q": "4 %"}, "q must be a plain number, e.g. 4, got '4 %'"),
        ({"D": 6500, "q": True}, "q must be a plain number, e.g. 4, got True"),
    ],
)
def test_api_errors_name_the_constant(kwargs, message) -> None:
    with pytest.raises(ValueError, match="^" + re.escape(message)):
        RateLaw.custom("cowper-symonds", **kwargs)


@pytest.mark.parametrize(
    ("rate", "message"),
    [
        ("cowper-symonds(D=6500 1/s, q=4 1)", "--rate q must be a plain number, e.g. 4, got '4 1'"),
        ("cowper-symonds(D=6500 1/s, q=4 %)", "--rate q must be a plain number, e.g. 4, got '4 %'"),
        ("johnson-cook(C=3 %, rate0=1 1/s)", "--rate C must be a plain number, e.g. 0.03"),
        ("cowper-symonds(D=6500 1/s 2, q=4)", "--rate D: '6500 1/s 2' holds more than one"),
        ("johnson-cook(C=0.03, rate0=1 1/S)", "--rate rate0: '1 1/S' has the wrong dimension"),
        (
            "cowper-symonds(D=6500 1/s, q=4))",
            "--rate 'cowper-symonds(D=6500 1/s, q=4))': unbalanced brackets; write the "
            'constants in one pair, e.g. "cowper-symonds(D=6500 1/s, q=4)"',
        ),
        (
            "johnson-cook((C=0.03, rate0=1 1/s)",
            'unbalanced brackets; write the constants in one pair, e.g. "johnson-cook(C=0.03, '
            'rate0=1 1/s)"',
        ),
        ("cowper-symonds(D==6500 1/s, q=4)", "takes D [1/s], q [1], got 'D==6500 1/s'"),
        ("cowper-symonds(D=6500 1/s q=4)", "takes D [1/s], q [1], got 'D=6500 1/s q=4'"),
    ],
)
def test_command_line_errors_quote_what_was_typed(rate, message) -> None:
    with pytest.raises(UserError) as info:
        rate_name(rate)
    text = str(info.value)
    assert message in text and "\n" not in text and "'1.0 1'" not in text, text
    assert "EOF" not in text, text


@pytest.mark.parametrize("typed", ["D=6500 1/s", "D=6500 /s", "D=6.5 1/ms", "d=6500"])
def test_a_reciprocal_unit_is_read_as_typed(typed) -> None:
    law = rate_name(f"cowper-symonds({typed}, q=4)")
    assert law == RateLaw.custom("cowper-symonds", D=6500.0, q=4.0)
