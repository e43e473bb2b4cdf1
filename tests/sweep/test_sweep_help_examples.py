"""Each of ``impactlab sweep``, ``sweep run``, ``info``, ``plot`` and ``export`` shows an
example in its ``--help``, and the examples, run in order in a copy of the repository's
``examples/`` folder, work (the engine runs the example study: about 5000 cases)."""

from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path

from sweep_fakes import run_cli
from typer.testing import CliRunner

from impactlab.cli import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
COMMANDS = [(), ("info",), ("plot",), ("export",)]


def _example(*command: str) -> str:
    r = CliRunner().invoke(app, ["sweep", *command, "--help"], terminal_width=200)
    assert r.exit_code == 0, r.output
    found = re.findall(r"Example: (impactlab sweep [^\n│]+)", r.output)
    assert len(found) == 1, r.output
    return found[0].strip()


def test_every_sweep_help_has_an_example_that_runs(tmp_path, monkeypatch, capsys) -> None:
    shutil.copytree(EXAMPLES, tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    for command in COMMANDS:
        words = shlex.split(_example(*command))
        assert words[:2] == ["impactlab", "sweep"]
        quiet = ["-q"] if not command else []
        code, _out, err = run_cli(monkeypatch, capsys, *words[1:], *quiet)
        assert code == 0, (words, err)
    assert (tmp_path / "map.csv").is_file() and any((tmp_path / "plots").glob("*.png"))
