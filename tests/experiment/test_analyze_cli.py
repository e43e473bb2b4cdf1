"""``impactlab analyze``: its JSON has the documented shape and its table the display units
of every other command."""

from __future__ import annotations

import json
from typing import Any

from typer.testing import CliRunner

from impactlab._json import shape_problems
from impactlab.cli import app


def test_analyze_json_shape_and_table(flat_json: tuple[list[str], Any]) -> None:
    args, res = flat_json  # conftest.py: the run with --flat aisi-1010 --json
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert shape_problems(data) == []  # docs/json-schema.md
    assert data["summary"]["delta_p"]["unit"] == "m" and data["summary"]["delta_p"]["sigma"] > 0
    assert "sigma" not in data["summary"]["pileup"]  # no uncertainty: no sigma
    assert data["inversion"]["duration"]["unit"] == "s"
    assert data["model"]["delta_p"]["unit"] == "m"
    table = CliRunner().invoke(app, args, env={"COLUMNS": "200"}).stdout
    rows = {
        c[0]: c[1:]
        for c in ([x.strip() for x in ln.split("│")[1:-1]] for ln in table.splitlines())
        if len(c) == 3
    }
    assert rows["delta_p"][1] == "um" and rows["duration"][1] == "ms" and rows["angle"][1] == "deg"
    assert "± 0 " not in table and "e-0" not in table
