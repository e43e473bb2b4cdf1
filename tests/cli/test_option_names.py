"""Options spelt alike across the commands, and errors that name the option as the user typed
it, in the product's words (``error: --steps must be >= 10, got 5``), once."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

DROPS = Path(__file__).resolve().parents[2] / "examples" / "data" / "drops.csv"
ROD = ("--angle", "20 deg", "--vy", "-1.41 m/s")


@pytest.mark.parametrize("flag", ["--radius", "--tip-radius"])
def test_invert_takes_the_tip_radius_as_the_other_commands(cli_main: Any, flag: str) -> None:
    code, out, err = cli_main("invert", "--case", "paper-20", flag, "5 mm", "--json")
    assert code == 0, err
    assert json.loads(out)["rod"]["tip_radius"] == {"value": 0.005, "unit": "m"}


@pytest.mark.parametrize(
    ("given", "nearest"),
    [
        ("cowper_symonds", "cowper-symonds"),
        ("Johnson_Cook", "johnson-cook"),
        ("cowper-symond", "cowper-symonds"),
        ("cowper_symonds(D=6500, q=4)", "cowper-symonds"),
    ],
)
def test_a_misspelt_rate_law_gets_the_nearest(cli_main: Any, given: str, nearest: str) -> None:
    code, out, err = cli_main("drop", *ROD, "--rate", given)
    assert code == 2 and out == ""
    assert err.startswith("error: --rate must be one of none, cowper-symonds, johnson-cook")
    assert err.endswith(f"got {given!r} (did you mean {nearest!r}?)\n")


def test_an_unlike_rate_gets_no_guess(cli_main: Any) -> None:
    code, _, err = cli_main("drop", *ROD, "--rate", "xyz")
    assert code == 2 and "did you mean" not in err


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (("--steps", "5"), "--steps must be >= 10, got 5"),
        (("--walkers", "2"), "--walkers must be >= 4 (4 and 2 x parameters), got 2"),
        (("--steps", "20", "--burn", "30"), "--burn must lie in [0, 20), got 30"),
    ],
)
def test_calibrate_names_the_sampler_option(
    cli_main: Any, args: tuple[str, ...], said: str
) -> None:
    code, out, err = cli_main("calibrate", str(DROPS), "-p", "mu=uniform(0, 0.6)", *args, "-q")
    assert (code, out, err) == (2, "", f"error: {said}\n")


def test_calibrate_names_the_config_files_setting(cli_main: Any, tmp_path: Path) -> None:
    config = tmp_path / "cal.toml"
    config.write_text("[sampler]\nsteps = 5\n")
    code, _, err = cli_main("calibrate", str(DROPS), "-p", "mu=uniform(0, 0.6)", "--config",
                            str(config), "--quiet")  # fmt: skip
    assert (code, err) == (2, f"error: {config}: [sampler] steps must be >= 10, got 5\n")


def test_calibrate_takes_q_for_quiet() -> None:
    from typer.testing import CliRunner

    from impactlab.cli import app

    r = CliRunner().invoke(app, ["calibrate", "--help"], terminal_width=100)
    assert r.exit_code == 0
    assert "-q, --quiet" in r.output


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (("simulate", "rod", *ROD, "--mu", "abc"), "--mu must be a number, got 'abc'"),
        (("simulate", "rod", *ROD, "--rtol", "tight"), "--rtol must be a number, got 'tight'"),
        (("drop", *ROD, "--mu", "abc"), "--mu must be a number, got 'abc'"),
        (("drop", *ROD, "--damping", "x"), "--damping must be a number, got 'x'"),
        (("invert", "--case", "paper-20", "--mu", "abc"), "--mu must be a number, got 'abc'"),
        (("fe", "indent", "--max", "1 um", "--mu", "abc"), "--mu must be a number, got 'abc'"),
        (("fe", "indent", "--max", "1 um", "--workers", "0"),
         "--workers must be a positive integer, got 0"),
        (("warm", "--jobs", "0"), "--jobs must be a positive integer, got 0"),
    ],
)  # fmt: skip
def test_errors_name_the_option_in_the_products_words(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, args: tuple[str, ...], said: str
) -> None:
    from impactlab import fe

    monkeypatch.setattr(fe, "indent", lambda *a, **k: pytest.fail("ccx would have run"))
    code, out, err = cli_main(*args)
    assert (code, out, err) == (2, "", f"error: {said}\n")


def test_a_config_files_value_is_labelled_once(cli_main: Any, tmp_path: Path) -> None:
    config = tmp_path / "c.toml"
    config.write_text('angle = "20 deg"\nvy = -1.41\nmass = 1e400\n')
    code, _, err = cli_main("simulate", "rod", "--config", str(config))
    assert (code, err) == (2, f"error: mass (in {config}) must be finite, got inf\n")
    code, _, err = cli_main("simulate", "rod", *ROD, "--mass", "1e400")
    assert (code, err) == (2, "error: --mass must be finite, got '1e400'\n")


def test_as_option_labels_a_bare_key_only() -> None:
    from impactlab.cli._common import as_option

    def label(key: str) -> str:
        return f"{key} (in c.toml)"

    assert as_option("mass must be > 0", ["mass"], label) == "mass (in c.toml) must be > 0"
    once = "mass (in c.toml) must be finite, got inf"
    assert as_option(once, ["mass"], label) == once
