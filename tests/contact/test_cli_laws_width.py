"""``impactlab laws`` reads in an 80-column terminal: one block per law, no line wider than the
terminal, every law, reference and DOI whole; a wide terminal keeps the table."""

from __future__ import annotations

import re

from typer.testing import CliRunner

from impactlab.cli import app
from impactlab.contact import get_law, law_names


def test_laws_at_80_columns() -> None:
    res = CliRunner().invoke(app, ["laws"], env={"COLUMNS": "80"})
    assert res.exit_code == 0, res.output
    lines = res.stdout.splitlines()
    assert max(len(ln) for ln in lines) <= 80
    text = " ".join(res.stdout.split())
    for n in law_names():
        assert re.search(rf"^{re.escape(n)}: ", res.stdout, flags=re.M), n
        assert f"doi:{get_law(n).doi}" in text  # never folded inside a DOI
    assert "│" not in res.stdout  # no table cells folded to a dozen characters


def test_laws_wide_terminal_keeps_the_table() -> None:
    res = CliRunner().invoke(app, ["laws"], env={"COLUMNS": "200"})
    assert res.exit_code == 0 and "┃ name" in res.stdout
