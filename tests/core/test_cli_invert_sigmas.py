"""``impactlab invert``: the unit of a bare ``--sigma-*`` number, and of a bare number in a
measurement file's ``[sigma]`` table, as the help says."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

BASE = ("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
        "--samples", "200", "--json")  # fmt: skip


def _sigma(cli_main: CliMain, *args: str, key: str = "sliding_length") -> float:
    code, out, err = cli_main(*BASE, *args)
    assert code == 0, err
    return float(json.loads(out)["inputs"][key]["sigma"])


@pytest.mark.parametrize(
    ("ls", "sigma", "expected"),
    [
        ("1400 um", "50", 50e-6),  # a bare sigma is in the value's unit (was read as 50 m)
        ("1400 um", "50 um", 50e-6),
        ("1.4 mm", "0.05", 50e-6),
        ("1.4mm", "0.05", 50e-6),
        ("0.0014", "5e-5", 50e-6),  # both bare: SI
        ("0.0014", "50 um", 50e-6),
    ],
)
def test_a_bare_sigma_takes_the_unit_of_its_value(
    cli_main: CliMain, ls: str, sigma: str, expected: float
) -> None:
    got = _sigma(cli_main, "--delta-p", "22 um", "--ls", ls, "--sigma-ls", sigma)
    assert got == pytest.approx(expected, rel=1e-9)


def test_the_other_dimensional_sigmas_too(cli_main: CliMain) -> None:
    args = ("--delta-p", "22 um", "--ls", "1400 um", "--sigma-delta-p", "0.5")
    assert _sigma(cli_main, *args, key="delta_p") == pytest.approx(0.5e-6)
    assert _sigma(cli_main, "--delta-p", "22 um", "--ls", "1400 um", "--sigma-vi", "0.01",
                  key="v_i") == pytest.approx(0.01)  # fmt: skip


def test_a_bare_sigma_of_a_value_from_a_case_is_refused(cli_main: CliMain) -> None:
    code, out, err = cli_main("invert", "--case", "paper-20", "--sigma-ls", "50")
    assert code == 2 and not out
    assert err.strip() == (
        "error: --sigma-ls 50 has no unit and --ls comes from --case or --file: give its unit, "
        "e.g. --sigma-ls '50 um'"
    )
    code, _, err = cli_main("invert", "--case", "paper-20", "--sigma-ls", "50 um", "--json")
    assert code == 0, err


def test_the_help_says_how_a_bare_sigma_is_read(cli_main: CliMain) -> None:
    code, out, _ = cli_main("invert", "--help")
    text = " ".join(out.replace("│", " ").split())
    assert code == 0
    assert "A bare number is in the unit of --ls as given on the command line" in text
    assert "with --ls from --case or --file it needs its unit" in text
    assert "same unit" not in text


# -- a measurement file (--file): its [sigma] table reads as the command line does --------------

FILE = 'angle = "20 deg"\nvi = "-1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\nsamples = 200\n'


def _file_sigma(
    cli_main: CliMain, tmp_path: Path, text: str, key: str = "sliding_length"
) -> tuple[int, float | str]:
    path = tmp_path / "inv.toml"
    path.write_text(text)
    code, out, err = cli_main("invert", "--file", str(path), "--json")
    return code, (float(json.loads(out)["inputs"][key]["sigma"]) if code == 0 else err)


@pytest.mark.parametrize(
    ("ls", "sigma", "expected"),
    [
        ('"1400 um"', "50", 50e-6),  # a bare sigma is in the value's unit (was read as 50 m)
        ('"1400 um"', '"50"', 50e-6),
        ('"1400 um"', '"50 um"', 50e-6),
        ('"1.4 mm"', "0.05", 50e-6),
        ("0.0014", "5e-5", 50e-6),  # both bare: SI
        ("0.0014", '"50 um"', 50e-6),
    ],
)
def test_a_bare_sigma_in_the_file_takes_the_unit_of_its_value(
    cli_main: CliMain, tmp_path: Path, ls: str, sigma: str, expected: float
) -> None:
    code, got = _file_sigma(cli_main, tmp_path, f"{FILE}ls = {ls}\n[sigma]\nls = {sigma}\n")
    assert code == 0, got
    assert got == pytest.approx(expected, rel=1e-9)


def test_the_files_other_sigmas_too(cli_main: CliMain, tmp_path: Path) -> None:
    text = f'{FILE}ls = "1400 um"\n[sigma]\ndelta_p = 0.5\nvi = 0.01\nmu = 0.02\n'
    assert _file_sigma(cli_main, tmp_path, text, "delta_p")[1] == pytest.approx(0.5e-6)
    assert _file_sigma(cli_main, tmp_path, text, "v_i")[1] == pytest.approx(0.01)
    assert _file_sigma(cli_main, tmp_path, text, "mu")[1] == pytest.approx(0.02)


def test_a_bare_sigma_in_the_file_without_its_value_is_refused(
    cli_main: CliMain, tmp_path: Path
) -> None:
    path = tmp_path / "inv.toml"
    path.write_text('case = "paper-20"\nsamples = 200\n[sigma]\nls = 50\n')
    code, out, err = cli_main("invert", "--file", str(path))
    assert code == 2 and not out
    assert err.strip() == (
        "error: sigma.ls = 50 in the measurement file has no unit and the file gives no 'ls' or "
        "'L_s' to take it from: give its unit, e.g. ls = '50 um' in [sigma]"
    )
    path.write_text('case = "paper-20"\nsamples = 200\n[sigma]\nls = "50 um"\n')
    assert cli_main("invert", "--file", str(path), "--json")[0] == 0


def test_the_help_says_how_a_bare_sigma_in_the_file_is_read(cli_main: CliMain) -> None:
    code, out, _ = cli_main("invert", "--help")
    text = " ".join(out.replace("│", " ").split())
    assert code == 0
    assert "A bare number in [sigma] is in the unit of its value in the file" in text
