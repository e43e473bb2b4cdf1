"""The command's console follows COLUMNS at the time of each command, whatever COLUMNS was when
the command line module was first imported (rich reads it when a Console is created)."""

from __future__ import annotations

from typer.testing import CliRunner


def test_console_width_is_read_when_used(monkeypatch) -> None:
    import impactlab.cli._common as common

    monkeypatch.setenv("COLUMNS", "200")
    assert common.console.width == 200
    monkeypatch.setenv("COLUMNS", "90")
    assert common.console.width == 90


def test_laws_table_after_a_narrow_command() -> None:
    from impactlab.cli import app

    narrow = CliRunner().invoke(app, ["laws"], env={"COLUMNS": "80"})
    wide = CliRunner().invoke(app, ["laws"], env={"COLUMNS": "200"})
    assert "┃ name" not in narrow.stdout and "┃ name" in wide.stdout
