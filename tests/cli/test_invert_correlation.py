"""``impactlab invert --correlation`` and a measurement file's ``correlation``: the command's
sigmas are the Python API's with the same correlations, a result fed back through ``--file``
repeats the inversion with its correlations, and every faulty correlation is refused in one
line naming it."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab.analytic import invert

CliMain = Callable[..., tuple[int, str, str]]

ARGS = ("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
        "--delta-p", "22 um", "--ls", "1400 um", "--sigma-vi", "0.01 m/s", "--sigma-e", "0.02",
        "--sigma-mu", "0.01", "--sigma-ls", "50 um", "--samples", "500")  # fmt: skip
#: the same inputs for Python's invert (a sigma with its unit read as the command reads it)
PY: dict[str, Any] = {
    "angle": "20 deg",
    "v_i": ("-1.41 m/s", 0.01),
    "e": (0.5, 0.02),
    "mu": (0.2, 0.01),
    "delta_p": "22 um",
    "sliding_length": ("1400 um", 50),
    "n_samples": 500,
}
#: the outputs a correlation changes, and those that show it
COMPARED = ("duration", "mean_force", "T_mc", "F_mc", "T_interval_mc", "F_interval_mc",
            "inputs", "correlation", "sensitivity_T", "sensitivity_F")  # fmt: skip


def _json(cli_main: CliMain, *args: str) -> dict[str, Any]:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    return json.loads(out)  # type: ignore[no-any-return]


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main(*args)
    assert code == 2 and out == "", err
    assert err.count("\n") == 1 and err.startswith("error: "), err
    return err.strip().removeprefix("error: ")


def _toml(value: Any) -> str:
    """``value`` (JSON data) as a TOML value: inline tables for mappings."""
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_toml(v)}" for k, v in value.items()) + " }"
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return json.dumps(value)


def _fed_back(data: dict[str, Any], path: Path) -> Path:
    """The JSON of ``invert --json`` written as a measurement file: its inputs, rod,
    correlation, measure, gravity, n_samples and seed."""
    keys = ("inputs", "correlation", "measure", "gravity", "n_samples", "seed")
    lines = [f"{k} = {_toml(q)}" for k, q in data["inputs"].items()]
    lines += [f"{k} = {_toml(data[k])}" for k in keys[1:]]
    lines += ["[rod]", *(f"{k} = {_toml(q)}" for k, q in data["rod"].items())]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_the_commands_sigmas_are_the_python_apis(cli_main: CliMain) -> None:
    """Formerly the command had no way to give correlations: its sigmas were those of
    independent inputs."""
    data = _json(cli_main, *ARGS, "--correlation", "e,mu=-0.3", "--correlation", "vi,ls=0.5")
    corr = {("e", "mu"): -0.3, ("v_i", "sliding_length"): 0.5}
    res = invert(**PY, correlation=corr)
    independent = invert(**PY)
    assert data["duration"]["sigma"] == res.sigma_T_linear != independent.sigma_T_linear
    assert data["mean_force"]["sigma"] == res.sigma_F_linear != independent.sigma_F_linear
    assert data["T_mc"]["sigma"] == res.sigma_T_mc and data["F_mc"]["sigma"] == res.sigma_F_mc
    # the coefficients of the inputs as used (|v_i|): v_i was given negative
    assert {tuple(c["inputs"]): c["coefficient"]["value"] for c in data["correlation"]} == {
        ("mu", "e"): -0.3,
        ("v_i", "sliding_length"): -0.5,
    }
    # Python's keywords and the options' names alike
    same = _json(cli_main, *ARGS, "--correlation", "mu, e = -0.3",
                 "--correlation", "sliding_length,v_i=0.5")  # fmt: skip
    assert same["duration"] == data["duration"] and same["mean_force"] == data["mean_force"]


def test_the_table_shows_the_coefficients_of_the_magnitudes_as_the_json(
    cli_main: CliMain,
) -> None:
    """--vi "-1.41 m/s": the table shows |v_i| and its coefficient, as the JSON's."""
    code, out, err = cli_main(*ARGS, "--correlation", "vi,ls=0.5")
    assert code == 0, err
    assert "(|v_i|, |sliding_length|) -0.5 " in " ".join(out.split()) + " "
    code, out, err = cli_main(*ARGS)
    assert code == 0 and "correlation" not in out


def test_a_result_fed_back_repeats_the_inversion_with_its_correlations(
    cli_main: CliMain, tmp_path: Path
) -> None:
    """Formerly a file's ``correlation`` was not read: the inversion fed back was another one."""
    first = _json(cli_main, *ARGS, "--correlation", "e,mu=-0.3", "--correlation", "vi,ls=0.5")
    again = _json(cli_main, "invert", "--file", str(_fed_back(first, tmp_path / "again.toml")))
    for k in COMPARED:
        assert again[k] == first[k], k
    # the output of the fed-back file feeds back again: the same bits
    third = _json(cli_main, "invert", "--file", str(_fed_back(again, tmp_path / "third.toml")))
    assert {k: third[k] for k in COMPARED} == {k: again[k] for k in COMPARED}


def test_a_file_takes_a_correlation_table_and_the_option_replaces_its_pair(
    cli_main: CliMain, tmp_path: Path
) -> None:
    path = tmp_path / "m.toml"
    path.write_text(
        'angle = "20 deg"\nvi = "-1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\n'
        'ls = "1400 um"\nsamples = 500\n[sigma]\nvi = 0.01\ne = 0.02\nmu = 0.01\nls = 50\n'
        '[correlation]\n"e,mu" = -0.3\n"vi,ls" = 0.5\n'
    )
    from_file = _json(cli_main, "invert", "--file", str(path))
    from_options = _json(cli_main, *ARGS, "--correlation", "e,mu=-0.3",
                         "--correlation", "vi,ls=0.5")  # fmt: skip
    for k in COMPARED:
        assert from_file[k] == from_options[k], k
    # --correlation replaces the file's coefficient of its pair; the file's other pair stays
    mixed = _json(cli_main, "invert", "--file", str(path), "--correlation", "mu,e=0.2")
    expected = invert(**PY, correlation={("e", "mu"): 0.2, ("v_i", "sliding_length"): 0.5})
    assert mixed["duration"]["sigma"] == expected.sigma_T_linear
    assert mixed["mean_force"]["sigma"] == expected.sigma_F_linear


#: a faulty --correlation -> the command's one line
REFUSED = {
    "e,mu=1.3": "--correlation 'e,mu=1.3': the coefficient must be a number in [-1, 1], got '1.3'",
    "e,mu=nan": "--correlation 'e,mu=nan': the coefficient must be a number in [-1, 1], got 'nan'",
    "e,foo=0.3": "--correlation 'e,foo=0.3': unknown input 'foo'; allowed: angle, v_i, e, mu, "
    "delta_p, sliding_length, dv_cy, vt_in (or their option names: vi, ls, delta-p, ...)",
    "e,e=0.3": "--correlation 'e,e=0.3' pairs e with itself (its coefficient is always 1): give "
    "two different inputs",
    "e;mu=0.3": "--correlation must be NAME,NAME=COEFFICIENT (e.g. --correlation e,mu=-0.3), got "
    "'e;mu=0.3'",
    "e,dv_cy=0.3": "--correlation: 'dv_cy' in ('e', 'dv_cy') is not an input given to invert "
    "(allowed: angle, v_i, mu, delta_p, sliding_length, e)",
    "e,angle=0.3": "--correlation: 'angle' in ('angle', 'e') has no sigma (given exact): only "
    "inputs with an uncertainty can be correlated",
}


@pytest.mark.parametrize(("option", "message"), REFUSED.items())
def test_a_faulty_correlation_is_refused(cli_main: CliMain, option: str, message: str) -> None:
    assert _error(cli_main, *ARGS, "--correlation", option) == message


def test_a_pair_twice_and_a_matrix_that_is_none(cli_main: CliMain) -> None:
    assert _error(cli_main, *ARGS, "--correlation", "e,mu=0.3", "--correlation", "mu,e=0.2") == (
        "--correlation 'mu,e=0.2': the pair (mu, e) is given twice; give it once"
    )
    message = _error(cli_main, *ARGS, "--correlation", "e,mu=0.9", "--correlation", "mu,ls=0.9",
                     "--correlation", "e,ls=-0.9")  # fmt: skip
    assert message.startswith("--correlation: the coefficients ")
    assert "not positive semi-definite" in message


def test_a_faulty_correlation_in_a_file_is_named(cli_main: CliMain, tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    head = 'case = "paper-20"\nsamples = 500\n[sigma]\ne = 0.02\nmu = 0.01\n'
    path.write_text(head + '[correlation]\n"e,mu" = 2\n')
    assert _error(cli_main, "invert", "--file", str(path)) == (
        "correlation 'e,mu' in the measurement file: the coefficient must be a number in "
        "[-1, 1], got 2"
    )
    path.write_text(head + "[[correlation]]\ninputs = ['e', 'mu']\n"
                    "coefficient = { value = 0.3, unit = 'm' }\n")  # fmt: skip
    assert _error(cli_main, "invert", "--file", str(path)).startswith(
        "correlation[0] in the measurement file: the coefficient's table holds value and unit"
    )
    path.write_text(head + "[[correlation]]\ninputs = ['e', 'mu']\ncoefficient = 0.3\n"
                    "[[correlation]]\ninputs = ['mu', 'e']\ncoefficient = 0.2\n")  # fmt: skip
    assert _error(cli_main, "invert", "--file", str(path)) == (
        "correlation[1] in the measurement file: the pair (mu, e) is given twice; give it once"
    )
    path.write_text(head + "[[correlation]]\ninputs = ['e', 'dv_cy']\ncoefficient = 0.3\n")
    assert _error(cli_main, "invert", "--file", str(path)).startswith(
        "correlation in the measurement file: 'dv_cy' in ('e', 'dv_cy') is not an input"
    )
    path.write_text("correlation = 0.3\n" + head)
    assert _error(cli_main, "invert", "--file", str(path)).startswith(
        "correlation in the measurement file must be a table"
    )


def test_the_help_says_a_negative_vi_flips_a_correlation_with_it(cli_main: CliMain) -> None:
    """Formerly the help said only that v_i's sign is ignored, yet --correlation vi,e=0.9 with
    --vi -1.41 m/s gives other sigmas than with +1.41 m/s."""
    code, out, _ = cli_main("invert", "--help")
    assert code == 0
    text = " ".join(out.replace("│", " ").split())
    assert "a negative v_i flips its sign" in text
    neg = _json(cli_main, *ARGS, "--correlation", "vi,e=0.9")
    pos = _json(cli_main, *[("1.41 m/s" if a == "-1.41 m/s" else a) for a in ARGS],
                "--correlation", "vi,e=0.9")  # fmt: skip
    assert neg["mean_force"]["sigma"] != pos["mean_force"]["sigma"]
