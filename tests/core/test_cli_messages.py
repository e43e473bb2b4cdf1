"""The command line answers angle errors in degrees, prints no numpy repr, says that nan and inf
are not finite, gives a bad material value with its unit, shows impactlab's warnings as one line
and reports max_delta_ratio (``impactlab simulate rod`` through the command's ``main``, in this
process: the ``cli_main`` fixture)."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]


def _rod(cli_main: CliMain, *args: str) -> tuple[int, str, str]:
    return cli_main("simulate", "rod", *args)


@pytest.mark.parametrize("angle", ["95 deg", "-20 deg"])
def test_angle_error_is_in_degrees(cli_main: CliMain, angle: str) -> None:
    code, _, err = _rod(cli_main, "--angle", angle, "--vy", "-1.41 m/s")
    assert code == 2
    assert err.strip().startswith(f"error: --angle must be in (0, 90] deg, got {angle}")
    assert ("past the flat's normal" in err) == (angle == "95 deg")


def test_receding_velocity_error_has_no_numpy_repr(cli_main: CliMain) -> None:
    code, _, err = _rod(cli_main, "--angle", "20 deg", "--vy", "1.41 m/s")
    assert code == 2 and "np.float64" not in err
    assert "= 1.41 m/s must be < 0" in err


def test_implausible_input_warning_is_one_line(cli_main: CliMain) -> None:
    _, _, err = _rod(cli_main, "--angle", "20 deg", "--vy", "-1e3 m/s")
    lines = err.strip().splitlines()
    assert lines[0].startswith("warning: the impact speed (1000 m/s) exceeds 100 m/s")
    assert "ImplausibleInputWarning" not in err and ".py:" not in err


def test_json_and_table_report_max_delta_ratio(cli_main: CliMain) -> None:
    code, out, err = _rod(cli_main, "--angle", "20 deg", "--vy", "-1.41 m/s", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["max_delta_ratio"]["unit"] == "1" and data["max_delta_ratio"]["value"] > 110.0
    assert data["extrapolated"] is True
    _, table, _ = _rod(cli_main, "--angle", "20 deg", "--vy", "-1.41 m/s")
    assert sum("max_delta_ratio" in line for line in table.splitlines()) == 1


@pytest.mark.parametrize("option", ["--vx", "--vy", "--spin", "--mass", "--radius", "--length"])
@pytest.mark.parametrize("value", ["nan", "inf", "-inf"])
def test_a_quantity_that_is_not_finite_is_named_as_such(
    cli_main: CliMain, option: str, value: str
) -> None:
    args = ["--angle", "20 deg", "--vy", "-1.41 m/s", option, value]
    if option == "--vy":
        args = args[:2] + args[4:]
    code, _, err = _rod(cli_main, *args)
    assert code == 2
    assert err.strip() == f"error: {option} must be finite, got {value!r}"


@pytest.mark.parametrize(
    "args",
    [
        ("--angle", "nan", "--vy", "-1 m/s"),
        ("--speed", "inf", "--incidence", "20 deg", "--angle", "20 deg"),
        ("--speed", "1 m/s", "--incidence", "nan", "--angle", "20 deg"),
    ],
)
def test_angles_and_speeds_that_are_not_finite(cli_main: CliMain, args: tuple[str, ...]) -> None:
    code, _, err = _rod(cli_main, *args)
    bad = next(i for i, a in enumerate(args) if a in ("nan", "inf"))
    assert code == 2
    assert err.strip() == f"error: {args[bad - 1]} must be finite, got {args[bad]!r}"


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("E=-69GPa", "E must be > 0 Pa, got -6.9e+10 Pa"),
        ("Sy=-276MPa", "yield_strength must be > 0 Pa, got -2.76e+08 Pa"),
        ("rho=-2700kg/m^3", "density must be > 0 kg/m^3, got -2700.0 kg/m^3"),
        ("HB=-3", "brinell_hardness must be > 0 kgf/mm^2, got -3.0 kgf/mm^2"),
        ("Sy=100GPa", "yield_strength (1e+11 Pa) must be smaller than E (6.9e+10 Pa)"),
        ("nu=0.7", "nu must lie in (-1.0, 0.5), got 0.7"),
    ],
)
def test_a_bad_material_value_is_given_with_its_unit(
    cli_main: CliMain, value: str, message: str
) -> None:
    props = {"E": "69GPa", "nu": "0.33", "Sy": "276MPa", "rho": "2700kg/m^3"}
    key, _, given = value.partition("=")
    flat = ", ".join(f"{k}={v}" for k, v in (props | {key: given}).items())
    code, _, err = _rod(cli_main, "--angle", "20 deg", "--vy", "-1 m/s", "--flat", flat)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith(f"error: --flat: {message}"), err


def test_a_dimensionless_prior_outside_its_values_has_no_unit(
    cli_main: CliMain, tmp_path: Path
) -> None:
    drops = tmp_path / "m.csv"
    drops.write_text("label,angle [deg],vy [m/s],e,e_sigma\na,20,-1.41,0.5,0.02\n")
    code, _, err = cli_main("calibrate", str(drops), "-p", "mu=uniform(-1,1)")
    assert code == 2
    assert err == "error: prior of mu: [-1, 1] reaches outside the possible values [0, inf]\n"
