"""``impactlab laws``: table, JSON, one law, one-line errors."""

from __future__ import annotations

import json

import pytest
import typer
from typer.testing import CliRunner

from impactlab.cli import laws as laws_cli
from impactlab.contact import law_names


@pytest.fixture(scope="module")
def app() -> typer.Typer:
    a = typer.Typer()
    laws_cli.register(a)

    @a.command("noop")
    def noop() -> None:  # a second command so that "laws" stays a sub-command
        pass

    return a


def test_list_json(app: typer.Typer) -> None:
    res = CliRunner().invoke(app, ["laws", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert list(data) == [*law_names(), "impactlab_version"]
    brake = data["brake"]
    assert brake["doi"] == "10.1016/j.ijsolstr.2015.02.019"
    assert {p["name"] for p in brake["parameters"]} == {"hardness", "meyer_index"}


def test_table_lists_every_law(app: typer.Typer) -> None:
    res = CliRunner().invoke(app, ["laws"], env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    for name in law_names():
        assert name in res.stdout


def test_one_law_with_numbers(app: typer.Typer) -> None:
    res = CliRunner().invoke(app, ["laws", "thornton", "--radius", "8.8 mm", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert data["example"]["radius"] == {"value": pytest.approx(8.8e-3), "unit": "m"}
    assert data["example"]["delta_y"]["value"] == pytest.approx(0.4362e-6, rel=1e-3)
    res = CliRunner().invoke(app, ["laws", "ghaednia"], env={"COLUMNS": "200"})
    assert res.exit_code == 0 and "published_switch" in res.stdout


@pytest.mark.parametrize(
    ("args", "text"),
    [(["laws", "nope"], "known laws: hertz"), (["laws", "brake", "--radius", "abc"], "radius")],
)
def test_errors_are_one_line(app: typer.Typer, args: list[str], text: str) -> None:
    res = CliRunner().invoke(app, args)
    assert res.exit_code == 2
    err = res.stderr.strip()
    assert err.startswith("error:") and text in err and "\n" not in err
