"""Quantities with units at the edge, and the Python API's input rule."""

from __future__ import annotations

import math
import re
from collections.abc import Callable

import numpy as np
import pint
import pytest

from impactlab._validation import (
    ImplausibleInputWarning,
    check_array,
    check_finite,
    check_flag,
    check_nonnegative,
    check_positive,
    check_range,
    check_seed,
    value_text,
    warn_implausible,
)
from impactlab.units import angle_to_rad, is_quantity, magnitude, to_si


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("8.8 mm", "m", 8.8e-3),
        ("1.41 m/s", "m/s", 1.41),
        ("-1410 mm/s", "m/s", -1.41),
        ("22 um", "m", 22e-6),
        ("200 GPa", "Pa", 200e9),
        ("0.25 ms", "s", 2.5e-4),
        (3.0, "mm", 3e-3),
        ("20", "degree", 0.3490658503988659),
        ("3", "mm", 3e-3),
    ],
)
def test_to_si(text: object, unit: str, expected: float) -> None:
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


def test_text_angles_carry_their_unit() -> None:
    """The angle rule: text gives its unit; a bare number could be degrees or radians."""
    assert angle_to_rad("20 deg") == pytest.approx(math.radians(20))
    assert angle_to_rad("0.5 rad") == pytest.approx(0.5)
    for bare in (20, 0.35, "20", " 0.35 "):
        with pytest.raises(ValueError, match="has no unit"):
            angle_to_rad(bare)


@pytest.mark.parametrize("bad", ["3 kg", "fast", "", "nan m"])
def test_bad_quantities_name_the_input(bad: str) -> None:
    with pytest.raises(ValueError, match="radius"):
        to_si(bad, "m", name="radius")


@pytest.mark.parametrize("text", ["nan", "inf", "-inf", " NaN ", "nan m/s"])
def test_text_that_is_not_finite_is_said_to_be_so(text: str) -> None:
    message = rf"^vy must be finite, got '{text}'$"
    with pytest.raises(ValueError, match=message):
        to_si(text, "m/s", name="vy")
    with pytest.raises(ValueError, match=message):
        magnitude("vy", text, "m/s")
    if "m/s" not in text:
        with pytest.raises(ValueError, match=rf"^angle must be finite, got '{text}'$"):
            angle_to_rad(text)


# -- the Python API's input rule (impactlab.units.magnitude + impactlab._validation) -------------


def test_magnitude_converts_strings_and_quantities_of_any_registry() -> None:
    other = pint.UnitRegistry()  # not impactlab's registry
    assert magnitude("v", -1.41 * other("m/s"), "m/s") == pytest.approx(-1.41)
    assert magnitude("angle", "20 deg", "rad") == pytest.approx(math.radians(20))
    assert magnitude("R", "8.8 mm", "m") == pytest.approx(8.8e-3)
    np.testing.assert_allclose(magnitude("x", [1.0, 2.0] * other.mm, "m"), [1e-3, 2e-3])
    assert magnitude("m", 0.46, "kg") == 0.46  # a number is already in the unit
    assert is_quantity(other("1 m")) and not is_quantity(1.0)


@pytest.mark.parametrize(
    ("value", "match"),
    [
        ("-1.41", r"vy: the string '-1.41' has no unit.*'-1.41 m/s'"),
        ("3 kg", "vy: '3 kg' has the wrong dimension"),
        ("fast", "vy: cannot parse 'fast'"),
        (5 * pint.UnitRegistry().kg, "vy: .* has the wrong dimension"),
    ],
)
def test_magnitude_refuses_what_is_not_a_quantity_of_the_unit(value: object, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        magnitude("vy", value, "m/s")


@pytest.mark.parametrize(
    ("name", "text", "unit", "match"),
    [
        ("angle", "20 deg 3", "rad", "holds more than one number"),  # pint: 60 deg
        ("vy", "1.41 m/s 2", "m/s", "holds more than one number"),  # pint: 2.82 m/s
        ("length", "1 000 m", "m", "holds more than one number"),
        ("rate", "6500 2/s", "1/s", "holds more than one number"),  # pint: 13000 1/s
        ("rate", "6500 1/2/s", "1/s", "holds more than one number"),  # pint: 3250 1/s
        ("radius", "5 1/2 mm", "m", "holds more than one number"),  # pint: 2.5 mm
        ("angle", "20 deg 1/2", "rad", "holds more than one number"),  # pint: 10 deg
        ("length", "6500 m/2", "m", "holds more than one number"),  # pint: 3250 m
        ("angle", "20 deg deg", "rad", "dimensionless units .* to the power 2"),  # pint: deg^2
        ("length", "5 deg m", "m", "dimensionless units .* to the power 1"),
        ("angle", "20 percent", "rad", r"is a pure number \(20 %\).*'1.0 deg'"),
        ("velocity", "(0, -5.076) km/h", "m/s", r"is one string; give each component"),
        ("radius", "2,5 mm", "m", "holds a comma.*'2.5 mm'"),  # pint: 25 mm
        ("angle", "2,0 deg", "rad", "holds a comma.*'2.0 deg'"),  # pint: 20 deg
        ("mass", "1,000.5 kg", "kg", "holds a comma"),  # pint: 1000.5 kg
    ],
)
def test_text_is_one_number_and_one_unit(name: str, text: str, unit: str, match: str) -> None:
    with pytest.raises(ValueError, match=f"{name}: .*{match}"):
        magnitude(name, text, unit)
    with pytest.raises(ValueError, match=name):
        to_si(text, unit, name=name)


def test_a_bare_angle_gets_a_hint_that_is_itself_accepted() -> None:
    with pytest.raises(ValueError, match=r"angle: the string '20' has no unit.*e.g. '20 deg'"):
        magnitude("angle", "20", "rad")
    assert magnitude("angle", "20 deg", "rad") == pytest.approx(math.radians(20))


def test_unit_expressions_that_stay_allowed() -> None:
    assert magnitude("angle", "pi/4 rad", "rad") == pytest.approx(math.pi / 4)
    assert magnitude("spin", "3 rpm", "rad/s") == pytest.approx(0.1 * math.pi)
    assert magnitude("spin", "20 deg/s", "rad/s") == pytest.approx(math.radians(20))
    assert magnitude("g", "9.81 m/s^2", "m/s^2") == 9.81
    assert magnitude("x", "-1.5e-3 m", "m") == -1.5e-3


@pytest.mark.parametrize(
    ("value", "match"),
    [
        ("0.2", r"mu must be a real number, got the string '0.2': write mu=0.2"),
        ("abc", "mu must be a real number, got the string 'abc'"),
        (True, "mu must be a real number, got the bool True"),
        (np.bool_(False), "mu must be a real number, got the bool"),
        (None, "mu must be a real number, got None"),
        ([0.2], "mu must be a real number"),
        (math.nan, "mu must be finite"),
    ],
)
def test_dimensionless_numbers_refuse_strings_and_bools(value: object, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        check_finite("mu", value)


def test_the_number_rule_accepts_real_numbers() -> None:
    assert check_finite("mu", 1) == 1.0
    assert check_finite("mu", np.float32(0.5)) == 0.5
    assert check_finite("mu", np.array(0.25)) == 0.25
    assert check_finite("mu", 0.2 * pint.UnitRegistry().dimensionless) == pytest.approx(0.2)
    assert check_positive("length", "30.48 cm", "m") == pytest.approx(0.3048)
    assert check_positive("length", 0.3048, "m") == 0.3048


@pytest.mark.parametrize(
    ("check", "value", "unit", "message"),
    [
        (check_positive, -69e9, "Pa", "E must be > 0 Pa, got -6.9e+10 Pa"),
        (check_positive, "-8.8 mm", "m", "E must be > 0 m, got -0.0088 m"),
        (check_positive, 0, "", "E must be > 0, got 0.0"),
        (check_nonnegative, -2.5e-7, "s", "E must be >= 0 s, got -2.5e-07 s"),
        (check_nonnegative, -1234567.0, "1", "E must be >= 0, got -1.234567e+06"),
    ],
)
def test_a_value_out_of_range_is_given_with_its_unit(
    check: Callable[..., float], value: object, unit: str, message: str
) -> None:
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        check("E", value, unit)


def test_value_text_reads_back_as_the_value() -> None:
    for x in (-69e9, 2700.0, 0.3, 1e-7, 123456789.123, -0.0):
        text = value_text(x)
        assert float(text) == x and ("e" in text) == (x != 0 and not 1e-4 <= abs(x) < 1e6)
    # beyond 11 significant digits (the round-off of a conversion): 12 digits, within 1e-12
    for x in (1 / 3 * 1e-9, -50e-6 * (1 - 2**-52), 0.1 + 0.2):
        text = value_text(x)
        assert abs(float(text) / x - 1.0) < 1e-12 and len(text.lstrip("-")) <= 18
    assert value_text(-4.9999999999999996e-05, "m") == "-5e-05 m"
    assert value_text(2.76e8, "Pa") == "2.76e+08 Pa" and value_text(0.5, "1") == "0.5"
    with pytest.raises(ValueError, match=r"must lie in \[0.0, 1.0\] rad, got 2.0 rad$"):
        check_range("angle", 2.0, 0.0, 1.0, unit="rad")


def test_arrays_flags_and_seeds() -> None:
    with pytest.raises(ValueError, match="vy must hold real numbers, got an array of strings"):
        check_array("vy", [-1.0, "2"])
    with pytest.raises(ValueError, match="vy must be a real number, got None"):
        check_array("vy", None)
    np.testing.assert_array_equal(check_array("vy", [-1, np.nan]), [-1.0, np.nan])
    np.testing.assert_allclose(check_array("vy", "-1410 mm/s", "m/s"), -1.41)
    assert check_flag("history", np.True_) is True
    with pytest.raises(ValueError, match="history must be True or False, got 'no'"):
        check_flag("history", "no")
    assert check_seed("seed", None) is None and check_seed("seed", np.int64(3)) == 3
    for bad in ("abc", True, -1, 1.5):
        with pytest.raises(ValueError, match="seed must be None or an integer >= 0"):
            check_seed("seed", bad)


def test_implausible_warnings_point_at_the_callers_line() -> None:
    with pytest.warns(ImplausibleInputWarning, match="too big") as rec:
        warn_implausible("too big")
    assert rec[0].filename == __file__


def test_a_material_input_is_shown_in_its_propertys_unit() -> None:
    """body_E and flat_E in GPa as E (a fitted modulus read 180496 MPa)."""
    from impactlab._display import display_unit

    assert display_unit("body_E", "Pa").unit == display_unit("E", "Pa").unit == "GPa"
    assert display_unit("flat_yield_strength", "Pa").unit == "MPa"


def test_a_decimal_comma_in_a_study_file_is_refused(tmp_path) -> None:
    from impactlab.sweep import load_study

    f = tmp_path / "s.toml"
    f.write_text('[fixed]\nvy = "-1,41 m/s"\nmu = 0.2\n[grid]\nangle = ["20 deg", "45 deg"]\n')
    with pytest.raises(ValueError, match=r"vy: '-1,41 m/s' holds a comma.*'-1.41 m/s'"):
        load_study(f)


@pytest.mark.parametrize("text", ["0.3 sr", "0.3 count"])
def test_a_dimensionless_unit_that_is_no_angle_is_refused(text: str) -> None:
    """pint converts any dimensionless unit to another: a solid angle or a count read as
    radians before."""
    with pytest.raises(ValueError, match=rf"angle: '{text}' is not"):
        magnitude("angle", text, "rad")
    with pytest.raises(ValueError, match="is not an angle"):
        angle_to_rad(text)
    assert magnitude("spin", "3 rpm", "rad/s") == pytest.approx(0.3141592653589793)


def test_unknown_law_and_friction_names_suggest_the_nearest() -> None:
    """A law's names take '-', a friction model's '_': the swapped spelling or a typo gets a
    suggestion (in the Python API, the command line and study files)."""
    from impactlab.contact import get_law
    from impactlab.friction import get_friction

    with pytest.raises(ValueError, match=r"'partial-slip' \(did you mean 'partial_slip'\?\)"):
        get_friction("partial-slip")
    with pytest.raises(ValueError, match=r"'columb' \(did you mean 'coulomb'\?\)"):
        get_friction("columb")
    with pytest.raises(ValueError, match=r"'jackson_green' \(did you mean 'jackson-green'\?\)"):
        get_law("jackson_green")
    with pytest.raises(ValueError, match=r"unknown contact law 'zzz'; known laws"):
        get_law("zzz")


def test_an_unknown_material_suggests_the_nearest_name() -> None:
    from impactlab.materials import get_material

    with pytest.raises(
        ValueError, match=r"unknown material 'aisi-101' \(did you mean 'aisi-1010'\?\)"
    ):
        get_material("aisi-101")


def test_laws_names_its_options_and_refuses_example_options_without_a_law(cli_main) -> None:
    code, _, err = cli_main("laws", "--radius", "5 mm")
    assert code == 2 and "--radius without a law" in err
    code, _, err = cli_main("laws", "ghaednia", "--body", "aisi-20")
    assert code == 2 and "--body: unknown material 'aisi-20' (did you mean 'aisi-201'?)" in err


@pytest.mark.parametrize("text", ["6500 1/s", "6500 /s", "6500 (1/s)", "6.5 1/ms", "6.5e3 1 / s"])
def test_a_reciprocal_unit_is_one_unit(text: str) -> None:
    """The 1 of ``1/s`` is a unit's, not a second number: the hint of the refusal above
    (e.g. '1.0 1/s') is itself accepted."""
    assert magnitude("rate", text, "1/s") == pytest.approx(6500.0)


def test_a_pure_number_is_asked_for_as_one() -> None:
    """The hint of a refused pure number is itself accepted (it said '1.0 1', refused as two
    numbers), and a pure number written in the unit 1 (a CSV header's ``[1]``) is read."""
    with pytest.raises(ValueError, match=r"e: '43 %' .*write one plain number, e.g. '0.4'"):
        magnitude("e", "43 %", "1")
    with pytest.raises(ValueError, match=r"holds more than one number.*e.g. '0.4'"):
        magnitude("e", "0.4 2", "1")
    assert magnitude("e", "0.4", "1") == pytest.approx(0.4)
    assert magnitude("e_sigma", "0.02 1", "1") == pytest.approx(0.02)
    assert to_si("0.02 1", "1", name="e_sigma") == pytest.approx(0.02)
    with pytest.raises(ValueError, match="holds more than one number"):
        magnitude("length", "5 1", "m")
