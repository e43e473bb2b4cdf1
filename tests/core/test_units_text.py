"""Quantity text as people type it: minus signs other than '-' (pint drops them without a word,
so "\u22120.3 m/s" would be +0.3 m/s), and arithmetic between numbers (pint computes it, so
"2*-1.41 m/s" would be -2.82 m/s) next to the units and exponents that stay allowed."""

from __future__ import annotations

import math
import re
import unicodedata

import pytest

from impactlab.units import (
    angle_to_rad,
    bare_number,
    bare_text,
    magnitude,
    parse_quantity,
    read_minus,
    to_si,
)

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


#: Every Unicode dash (Pd) but '-', and the other minus signs: the modifier-letter, commercial
#: and heavy minus signs and the soft hyphen. pint drops each without a word.
EVERY_DASH = tuple(
    c
    for c in map(chr, range(0x110000))
    if c != "-" and (unicodedata.category(c) == "Pd" or c in "\u2212\u02d7\u2052\u2796\u00ad")
)


def test_every_dash_before_a_number_is_its_minus_sign():
    assert {"\u2010", "\u2011", "\u2015", "\u2052", "\u02d7", "\u00ad", "\u2796"} <= set(EVERY_DASH)
    for dash in EVERY_DASH:
        assert to_si(f"{dash}0.5 m/s", "m/s", name="--vx") == -0.5, repr(dash)
        assert to_si(f"1.41e{dash}3 m/s", "m/s") == pytest.approx(1.41e-3, rel=1e-12)
        assert to_si(f"{dash}3", "m/s") == -3.0  # a bare number: in the stated unit
        with pytest.raises(ValueError, match=r"holds a dash \(U\+"):
            to_si(f"0.5 {dash} m/s", "m/s")
    assert angle_to_rad("\u201020 deg", name="--angle") == pytest.approx(-math.radians(20))


def test_no_character_is_dropped_without_a_word():
    """Every code point of the basic plane that is no letter or digit, written before a number,
    is read as a minus sign (a dash), as what it is (a space, '+'), or refused."""
    read_as_is = {"+", "\u00b7", "\u00d7", "\u22c5", "\u2219"} | {
        c for c in map(chr, range(0x10000)) if c.isspace()
    }
    for c in map(chr, range(0x20, 0x10000)):
        if c.isalnum() or 0xD800 <= ord(c) <= 0xDFFF:
            continue
        try:
            x = to_si(f"{c}0.3 m", "m")
        except ValueError:
            continue
        minus = c in EVERY_DASH or c in "-\u207b"  # the superscript minus: pint reads it
        assert (minus or c in read_as_is) and x == (-0.3 if minus else 0.3), repr(c)


@pytest.mark.parametrize(
    "text",
    [
        "0.3 m\u200b/s",  # zero-width space
        "0.3 m/s # measured",  # Python's comment: the unit would be lost
        "~0.3 m/s",
        "!0.3 m/s",
        "'0.3' m/s",
        "[0.3] m/s",
        "0.3 m\u2044s",  # fraction slash: m*s
        "0.3\u0e33 m/s",  # a Thai vowel that pint drops
        "0.3 m/s\ufe70",
        "\u221e m/s",
    ],
)
def test_a_character_pint_would_drop_is_refused_naming_it(text):
    head = re.escape(f"--vx: {text.strip()!r} holds ")
    with pytest.raises(ValueError, match=f"^{head}.*\\(U\\+[0-9A-F]{{4}}.*cannot hold") as exc:
        to_si(text, "m/s", name="--vx")
    assert "'1.0 m/s'" in str(exc.value)


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("10 \u00b5m", "m", 1e-5),  # micro sign
        ("10 \u03bcm", "m", 1e-5),  # Greek mu
        ("2 \u00c5", "m", 2e-10),
        ("20\u00b0", "deg", math.radians(20)),
        ("20 \u00b0", "deg", math.radians(20)),
        ("2700 kg/m\u00b3", "kg/m^3", 2700.0),
        ("2700 kg\u00b7m\u207b\u00b3", "kg/m^3", 2700.0),
        ("1.41 m\u22c5s\u207b\u00b9", "m/s", 1.41),
        ("1e-4 kg\u00d7m\u00b2", "kg*m^2", 1e-4),
        ("1.41\u00a0m/s", "m/s", 1.41),  # no-break space
        ("1.41\u2009m/s", "m/s", 1.41),  # thin space
        ("1.41\u202fm/s", "m/s", 1.41),  # narrow no-break space
        ("1.41\tm/s", "m/s", 1.41),
        ("0.5 pi rad", "rad", 0.5 * math.pi),
    ],
)
def test_the_characters_quantity_text_holds_stay_read(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "unit", "pint_reads"),
    [
        ("(2)^2 m", "m", "4 m"),
        ("(2)**2 m", "m", "4 m"),
        ("(20)^2 deg", "deg", "400 deg"),
        ("(1e-3)**-1 1/s", "1/s", "1000.0 / s"),
        ("-(1.41)**2 m/s", "m/s", "-1.98"),
        ("10\u207b\u00b3 m", "m", "0.001 m"),
        ("((2))^2 m", "m", "4 m"),
    ],
)
def test_a_power_of_a_number_is_refused(text, unit, pint_reads):
    head = re.escape(f"--vy: {text!r} holds more than one number (pint would compute with them")
    with pytest.raises(ValueError, match=f"^{head}") as exc:
        to_si(text, unit, name="--vy")
    assert pint_reads in str(exc.value)


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("(1e-3) m", "m", 1e-3),
        ("-(1.41) m/s", "m/s", -1.41),
        ("(1/s)", "1/s", 1.0),
        ("2 (1/s)", "1/s", 2.0),
        ("1 kg*m**2", "kg*m^2", 1.0),
        ("9.81 m/s**2", "m/s^2", 9.81),
        ("1 m^+2", "m^2", 1.0),
        ("1e9 N/m^1.5", "N/m^1.5", 1e9),
        ("5 s\u207b\u00b9", "1/s", 5.0),
    ],
)
def test_brackets_and_powers_of_units_stay_allowed(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


def test_bare_numbers_read_their_minus_sign():
    assert bare_number("\u22124") == -4.0 and bare_number(" \u2010 2.5e\u22123 ".strip()) is None
    assert bare_number("\u22122.5e\u20133") == pytest.approx(-2.5e-3, rel=1e-15)
    assert bare_number(3) == 3.0 and bare_number("inf") == math.inf
    assert bare_number(True) is None and bare_number("4 m/s") is None and bare_number(None) is None
    assert bare_text("\u22124") == "-4" and bare_text("\u22124 m/s") == "\u22124 m/s"
    assert bare_text(-4.0) == -4.0
    assert read_minus("\u22121.41e\u22123 m/s \u2013 x") == "-1.41e-3 m/s \u2013 x"


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("1_000 m", "m", 1000.0),
        ("1_000.000_5 mm", "m", 1.0000005),
        ("2.5e1_0 Pa", "Pa", 2.5e10),
        ("\u22121_000 mm", "m", -1.0),
        ("(1_000) m", "m", 1000.0),
        ("6_500 1/s", "1/s", 6500.0),
    ],
)
def test_digit_groups_are_one_number(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)
    assert magnitude("x", text, unit) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "unit"),
    [
        ("m^2", "m**2"),
        ("kg m^2", "kg*m**2"),
        ("kg*m**2", "kg*m**2"),
        ("m/s^2", "m/s**2"),
        ("s^-2", "1/s**2"),
        ("m^1.5", "m**1.5"),
        ("N/m^2", "Pa"),
    ],
)
def test_a_unit_alone_is_refused_not_read_as_one(text, unit):
    with pytest.raises(ValueError, match="holds a unit but no number"):
        to_si(text, unit)
    assert to_si(f"1 {text}", unit) == 1.0


def test_a_one_over_a_unit_is_its_number():
    assert to_si("1/s^2", "1/s**2") == 1.0


def test_the_exponent_of_a_unit_is_never_the_number():
    assert to_si("3 kg m^2", "kg*m**2") == 3.0
    assert to_si("m^2 3", "m**2") == 3.0  # pint reads 3 m^2: the number written
    for text in ("1_000 m 2", "(2)^2 m^2", "2^2 m^2"):
        with pytest.raises(ValueError, match=re.escape(f"x: {text!r} holds more than one number")):
            to_si(text, "m" if text.endswith(" 2") else "m**2", name="x")


@pytest.mark.parametrize(
    ("text", "unit"),
    [(" deg", "rad"), ("deg", "rad"), ("-m/s", "m/s"), ("mm", "m"), ("GPa", "Pa"), ("kg", "kg")],
)
def test_a_unit_without_its_number_is_refused(text, unit):
    """pint reads a unit alone as 1 of it: an empty shell variable ("$A deg") would run at 1."""
    with pytest.raises(ValueError, match="holds a unit but no number"):
        to_si(text, unit)


@pytest.mark.parametrize(
    ("text", "expected"), [("pi rad", math.pi), ("pi/4 rad", math.pi / 4), ("\u03c0 rad", math.pi)]
)
def test_pi_stands_for_a_number(text, expected):
    assert to_si(text, "rad") == pytest.approx(expected, rel=1e-12)
