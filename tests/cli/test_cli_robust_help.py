"""``impactlab drop --help`` states each default once, in the option's own words (typer's
``[default: ...]`` would say it a second time)."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def drop_help() -> str:
    from typer.testing import CliRunner

    from impactlab.cli import app

    r = CliRunner().invoke(app, ["drop", "--help"], terminal_width=100)
    assert r.exit_code == 0, r.output
    return " ".join(r.output.split())


def test_no_default_is_stated_twice(drop_help):
    assert "[default:" not in drop_help


@pytest.mark.parametrize(
    "said",
    [
        "Friction coefficient, >= 0 (default 0).",
        "impulse_ratio, coulomb (default), mindlin or partial_slip.",
        "Contact law (default ghaednia).",
        "its strain rate (default none)",
        "(bare number: kg; default the paper's 0.4607 kg)",
    ],
)
def test_each_default_is_said_in_the_options_words(drop_help, said):
    assert drop_help.count(said) == 1
