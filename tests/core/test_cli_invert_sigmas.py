"""``impactlab invert``: the unit of a bare ``--sigma-*`` number, as its help says."""

from __future__ import annotations

import json
from collections.abc import Callable

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
