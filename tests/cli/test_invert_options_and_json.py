"""``impactlab invert``: ``--flat`` read as written (units and file names keep their case),
``--measure``, a measurement file that takes the Python and JSON names (so that a result's
inputs feed back), errors that name each input as the user gave it, and a JSON whose inputs and
sensitivities are the same quantities as the Python result's."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab.analytic import invert
from impactlab.paper.data import get_case

CliMain = Callable[..., tuple[int, str, str]]

ARGS = ("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
        "--delta-p", "22 um", "--ls", "1400 um", "--samples", "200")  # fmt: skip
PY: dict[str, Any] = {
    "angle": math.radians(20),
    "v_i": -1.41,
    "e": 0.5,
    "mu": 0.2,
    "delta_p": 22e-6,
    "sliding_length": 1400e-6,
    "n_samples": 200,
}


def _json(cli_main: CliMain, *args: str) -> dict[str, Any]:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    return json.loads(out)  # type: ignore[no-any-return]


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main(*args)
    assert code == 2 and out == "", err
    assert err.count("\n") == 1 and err.startswith("error: ")
    return err.strip().removeprefix("error: ")


# -- --flat ------------------------------------------------------------------------------------


def test_flat_by_values_keeps_the_case_of_its_units(cli_main: CliMain) -> None:
    data = _json(cli_main, "invert", "--case", "paper-20", "--samples", "200",
                 "--flat", "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3")  # fmt: skip
    assert data["model"]["flat"].startswith("custom (E 69 GPa, nu 0.33, Sy 276 MPa, rho 2700")
    data = _json(cli_main, "invert", "--case", "paper-20", "--samples", "200",
                 "--flat", "E=200GPa, nu=0.3, Sy=305MPa, rho=7.87 Mg/m^3")  # fmt: skip
    assert "rho 7870 kg/m^3" in data["model"]["flat"]  # megagrams, not milligrams


def test_flat_file_name_keeps_its_case(cli_main: CliMain, tmp_path: Path) -> None:
    path = tmp_path / "Flat.toml"
    path.write_text('E = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = 2700\nname = "my Al"\n')
    data = _json(cli_main, "invert", "--case", "paper-20", "--samples", "200", "--flat", str(path))
    assert data["model"]["flat"] == "my Al"


# -- the JSON: inputs and sensitivities are the Python result's ---------------------------------


def test_json_inputs_and_sensitivities_are_the_same_quantities(cli_main: CliMain) -> None:
    data = _json(cli_main, "invert", "--case", "paper-45", "--samples", "200")
    x = get_case("paper-45")
    res = invert(angle=x.angle, v_i=x.v_i, e=x.e, mu=x.mu, delta_p=abs(x.delta_p),
                 sliding_length=abs(x.L_s), n_samples=200)  # fmt: skip
    assert data["inputs"]["v_i"]["value"] == res.inputs["v_i"][0] == abs(x.v_i)
    for k, (value, _sigma) in res.inputs.items():
        assert data["inputs"][k]["value"] == value
        assert data["sensitivity_T"][k]["value"] == res.sensitivity_T[k]
        assert data["sensitivity_F"][k]["value"] == res.sensitivity_F[k]
    units = {k: q["unit"] for k, q in data["sensitivity_T"].items()}
    assert units == {"angle": "s/rad", "v_i": "s/(m/s)", "mu": "s", "delta_p": "s/m",
                     "sliding_length": "s/m", "e": "s"}  # fmt: skip
    assert data["sensitivity_F"]["delta_p"]["unit"] == "N/m"
    # dT/d|v_i| < 0 with |v_i| = 2.18 > 0 echoed: the same variable
    assert data["sensitivity_T"]["v_i"]["value"] < 0 < data["inputs"]["v_i"]["value"]


# -- --measure and the measurement file ----------------------------------------------------------


def test_measure_option(cli_main: CliMain) -> None:
    travel = _json(cli_main, *ARGS, "--measure", "travel")
    assert travel["measure"] == "travel"
    assert travel["duration"]["value"] == invert(**PY, measure="travel").duration
    assert _json(cli_main, *ARGS)["duration"]["value"] == invert(**PY).duration
    assert _error(cli_main, *ARGS, "--measure", "patch") == (
        "--measure must be 'slip' or 'travel', got 'patch'"
    )


def test_a_file_takes_the_python_names_and_measure(cli_main: CliMain, tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text(
        'angle = "20 deg"\nv_i = "-1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\n'
        'sliding_length = "1400 um"\nmeasure = "travel"\nn_samples = 200\n'
        "[sigma]\nsliding_length = 50\n"
    )
    data = _json(cli_main, "invert", "--file", str(path))
    expected = invert(**{**PY, "sliding_length": (1400e-6, 50e-6)}, measure="travel")
    assert data["measure"] == "travel" and data["n_samples"] == 200
    assert data["duration"]["value"] == expected.duration
    assert data["inputs"]["sliding_length"]["sigma"] == pytest.approx(50e-6, rel=1e-12)
    assert _json(cli_main, "invert", "--file", str(path), "--measure", "slip")["measure"] == "slip"


def test_a_result_feeds_back_as_a_measurement_file(cli_main: CliMain, tmp_path: Path) -> None:
    first = _json(cli_main, *ARGS, "--sigma-ls", "50 um", "--measure", "travel")
    lines = [f'{k} = "{q["value"]!r} {q["unit"]}"' for k, q in first["inputs"].items()]
    sigmas = [f'{k} = "{q["sigma"]!r} {q["unit"]}"' for k, q in first["inputs"].items()
              if "sigma" in q]  # fmt: skip
    text = "\n".join([*lines, f'measure = "{first["measure"]}"', "n_samples = 200", "[sigma]",
                      *sigmas]).replace('"1"', '""').replace(' 1"', '"')  # fmt: skip
    path = tmp_path / "again.toml"
    path.write_text(text + "\n")
    again = _json(cli_main, "invert", "--file", str(path))
    for k in ("duration", "mean_force", "T_mc", "inputs", "sensitivity_T", "measure"):
        assert again[k] == first[k], k


def test_a_result_feeds_back_in_its_own_quantity_tables(cli_main: CliMain, tmp_path: Path) -> None:
    """The JSON's ``{value, unit, sigma}`` of each input, written as TOML inline tables."""
    first = _json(cli_main, *ARGS, "--sigma-ls", "50 um", "--measure", "travel")
    lines = [
        f"{k} = {{ {', '.join(f'{kk} = {json.dumps(v)}' for kk, v in q.items())} }}"
        for k, q in first["inputs"].items()
    ]
    path = tmp_path / "tables.toml"
    path.write_text("\n".join([*lines, 'measure = "travel"', "n_samples = 200"]) + "\n")
    again = _json(cli_main, "invert", "--file", str(path))
    for k in ("duration", "mean_force", "T_mc", "inputs", "sensitivity_T", "measure"):
        assert again[k] == first[k], k
    path.write_text('angle = { value = 0.35, units = "rad" }\n')
    code, _, err = cli_main("invert", "--file", str(path))
    assert code == 2 and "a quantity's table holds value, unit and sigma" in err


def test_a_file_may_give_an_input_once(cli_main: CliMain, tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text('case = "paper-20"\nls = "1400 um"\nsliding_length = "1300 um"\n')
    assert _error(cli_main, "invert", "--file", str(path)) == (
        "'ls' and 'sliding_length' in the measurement file give the same input (--ls); give it once"
    )
    path.write_text('case = "paper-20"\nmeasure = "patch"\n')
    assert _error(cli_main, "invert", "--file", str(path)) == (
        "measure in the measurement file must be 'slip' or 'travel', got 'patch'"
    )


# -- errors name the input as given --------------------------------------------------------------


def _replaced(option: str, value: str) -> list[str]:
    args = list(ARGS)
    args[args.index(option) + 1] = value
    return args


@pytest.mark.parametrize(
    ("option", "value", "start"),
    [
        ("--mu", "nan", "--mu must be finite, got nan"),
        ("--mu", "-0.2", "--mu must be >= 0, got -0.2"),
        ("--e", "1.5", "--e must lie in [0, 1], got 1.5"),
        ("--ls", "0 um", "--ls must be non-zero: in gross sliding"),
        ("--delta-p", "-22 um", "--delta-p must be >= 0 (the permanent dent depth"),
        ("--vi", "0", "--vi must be non-zero (the drop speed)"),
    ],
)
def test_errors_name_the_option(cli_main: CliMain, option: str, value: str, start: str) -> None:
    assert _error(cli_main, *_replaced(option, value)).startswith(start)


def test_errors_name_sigmas_and_file_keys(cli_main: CliMain, tmp_path: Path) -> None:
    assert _error(cli_main, *ARGS, "--sigma-mu", "-0.1") == "--sigma-mu must be >= 0, got -0.1"
    assert _error(cli_main, *ARGS, "--dv-cy", "-0.3").startswith("--dv-cy must be > 0")
    assert _error(cli_main, *ARGS, "--seed", "-1") == "--seed must be an integer >= 0, got -1"
    path = tmp_path / "m.toml"
    path.write_text('case = "paper-20"\nsliding_length = 0\n')
    assert _error(cli_main, "invert", "--file", str(path)).startswith(
        "sliding_length in the measurement file must be non-zero"
    )
    path.write_text('case = "paper-20"\nmu = nan\n[sigma]\ne = 0.3\n')
    assert _error(cli_main, "invert", "--file", str(path)) == (
        "mu in the measurement file must be finite, got nan"
    )
    path.write_text('case = "paper-20"\n[sigma]\ne = 0.3\n')
    assert _error(cli_main, "invert", "--file", str(path)).startswith(
        "sigma.e (in the measurement file) = 0.3 does not fit its range"
    )


# -- a value written with a Unicode minus sign keeps its unit for a bare sigma --------------------


def test_a_bare_sigma_takes_the_unit_of_a_value_with_a_unicode_minus(cli_main: CliMain) -> None:
    data = _json(cli_main, *_replaced("--vi", "\u2212141 cm/s"), "--sigma-vi", "2")
    assert data["inputs"]["v_i"]["sigma"] == pytest.approx(0.02, rel=1e-12)  # 2 cm/s, not m/s
    data = _json(cli_main, *_replaced("--ls", "\u20101400 um"), "--sigma-ls", "50")
    assert data["inputs"]["sliding_length"]["sigma"] == pytest.approx(50e-6, rel=1e-12)


def test_a_file_sigma_takes_the_unit_of_a_value_with_a_unicode_minus(
    cli_main: CliMain, tmp_path: Path
) -> None:
    path = tmp_path / "m.toml"
    path.write_text(
        'angle = "20 deg"\nvi = "\u2212141 cm/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\n'
        'ls = "\u22121400 um"\nn_samples = 200\n[sigma]\nls = 50\nvi = 2\n',
        encoding="utf-8",
    )
    data = _json(cli_main, "invert", "--file", str(path))
    assert data["inputs"]["sliding_length"]["sigma"] == pytest.approx(50e-6, rel=1e-12)
    assert data["inputs"]["v_i"]["sigma"] == pytest.approx(0.02, rel=1e-12)


def test_a_file_value_error_says_it_is_in_the_file(cli_main: CliMain, tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text('case = "paper-20"\nv_i = "fast"\n')
    assert _error(cli_main, "invert", "--file", str(path)).startswith(
        "v_i in the measurement file: cannot parse 'fast' as a quantity"
    )
    path.write_text('case = "paper-20"\nangle = 20\n')
    assert _error(cli_main, "invert", "--file", str(path)) == (
        "angle = 20 in the measurement file has no unit: give a unit, e.g. '20 deg' or '0.35 rad'"
    )
