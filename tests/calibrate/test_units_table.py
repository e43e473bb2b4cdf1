"""Units that could be read wrong: a TOML file's [units] keys resolved as column names (the
paper's symbols too) and refused when they name nothing, a measured angle refused bare, a
fraction in percent, a semicolon file named before its rows are counted, and a prior whose
numbers mix a unit with a bare number."""

from __future__ import annotations

import math
import tomllib

import pytest

from impactlab.calibrate import Measurements, parse_parameter, read_measurements

DROP = '[[drop]]\nlabel = "a"\nangle = "20 deg"\nvy = -1.41\nmu = 0.2\n'


def _toml(tmp_path, units: str, values: str):
    path = tmp_path / "m.toml"
    path.write_text(f"[units]\n{units}\n{DROP}{values}\n")
    return path


@pytest.mark.parametrize(
    ("units", "values", "quantity", "value", "sigma"),
    [
        ('mean_force = "kN"', "F = 2.2\nF_sigma = 0.2", "mean_force", 2200.0, 200.0),
        ('F = "kN"', "mean_force = 2.2\nmean_force_sigma = 0.2", "mean_force", 2200.0, 200.0),
        ('duration = "ms"', "T = 0.12\nT_sigma = 0.01", "duration", 1.2e-4, 1e-5),
        ('T = "ms"\nT_sigma = "us"', "duration = 0.12\nduration_sigma = 10", "duration", 1.2e-4,
         1e-5),
        ('spin_out = "rpm"', "spin_out = -95\nspin_out_sigma = 5", "spin_out",
         -95 * 2 * math.pi / 60, 5 * 2 * math.pi / 60),
    ],
)  # fmt: skip
def test_a_units_key_is_read_as_a_column_name(tmp_path, units, values, quantity, value, sigma):
    """[units] mean_force = "kN" holds for a column written F (it was read as 2.2 N)."""
    m = read_measurements(_toml(tmp_path, units, values))
    assert m.observed[quantity][0] == pytest.approx(value)
    assert m.sigma[quantity][0] == pytest.approx(sigma)


@pytest.mark.parametrize(
    ("units", "match"),
    [
        ('spin_ot = "rpm"', r"\[units\]: unknown column 'spin_ot' \(did you mean 'spin_out'\?\)"),
        ('dleta_p = "um"', r"unknown column 'dleta_p' \(did you mean 'delta_p'\?\); a key of "
         r"\[units\] is a column of the drops"),
        ('label = "m"', r"\[units\] label = 'm': label is not a quantity \(the drop's name\), so "
         r"it takes no unit"),
        ('flat_material = "Pa"', r"flat_material is not a quantity"),
        ("e = 0.01", r"\[units\] e = 0.01: a unit is text"),
        ('T = "ms"\nduration = "s"', r"\[units\]: duration is given twice \(keys 'T' and "
         r"'duration'\)"),
        ('L_s = "um"', r"L_s names two quantities"),
    ],
)  # fmt: skip
def test_a_units_key_that_names_no_quantity_is_refused(tmp_path, units, match):
    """An unknown or misspelt key was accepted silently (the values then read in SI)."""
    path = _toml(tmp_path, units, "e = 0.4\ne_sigma = 0.02")
    with pytest.raises(ValueError, match=match) as info:
        read_measurements(path)
    assert str(info.value).startswith(str(path)) and "\n" not in str(info.value)
    with pytest.raises(ValueError, match=match):  # the same rule in Python
        Measurements.from_records(
            [{"angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.4, "e_sigma": 0.02}],
            tomllib.loads(units),
        )


def test_a_unit_in_the_header_of_a_label_is_refused():
    with pytest.raises(ValueError, match=r"column 'label \[m\]': label is not a quantity"):
        Measurements.from_records(
            [{"label [m]": "a", "angle": "20 deg", "vy": -1.41, "e": 0.4, "e_sigma": 0.02}]
        )


def _one(**kw):
    rec = {"label": "a", "angle": "20 deg", "vy": -1.41, "mu": 0.2, **kw}
    return Measurements.from_records([rec])


def test_a_measured_angle_needs_a_unit():
    """A bare angle_out of 20 was read as 20 rad (1146 deg), only a misfit warning."""
    with pytest.raises(ValueError, match=r"drop 1: angle_out: the bare number 20 has no unit; "
                       r"an angle needs one, e.g. '20 deg', or a unit in the column header "
                       r"\('angle_out \[deg\]'\)"):  # fmt: skip
        _one(angle_out=20, angle_out_sigma="1 deg")
    with pytest.raises(ValueError, match=r"angle_out_sigma = 1 has no unit while angle_out = "
                       r"'20 deg' has one: give the uncertainty's unit too \(e.g. "
                       r"'1 deg'\)"):  # fmt: skip
        _one(angle_out="20 deg", angle_out_sigma=1)
    with pytest.raises(ValueError, match=r"angle_out_sigma: the bare number 1 has no unit"):
        _one(angle_out="", angle_out_sigma=1, e=0.4, e_sigma=0.02)
    m = _one(**{"angle_out [deg]": 21, "angle_out_sigma": 1})  # the header's unit for both
    assert m.observed["angle_out"][0] == pytest.approx(math.radians(21))
    assert m.sigma["angle_out"][0] == pytest.approx(math.radians(1))


def test_a_measured_angle_lies_in_0_to_180_deg():
    """Its errors speak in degrees, as the file writes an angle (not in rad, nor bare)."""
    with pytest.raises(ValueError, match=r"angle_out = 1145.92 deg lies outside the possible "
                       r"range \[0, 180\] deg by more than 3 sigma \(angle_out_sigma = 1 deg; "
                       r".*\) \(the rod's angle to the flat at separation, in "
                       r"\[0, 180\] deg"):  # fmt: skip
        _one(angle_out="20 rad", angle_out_sigma="1 deg")
    with pytest.raises(ValueError, match=r": angle_out = 190 deg lies outside the possible "
                       r"range \[0, 180\] deg by more than 3 sigma \("):  # fmt: skip
        _one(angle_out="190 deg", angle_out_sigma="1 deg")
    assert _one(angle_out="182 deg", angle_out_sigma="1 deg").n_values == 1  # noise
    with pytest.raises(ValueError, match=r"angle_out = -5 deg lies outside"):
        _one(angle_out="-5 deg", angle_out_sigma="1 deg")
    with pytest.raises(ValueError, match=r": angle_out_sigma = 400 deg is wider than the whole "
                       r"range of angle_out \[0, 180\] deg: an implausible"):  # fmt: skip
        _one(angle_out="30 deg", angle_out_sigma="400 deg")
    with pytest.raises(ValueError, match=r": angle_out_sigma must be finite and > 0, got 0 deg$"):
        _one(angle_out="30 deg", angle_out_sigma="0 deg")
    with pytest.raises(ValueError, match=r"got -1 deg$"):
        _one(angle_out="30 deg", angle_out_sigma="-1 deg")
    assert _one(angle_out="100 deg", angle_out_sigma="1 deg").n_values == 1


@pytest.mark.parametrize(
    ("columns", "quantity", "value", "sigma"),
    [
        ({"e": "43 %", "e_sigma": "2 %"}, "e", 0.43, 0.02),
        ({"e [%]": 43, "e_sigma": 2}, "e", 0.43, 0.02),
        ({"e [percent]": "43", "e_sigma [%]": "2"}, "e", 0.43, 0.02),
        ({"e_t": "-20 %", "e_t_sigma": "5 %", "vx": 0.5}, "e_t", -0.2, 0.05),
    ],
)  # fmt: skip
def test_a_fraction_may_be_given_in_percent(columns, quantity, value, sigma):
    m = _one(**columns)
    assert m.observed[quantity][0] == pytest.approx(value)
    assert m.sigma[quantity][0] == pytest.approx(sigma)


def test_an_input_fraction_in_percent(tmp_path):
    m = _one(**{"mu": "20 %", "damping [%]": 5, "e": 0.4, "e_sigma": 0.02})
    assert (m.inputs["mu"][0], m.inputs["damping"][0]) == pytest.approx((0.2, 0.05))
    toml = read_measurements(_toml(tmp_path, 'e = "%"', "e = 40\ne_sigma = 2"))
    assert (toml.observed["e"][0], toml.sigma["e"][0]) == pytest.approx((0.4, 0.02))


@pytest.mark.parametrize(
    ("columns", "match"),
    [
        ({"e": 0.4, "e_sigma": "5 %"},
         r"e_sigma = '5 %' is in percent while e = '0.4' is not: a percentage of e could be "
         r"relative \(of the value\) or of 1; give e_sigma as e is"),
        ({"e": 0.4, "e_sigma [%]": 5}, r"e_sigma = '5 %' is in percent while e = '0.4' is not"),
        ({"e": "43 %", "e_sigma": 2},
         r"e_sigma = 2 has no unit while e = '43 %' has one: give the uncertainty's unit too "
         r"\(e.g. '2 %'\)"),
        ({"e": 0.4, "e_sigma": 0.02, "flat_nu": "30 %"},
         r"flat_nu: '30 %' is in percent; only a fraction \(e, e_energy, e_t, mu, damping\) may "
         r"be"),
        ({"delta_p": "5 %", "delta_p_sigma": "1 %"}, r"delta_p: '5 %' is in percent"),
    ],
)  # fmt: skip
def test_a_percentage_that_could_be_read_two_ways_is_refused(columns, match):
    with pytest.raises(ValueError, match=match) as info:
        _one(**columns)
    assert str(info.value).startswith("drop 1") and "\n" not in str(info.value)


def test_a_semicolon_file_with_decimal_commas_is_named(tmp_path):
    """Its rows split at the decimal commas too: the header's one column is named first, not
    'line 2: 4 fields, the header has 1'."""
    path = tmp_path / "m.csv"
    path.write_text("label;angle [deg];vy [m/s];e;e_sigma\na;20;-1,41;0,4;0,02\n")
    with pytest.raises(ValueError, match=r"line 1: the header is one column 'label;angle \[deg\];"
                       r".*separates its columns with ';'; a measurements CSV separates them "
                       r"with commas and writes decimals with a point \(0.4, "
                       r"not 0,4\)"):  # fmt: skip
        read_measurements(path)
    path.write_text("label\tangle [deg]\tvy [m/s]\na\t20\t-1.41\n")
    with pytest.raises(ValueError, match=r"separates its columns with tabs"):
        read_measurements(path)


@pytest.mark.parametrize(
    ("spec", "match"),
    [
        ("normal(300 MPa, 50)", r"prior of flat_yield_strength: 'normal\(300 MPa, 50\)': 50 has "
         r"no unit while '300 MPa' has one: give its unit too \(e.g. '50 MPa'\)"),
        ("uniform(100 MPa, 1000)", r"1000 has no unit while '100 MPa' has one"),
        ("normal(300, 50 MPa)", r"300 has no unit while '50 MPa' has one"),
        ({"prior": "normal", "mean": "300 MPa", "sd": 50}, r"50 has no unit while '300 MPa'"),
    ],
)  # fmt: skip
def test_a_prior_mixing_a_unit_and_a_bare_number_is_refused(spec, match):
    """normal(300 MPa, 50) was normal(300 MPa, 50 Pa): a posterior sd of 43 Pa."""
    with pytest.raises(ValueError, match=match):
        parse_parameter("flat_yield_strength", spec)


def test_a_bare_zero_or_open_end_beside_a_unit_is_kept():
    p = parse_parameter("flat_yield_strength", "normal(300 MPa, 50 MPa, 0, inf)")
    assert (p.mean, p.sd, p.low, p.high) == (3e8, 5e7, 0.0, math.inf)
    assert parse_parameter("flat_yield_strength", "uniform(0, 1 GPa)").high == 1e9
    assert parse_parameter("mu", "uniform(0, 0.6)").high == 0.6  # a number of unit 1
    with pytest.raises(ValueError, match=r"200 has no unit while '50 HB' has one"):
        parse_parameter("flat_brinell_hardness", "uniform(50 HB, 200)")
