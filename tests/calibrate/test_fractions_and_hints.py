"""A fraction in percent reads alike in a measurements file, a prior and a model's fixed inputs;
a header in the unit 1 reads; a prior's hint for a bare number names a unit that keeps its
magnitude; a drop that measures nothing is refused."""

from __future__ import annotations

import pytest

from impactlab.calibrate import Measurements, parse_parameter, read_measurements
from impactlab.calibrate.fixed import fixed_values


@pytest.mark.parametrize(
    ("name", "percent", "fraction"),
    [
        ("mu", "uniform(0, 60 %)", "uniform(0, 0.6)"),
        ("mu", "uniform(0, 60%)", "uniform(0, 0.6)"),
        ("mu", "normal(20 %, 5 percent)", "normal(0.2, 0.05)"),
        ("damping", "loguniform(0.1 %, 20 %)", "loguniform(0.001, 0.2)"),
        ("damping", {"prior": "uniform", "low": "1 %", "high": "20 %"}, "uniform(0.01, 0.2)"),
    ],
)
def test_a_prior_of_a_fraction_may_be_in_percent(name, percent, fraction):
    assert parse_parameter(name, percent) == parse_parameter(name, fraction)
    assert parse_parameter(name, percent).describe() == fraction


@pytest.mark.parametrize(
    ("name", "spec"),
    [("mu", "normal(30 %, 5)"), ("damping", "normal(5 %, 2)"), ("mu", "uniform(5 %, 60)")],
)
def test_a_prior_mixing_percent_and_a_bare_number_is_refused(name, spec):
    """normal(30 %, 5) read the sd as 5 (500 %): as the measurements file, a percentage beside
    a bare number is refused (a bare 0 stays allowed: it is 0 in both)."""
    with pytest.raises(ValueError, match=r"has no unit while '.* %' is in percent"):
        parse_parameter(name, spec)
    assert parse_parameter("mu", "uniform(0, 60 %)").describe() == "uniform(0, 0.6)"


def test_a_prior_in_percent_of_no_fraction_is_refused():
    with pytest.raises(ValueError, match=r"^body_nu: '30 %' has dimensionless units"):
        parse_parameter("body_nu", "uniform(0, 30 %)")
    with pytest.raises(ValueError, match=r"^prior of damping: \[0, 1.6\] reaches outside"):
        parse_parameter("damping", "uniform(0, 160 %)")


@pytest.mark.parametrize("value", ["5 %", "5%", "5 percent", {"value": 5, "unit": "%"}, 0.05])
def test_a_fixed_fraction_may_be_in_percent(value):
    assert fixed_values("m", {"damping": value}) == {"damping": pytest.approx(0.05)}
    assert fixed_values("m", {"mu": value}) == {"mu": pytest.approx(0.05)}


def test_a_fixed_percentage_of_no_fraction_is_refused():
    with pytest.raises(ValueError, match=r"^model 'm', fixed flat_nu: flat_nu: '30 %'"):
        fixed_values("m", {"flat_nu": "30 %"})


def test_a_header_in_the_unit_1_reads(tmp_path):
    path = tmp_path / "drops.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu [1],e [1],e_sigma [1],e_t,e_t_sigma [1],vx [m/s]\n"
        "a,20,-1.41,0.15,0.4,0.01,0.3,0.02,0.5\n"
    )
    m = read_measurements(path)
    assert (m.observed["e"][0], m.sigma["e"][0]) == (0.4, 0.01)
    assert (m.observed["e_t"][0], m.sigma["e_t"][0], m.inputs["mu"][0]) == (0.3, 0.02, 0.15)


@pytest.mark.parametrize(
    ("name", "spec", "hint"),
    [
        ("flat_yield_strength", "uniform(1e8, 1 GPa)", "1e8 Pa"),  # not 1e8 GPa = 1e17 Pa
        ("flat_yield_strength", "uniform(1e8, 1e9 Pa)", "1e8 Pa"),
        ("flat_yield_strength", "normal(300 MPa, 50)", "50 MPa"),
        ("flat_yield_strength", "uniform(100 MPa, 1000)", "1000 MPa"),
        ("flat_brinell_hardness", "uniform(50 HB, 200)", "200 HB"),
    ],
)
def test_the_unit_hinted_for_a_bare_number_keeps_its_magnitude(name, spec, hint):
    with pytest.raises(ValueError, match=r"has no unit while") as info:
        parse_parameter(name, spec)
    assert f"give its unit too (e.g. '{hint}'); a number without a unit" in str(info.value)


def test_a_drop_that_measures_nothing_is_refused(tmp_path):
    """With two models its zeros made the ranking's spread (elpd_diff 1689 +- 1194)."""
    path = tmp_path / "drops.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma\na,20,-1.4,0.15,0.4,0.01\nb,45,-1.4,0.15,,\n"
    )
    with pytest.raises(ValueError, match=r": line 3: drop 2 \(b\)") as info:
        read_measurements(path)
    assert str(info.value) == (
        f"{path}: line 3: drop 2 (b) has no measured value: give e with its uncertainty where "
        "it was measured, or leave the drop out"
    )
    recs = [
        {"label": "a", "angle": "20 deg", "vy": -1.4, "e": 0.4, "e_sigma": 0.01},
        {"label": "b", "angle": "45 deg", "vy": -1.4, "delta_p": "50 um", "delta_p_sigma": "2 um"},
        {"label": "c", "angle": "70 deg", "vy": -1.4},
    ]
    with pytest.raises(ValueError, match=r"^drop 3 \(c\) has no measured value: give e or "
                       r"delta_p with its uncertainty"):  # fmt: skip
        Measurements.from_records(recs)
    assert Measurements.from_records(recs[:2]).n_drops == 2
