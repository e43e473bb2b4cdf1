"""A pure number written in percent ("20 %"), read as the fraction a percent Quantity is."""

from __future__ import annotations

import pytest

import impactlab as il
from impactlab._validation import check_array, check_finite


@pytest.mark.parametrize("text", ["20 %", "20%", "20 percent"])
def test_a_percent_string_is_its_fraction(text) -> None:
    assert check_finite("mu", text) == pytest.approx(0.2)
    assert check_array("mu", [text, 0.3]).tolist() == pytest.approx([0.2, 0.3])


@pytest.mark.parametrize("text", ["20 deg", "0.2", "x %"])
def test_other_strings_stay_refused(text) -> None:
    """An angle unit is dimensionless in pint: mu = '20 deg' must not read as 0.35."""
    with pytest.raises(ValueError, match="mu must be a real number, got the string"):
        check_finite("mu", text)


def test_simulate_takes_mu_in_percent() -> None:
    r = il.simulate(il.PAPER_ROD, angle=0.35, velocity=(0, -1.41), mu="20 %", history=False)
    assert r.e == il.simulate(il.PAPER_ROD, angle=0.35, velocity=(0, -1.41), mu=0.2).e


def test_the_command_line_takes_mu_in_percent() -> None:
    from typer.testing import CliRunner

    from impactlab.cli import app

    args = ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--json"]
    percent = CliRunner().invoke(app, [*args, "--mu", "20 %"])
    plain = CliRunner().invoke(app, [*args, "--mu", "0.2"])
    assert percent.exit_code == 0, percent.output
    assert percent.stdout == plain.stdout
    bad = CliRunner().invoke(app, [*args, "--mu", "x %"])
    assert "--mu must be a number, got 'x %'" in bad.output + str(bad.exception)
