"""Minus signs other than '-' (U+2212 and the dashes pint drops without a word) reach every text
input as the negative number: command-line options, a ``--config`` file, a study file and a
measurements file. Before, ``--vx "\u22120.3 m/s"`` simulated +0.3 m/s."""

from __future__ import annotations

import json

import pytest

from impactlab.calibrate import read_measurements
from impactlab.sweep import load_study

MINUS = "\u2212"
ROD = ("simulate", "rod", "--angle", "20 deg", "--json")


def _input(cli_main, *args: str) -> dict:
    code, out, err = cli_main(*args)
    assert code == 0, err
    return json.loads(out)["input"]


def test_options_read_a_unicode_minus_as_negative(cli_main):
    given = _input(
        cli_main,
        *ROD,
        "--vy",
        f"{MINUS}1.41 m/s",
        "--vx",
        f"{MINUS}0.3 m/s",
        "--spin",
        f"{MINUS}5 rad/s",
    )
    assert given["velocity"]["value"] == [-0.3, -1.41]
    assert given["spin"]["value"] == -5.0


def test_a_config_file_reads_a_unicode_minus_as_negative(cli_main, tmp_path):
    config = tmp_path / "c.toml"
    config.write_text(
        f'vy = "{MINUS}1.41 m/s"\nvx = "\u20130.3 m/s"\nspin = "{MINUS}5 rad/s"\n', encoding="utf-8"
    )
    given = _input(cli_main, *ROD, "--config", str(config))
    assert given["velocity"]["value"] == [-0.3, -1.41]
    assert given["spin"]["value"] == -5.0


def test_an_option_with_a_stray_dash_is_one_line_naming_it(cli_main):
    code, out, err = cli_main(*ROD, "--vy", "-1.41 m/s", "--vx", "0.3 \u2013 m/s")
    assert code == 2 and out == ""
    assert err.startswith("error: --vx: '0.3 \u2013 m/s' holds a dash (U+2013) that is not a ")
    assert len(err.splitlines()) == 1


def test_arithmetic_in_an_option_is_refused(cli_main):
    code, _, err = cli_main(*ROD, "--vy", "2*-1.41 m/s")
    assert code == 2
    assert err.startswith("error: --vy: '2*-1.41 m/s' holds more than one number")


def test_a_study_file_reads_a_unicode_minus_as_negative(tmp_path):
    study = tmp_path / "s.toml"
    study.write_text(
        f'[fixed]\nvy = "{MINUS}1.41 m/s"\nmu = 0.2\nangle = "20 deg"\n'
        f'[grid]\nvx = ["{MINUS}0.3 m/s", "0.25 m/s"]\n',
        encoding="utf-8",
    )
    s = load_study(study)
    assert s.fixed["vy"] == -1.41
    assert s.grid[0].values == (-0.3, 0.25)


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("a.csv", f"label,angle [deg],vy [m/s],mu,e,e_sigma\na,20,{MINUS}1.41,0.2,0.45,0.02\n"),
        ("b.csv", f"label,angle,vy,mu,e,e_sigma\na,20 deg,{MINUS}1.41 m/s,0.2,0.45,0.02\n"),
        (
            "c.toml",
            f'[[drop]]\nangle = "20 deg"\nvy = "{MINUS}1.41 m/s"\nmu = 0.2\ne = 0.45\n'
            "e_sigma = 0.02\n",
        ),
    ],
)
def test_a_measurements_file_reads_a_unicode_minus_as_negative(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    assert list(read_measurements(path).inputs["vy"]) == [-1.41]
