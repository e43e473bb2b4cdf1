"""Refusals of calibrate's inputs that name what is wrong: a misspelt free parameter whose prior
carries units (named before its numbers are read), a theta of the wrong shape or not finite in
``predict`` (a NaN read as the preset's value), an invert input file given as measurements;
and the predictions' rows carry ``reason`` always ("" when nothing failed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab.calibrate import parse_model, parse_parameter, predict, read_measurements

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


def test_a_misspelt_parameter_is_named_before_its_units() -> None:
    with pytest.raises(ValueError, match=r"unknown free parameter 'flat_yield_strenth' \(did you"):
        parse_parameter("flat_yield_strenth", "uniform(100 MPa, 1 GPa)")


@pytest.mark.parametrize(
    ("theta", "message"),
    [
        ([[np.nan, 0.2]], r"theta\[0, 0\] \(flat_yield_strength\) is nan; every value"),
        ([[305e6, np.inf]], r"theta\[0, 1\] \(mu\) is inf"),
        (
            [[305e6, 0.2, 1.0]],
            r"theta must have shape \(W, 2\), a row of \(flat_yield_strength, mu\)",
        ),
        ([[305e6]], r"got \(1, 1\)"),
    ],
)
def test_predict_refuses_a_theta_it_cannot_read(theta: list, message: str) -> None:
    meas = read_measurements(DATA / "drops.csv")
    params = [parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)"),
              parse_parameter("mu", "uniform(0, 0.6)")]  # fmt: skip
    with pytest.raises(ValueError, match=message):
        predict(parse_model("ghaednia/coulomb"), meas, params, np.array(theta), quantities=["e"])


def test_an_invert_file_is_named_as_such() -> None:
    with pytest.raises(ValueError, match=r"unknown key\(s\) .*an input file of impactlab invert"):
        read_measurements(DATA / "measurements.toml")


def test_a_subnormal_sigma_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "tiny.csv"
    path.write_text("label,angle [deg],vy,e,e_sigma\na,20,-1.41,0.42,1e-320\n", encoding="utf-8")
    with pytest.raises(ValueError, match=r"drop 1 \(a\): e_sigma = 1e-320 is below 2\.23e-308"):
        read_measurements(path)


@pytest.mark.parametrize("name", ["n_axial", "n_bending"])
def test_a_mode_count_is_no_free_parameter(name) -> None:
    """A continuous prior on a mode count failed every draw as 'body rejected (a non-positive
    length, radius, mass ...)'; it is a resolution, not physics."""
    from impactlab.calibrate import parse_parameter

    with pytest.raises(ValueError, match=f"{name} is a count of a flexible rod's modes"):
        parse_parameter(name, "uniform(1, 64)")
    with pytest.raises(ValueError, match="unknown free parameter 'bogus'") as err:
        parse_parameter("bogus", "uniform(1, 64)")
    assert name not in str(err.value)
