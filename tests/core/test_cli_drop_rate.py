"""``impactlab drop --rate``: a rate law with the flat's own constants on the command line (the
form a result prints reads back), the command line's hint when a built-in law does not fit the
flat, the laws' constants in ``--help``, and the errors of ``--damping`` named as typed."""

from __future__ import annotations

import json
import math

import pytest

from impactlab.bodies import FlexibleRod
from impactlab.cli._common import UserError, rate_name
from impactlab.contact.rate import RATE_LAWS, RateLaw
from impactlab.dynamics.drop import simulate_drop
from impactlab.materials import get_material

ALU_20 = ("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2", "--flat", "al-6061-t6")
OWN = "cowper-symonds(D=6500 1/s, q=4)"


def _json(cli_main, *args: str) -> dict:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    return json.loads(out)


def test_own_constants_run_the_law_of_the_api(cli_main) -> None:
    """--rate "cowper-symonds(D=6500 1/s, q=4)" is RateLaw.custom("cowper-symonds", D=6500,
    q=4): the same drop, bit for bit, and its record keeps the constants."""
    data = _json(cli_main, *ALU_20, "--rate", OWN)
    law = RateLaw.custom("cowper-symonds", D=6500.0, q=4.0)
    ref = simulate_drop(
        FlexibleRod.paper(),
        get_material("al-6061-t6"),
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
        rate=law,
        history=False,
    )
    assert data["rate"] == law.label == "cowper-symonds (D = 6500 1/s, q = 4)"
    assert data["e"]["value"] == ref.e and data["dent_depth"]["value"] == ref.dent_depth
    assert data["rate_factor"]["value"] == ref.rate_factor > 1.0
    assert data["input"]["rate"]["parameters"]["D"] == {"value": 6500.0, "unit": "1/s"}


def test_the_printed_form_reads_back(cli_main, tmp_path) -> None:
    """The rate a result prints, given to --rate (and on top of --from), runs the same law."""
    first = _json(cli_main, *ALU_20, "--rate", "johnson-cook(C=0.03, rate0=1 1/s)")
    assert first["rate"] == "johnson-cook (C = 0.03, rate0 = 1 1/s)"
    again = _json(cli_main, *ALU_20, "--rate", first["rate"])
    assert again["e"] == first["e"] and again["rate_factor"] == first["rate_factor"]
    record = tmp_path / "drop.json"
    record.write_text(json.dumps(first))
    other = _json(cli_main, "drop", "--from", str(record), "--rate", OWN)
    assert other["rate"] == "cowper-symonds (D = 6500 1/s, q = 4)"
    assert other["rate_factor"] != first["rate_factor"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("none", None),
        (" Cowper-Symonds ", "cowper-symonds"),
        ("cowper-symonds (D = 6500 1/s, q = 4)", {"D": 6500.0, "q": 4.0}),
        ("cowper-symonds(d=6.5 kHz, Q=4)", {"D": 6500.0, "q": 4.0}),
        ("cowper-symonds(q=4, D=6500)", {"D": 6500.0, "q": 4.0}),
        ("johnson-cook(C=0.03, rate0=2 1/s)", {"C": 0.03, "rate0": 2.0}),
        ("johnson-cook(C=0.03, rate0=2e-3 /ms)", {"C": 0.03, "rate0": 2.0}),
    ],
)
def test_rate_forms(text, expected) -> None:
    law = rate_name(text)
    if not isinstance(expected, dict):
        assert law == expected
        return
    assert isinstance(law, RateLaw) and law.fitted_for is None
    assert dict(law.parameters) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("rate", "needle"),
    [
        ("fast", "--rate must be one of none, cowper-symonds, johnson-cook, or a law with its"),
        ("none(D=1)", "--rate must be one of"),
        ("cowper-symonds(D=6500 1/s)", "cowper-symonds takes D [1/s], q [1], missing q"),
        ("cowper-symonds(D=1, q=4, C=1)", "takes D [1/s], q [1], got 'C=1'"),
        ("cowper-symonds(D=1, D=2, q=4)", "got 'D=2' twice"),
        ("cowper-symonds(D 1, q=4)", "got 'D 1'"),
        ("cowper-symonds(D=-1, q=4)", "--rate D must be > 0 1/s, got -1.0 1/s"),
        ("cowper-symonds(D=6500 m, q=4)", "--rate D: '6500 m' has the wrong dimension"),
        ("johnson-cook(C=-0.1, rate0=1)", "--rate C must be >= 0, got -0.1"),
    ],
)
def test_bad_rates_are_one_line_naming_the_option(cli_main, rate, needle) -> None:
    code, _out, err = cli_main(*ALU_20, "--rate", rate)
    assert code == 2 and needle in err, err
    assert err.startswith("error: --rate") and len(err.strip().splitlines()) == 1
    with pytest.raises(UserError):
        rate_name(rate)


def test_a_law_fitted_for_another_flat_says_the_command_line_way(cli_main, tmp_path) -> None:
    code, _out, err = cli_main(*ALU_20, "--rate", "cowper-symonds")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith("error: --rate cowper-symonds: its constants are fitted for")
    assert '--rate "cowper-symonds(D=... 1/s, q=...)"' in err and "RateLaw" not in err
    steel = _json(
        cli_main, "drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--rate", "johnson-cook"
    )
    record = tmp_path / "steel.json"
    record.write_text(json.dumps(steel))
    code, _out, err = cli_main("drop", "--from", str(record), "--flat", "al-6061-t6")
    assert code == 2 and err.startswith("error: the recorded rate johnson-cook: its constants")
    assert '--rate "johnson-cook(C=..., rate0=... 1/s)"' in err and "RateLaw" not in err
    assert 'e.g. "johnson-cook(C=0.03, rate0=1 1/s)"' in err and "cowper" not in err
    alu = tmp_path / "alu.json"
    alu.write_text(json.dumps(_json(cli_main, *ALU_20, "--rate", OWN)))
    code, _out, err = cli_main("drop", "--from", str(alu), "--rate", "cowper-symonds")
    assert code == 2 and err.startswith("error: --rate cowper-symonds: its constants are fitted")


def test_simulate_flexible_says_the_command_line_way_too(cli_main) -> None:
    """``simulate rod --flexible`` reads --rate as ``drop`` does: the same refusal, in the
    command line's words, and a law of one's own constants runs."""
    args = ("simulate", "rod", "--flexible", *ALU_20[1:])
    code, _out, err = cli_main(*args, "--rate", "cowper-symonds")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert '--rate "cowper-symonds(D=... 1/s, q=...)"' in err and "RateLaw" not in err
    assert _json(cli_main, *args, "--rate", OWN)["ok"] is not None
    code, out, _err = cli_main("simulate", "rod", "--help")
    assert code == 0 and "cowper-symonds(D=... 1/s, q=...)" in " ".join(out.split())


def test_help_lists_each_law_with_its_constants_and_sources(cli_main) -> None:
    code, out, _err = cli_main("drop", "--help")
    assert code == 0
    flat = " ".join(out.split())
    for name, law in RATE_LAWS.items():
        assert name in flat
        for key, value in law.parameters:
            unit = " 1/s" if key in ("D", "rate0") else ""
            assert f"{key} = {value:g}{unit}" in flat, (name, key)
    for source in ("Cowper & Symonds 1957", "Jones, Structural Impact 1989", "Johnson & Cook 1983"):
        assert source in flat
    assert '"cowper-symonds(D=... 1/s, q=...)"' in flat and OWN in flat


@pytest.mark.parametrize(
    ("value", "needle"),
    [
        ("1", "--damping must lie in [0.0, 1.0), got 1.0"),
        ("-0.1", "--damping must lie in [0.0, 1.0), got -0.1"),
        ("nan", "--damping must be finite, got nan"),
    ],
)
def test_damping_errors_name_the_option(cli_main, value, needle) -> None:
    code, _out, err = cli_main("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--damping", value)
    assert code == 2 and err.strip() == f"error: {needle}"


def test_a_rate_with_the_elastic_law_says_the_command_line_way(cli_main) -> None:
    args = ("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--law", "hertz")
    code, _out, err = cli_main(*args, "--rate", "johnson-cook")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith("error: --rate johnson-cook: --law hertz is elastic")
    assert "leave out --rate" in err and "rate=None" not in err


ELASTIC = "is elastic (no yield strength for the rate to raise); "


def test_the_elastic_law_refusal_speaks_the_command_line_everywhere(cli_main, tmp_path) -> None:
    """simulate --flexible and --from refuse a rate with the elastic law as plain drop does,
    naming what the user gave (or the record) and never the Python keyword."""
    kinematics = ("--angle", "20 deg", "--vy", "-1.41 m/s")
    code, _out, err = cli_main(
        "simulate", "rod", "--flexible", *kinematics, "--law", "hertz", "--rate", "cowper-symonds"
    )
    assert code == 2 and err.strip() == (
        f"error: --rate cowper-symonds: --law hertz {ELASTIC}leave out --rate, or give an "
        "elastic-plastic --law"
    )
    own = tmp_path / "own.json"
    jc = _json(cli_main, "drop", *kinematics, "--rate", "johnson-cook(C=0.03, rate0=1 1/s)")
    own.write_text(json.dumps(jc))
    for command in ("drop", "simulate"):
        code, _out, err = cli_main(command, "--from", str(own), "--law", "hertz")
        assert code == 2 and err.strip() == (
            f"error: the recorded rate johnson-cook (C = 0.03, rate0 = 1 1/s): --law hertz "
            f"{ELASTIC}add --rate none, or give an elastic-plastic --law"
        )
    assert _json(cli_main, "drop", "--from", str(own), "--law", "hertz", "--rate", "none")["ok"]
    hertz = tmp_path / "hertz.json"
    hertz.write_text(json.dumps(_json(cli_main, "drop", *kinematics, "--law", "hertz")))
    code, _out, err = cli_main("drop", "--from", str(hertz), "--rate", "johnson-cook")
    assert code == 2 and err.strip() == (
        f"error: --rate johnson-cook: the recorded law hertz {ELASTIC}leave out --rate, or give "
        "an elastic-plastic --law"
    )
