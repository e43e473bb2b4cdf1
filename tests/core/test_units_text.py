"""Quantity text as people type it: minus signs other than '-' (pint drops them without a word,
so "\u22120.3 m/s" would be +0.3 m/s), and arithmetic between numbers (pint computes it, so
"2*-1.41 m/s" would be -2.82 m/s) next to the units and exponents that stay allowed."""

from __future__ import annotations

import math
import re

import pytest

from impactlab.units import angle_to_rad, magnitude, parse_quantity, to_si

#: U+2212 minus sign, U+2012 figure dash, U+2013 en dash, U+2014 em dash, U+FE63 small
#: hyphen-minus, U+FF0D full-width hyphen-minus.
DASHES = ("\u2212", "\u2012", "\u2013", "\u2014", "\ufe63", "\uff0d")


@pytest.mark.parametrize("dash", DASHES)
def test_a_dash_before_a_number_is_its_minus_sign(dash):
    assert to_si(f"{dash}0.3 m/s", "m/s", name="vx") == -0.3
    assert to_si(f"{dash}5 rad/s", "rad/s", name="spin") == -5.0
    assert to_si(f"{dash}.5 mm", "m") == pytest.approx(-5e-4, rel=1e-12)
    assert to_si(f" {dash}3", "m/s") == -3.0  # a bare number: in the stated unit
    assert magnitude("vy", f"{dash}1.41 m/s", "m/s") == -1.41
    assert angle_to_rad(f"{dash}20 deg") == pytest.approx(-math.radians(20), rel=1e-12)


@pytest.mark.parametrize("dash", DASHES)
def test_a_dash_in_an_exponent_is_its_minus_sign(dash):
    assert to_si(f"1.41e{dash}3 m/s", "m/s") == pytest.approx(1.41e-3, rel=1e-12)
    assert to_si(f"{dash}1.41E{dash}3 m/s", "m/s") == pytest.approx(-1.41e-3, rel=1e-12)
    assert to_si(f"5 s^{dash}1", "1/s") == 5.0
    assert to_si(f"2 m*s^{dash}2", "m/s^2") == 2.0


@pytest.mark.parametrize(
    "text",
    ["0.3 \u2013 m/s", "\u2212 0.3 m/s", "0.3 m\u2014s", "\u2212", "0.3 m/s \u2212"],
)
def test_a_dash_elsewhere_is_refused_with_the_name_and_the_text(text):
    head = re.escape(f"--vx: {text.strip()!r} holds a dash (U+")
    with pytest.raises(ValueError, match=f"^{head}") as exc:
        to_si(text, "m/s", name="--vx")
    message = str(exc.value)
    assert "not a minus sign right before a number" in message and "'-1.0 m/s'" in message


def test_a_range_with_a_dash_is_two_numbers():
    with pytest.raises(ValueError, match=r"--vx: '0.3\u20130.5 m/s' holds more than one number"):
        to_si("0.3\u20130.5 m/s", "m/s", name="--vx")


def test_messages_show_the_text_as_given():
    with pytest.raises(ValueError, match=r"'\u22121\.41 m/s 2' holds more than one number"):
        to_si("\u22121.41 m/s 2", "m/s")
    with pytest.raises(ValueError, match=r"'\u22121\.41 kg' has the wrong dimension"):
        to_si("\u22121.41 kg", "m/s")


@pytest.mark.parametrize(
    ("text", "unit"),
    [
        ("2*-1.41 m/s", "m/s"),  # pint: -2.82 m/s
        ("2 * 1.41 m/s", "m/s"),
        ("1.41/2 m/s", "m/s"),  # pint: 0.705 m/s
        ("2**2 m", "m"),  # pint: 4 m
        ("2 ** 2 m", "m"),
        ("2^2 m", "m"),
        ("2+1 m/s", "m/s"),
        ("2-1 m/s", "m/s"),
        ("2 m*3", "m"),  # pint: 6 m
        ("2 m**2*3", "m^2"),
        ("(2*3) m", "m"),  # pint: 6 m
        ("(1.41/2) m/s", "m/s"),
        ("2*3", "1"),
        ("-2*3 kg*m^2", "kg*m^2"),
    ],
)
def test_arithmetic_between_numbers_is_refused(text, unit):
    head = re.escape(f"--vy: {text!r} holds more than one number")
    with pytest.raises(ValueError, match=f"^{head}"):
        to_si(text, unit, name="--vy")


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("3 N*m", "N*m", 3.0),
        ("1 kg*m^2", "kg*m^2", 1.0),
        ("1 kg*m**2", "kg*m^2", 1.0),
        ("3.6e-3 kg*m^2", "kg*m^2", 3.6e-3),
        ("9.81 m/s**2", "m/s^2", 9.81),
        ("9.81 m/s^2", "m/s^2", 9.81),
        ("5 s**-1", "1/s", 5.0),
        ("5 s^-1", "1/s", 5.0),
        ("5 1/s**2", "1/s^2", 5.0),
        ("6500 1/s", "1/s", 6500.0),
        ("6500 (1/s)", "1/s", 6500.0),
        ("1e-3 m", "m", 1e-3),
        ("1E+3 mm", "m", 1.0),
        ("-1.41e-0 m/s", "m/s", -1.41),
        ("(1e-3) m", "m", 1e-3),
        ("2 m^2", "m^2", 2.0),
        ("0.02 1", "1", 0.02),
        ("2.5e-3", "1", 2.5e-3),
    ],
)
def test_units_and_exponents_stay_allowed(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


def test_parse_quantity_reads_the_minus_sign_too():
    """The rule of every text input (the sweep's study files parse with it)."""
    q = parse_quantity("vy", "\u22121.41 m/s", "m/s")
    assert q.magnitude == -1.41 and str(q.units) == "meter / second"
