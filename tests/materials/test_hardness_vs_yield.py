"""A Brinell hardness whose pressure (HB x 9.80665e6 Pa) lies below the material's own yield
strength is a unit slip (a hardness is about 3 S_y): refused in one line naming HB, both
values with their units and that HB is in kgf/mm^2, where a user gives the values (the text,
mapping and TOML forms, the command line); a copy with a raised yield strength (sweeps,
calibrations) is still made. The library's entries load."""

from __future__ import annotations

import dataclasses
import re

import pytest

from impactlab import Material
from impactlab.materials import get_material
from impactlab.materials.core import hardness_below_yield
from impactlab.materials.library import PRESETS

SLIP = (
    r"brinell_hardness HB = 9\.5 kgf/mm\^2 \(93\.16 MPa\) lies below the yield strength S_y = "
    r"276 MPa, while a hardness is about 3 S_y; HB is in kgf/mm\^2 \(a Brinell number: HB 95 "
    r"is 932 MPa\), check its unit$"
)


def test_a_hardness_below_the_yield_strength_is_named() -> None:
    slip = hardness_below_yield(Material("al", 69e9, 0.33, 276e6, 9.5, density=2700.0))
    assert re.match("^" + SLIP, slip), slip
    # at the yield strength and above (a hardness of 3 S_y and more): nothing to say
    assert hardness_below_yield(Material("al", 69e9, 0.33, 276e6, 95.0, density=2700.0)) == ""
    assert hardness_below_yield(Material("x", 69e9, 0.33, 276e6, 276e6 / 9.80665e6)) == ""


def test_a_copy_with_a_raised_yield_strength_is_still_made() -> None:
    """A sweep or a calibration raises a library flat's S_y and keeps its HB (only Brake's law
    reads it): the copy is made, not refused."""
    flat = get_material("aisi-1010")
    raised = dataclasses.replace(flat, yield_strength=2.0e9)
    assert raised.yield_strength == 2.0e9 and hardness_below_yield(raised)


def test_the_text_form_names_where() -> None:
    with pytest.raises(ValueError, match=r"^--flat: " + SLIP):
        get_material("E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3, HB=9.5", "--flat")


def test_the_command_line_refuses_it_in_one_line(cli_main) -> None:
    code, _, err = cli_main(
        "simulate", "sphere", "--radius", "3 mm", "--vy", "-2.5 m/s", "--material", "aisi-52100",
        "--flat", "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3, HB=9.5",
    )  # fmt: skip
    assert code == 2 and "lies below the yield strength S_y = 276 MPa" in err
    assert "HB is in kgf/mm^2" in err and "Traceback" not in err


def test_the_library_loads() -> None:
    for key, m in PRESETS.items():
        assert get_material(key) is m
        if m.has_hardness:
            assert m.brinell_hardness * 9.80665e6 > 2.5 * m.yield_strength, key


@pytest.mark.parametrize(
    ("field", "value"),
    [("yield_strength", 1e-100), ("yield_strength", 1e-300), ("E", 1e-200), ("density", 1e-310)],
)
def test_a_value_far_below_the_plausible_is_refused(field, value) -> None:
    """No solid has it, and the contact laws' closed forms divide by zero or overflow there: a
    one-line refusal naming the field, not a ZeroDivisionError from a law."""
    values = {"E": 200e9, "nu": 0.3, "yield_strength": 300e6, "density": 7800.0}
    values[field] = value
    if field == "E":
        values["yield_strength"] = 1e-201
    with pytest.raises(
        ValueError, match=rf"{field} = .* lies below .*, 1000 times below the plausible"
    ):
        Material("x", **values)


def test_the_command_line_refuses_a_yield_strength_of_1e_minus_100(cli_main) -> None:
    code, _, err = cli_main(
        "simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s",
        "--flat", "E=200GPa, nu=0.3, Sy=1e-100 Pa, rho=7800kg/m^3",
    )  # fmt: skip
    assert code == 2 and err.count("\n") == 1 and "1000 times below the plausible" in err
