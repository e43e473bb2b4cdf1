"""``impactlab laws --accuracy`` reads in an 80-column pipe: one block per law, no line wider
than the terminal, every number whole (each cell ``ratio: force % / delta_r`` on one line); a
wide terminal keeps the table."""

from __future__ import annotations

import re

from typer.testing import CliRunner

from impactlab.cli import app
from impactlab.cli.laws_accuracy import law_blocks, table_width, wrapped

#: A cell of the accuracy table: the force error in % and the delta_r/delta_max error.
CELL = re.compile(r"^[+-]\d+ % / [+-]\d\.\d{3}$")


def test_accuracy_at_80_columns_keeps_numbers_whole() -> None:
    res = CliRunner().invoke(app, ["laws", "--accuracy"], env={"COLUMNS": "80"})
    assert res.exit_code == 0, res.output
    lines = res.stdout.splitlines()
    assert max(len(ln) for ln in lines) <= 80
    assert "│" not in res.stdout and "┃" not in res.stdout  # no folded table
    items = re.findall(r"(?:^| )(\d+(?:\.\d+)?): ([+-]\d+ % / [+-]\d\.\d{3})", res.stdout, re.M)
    assert len(items) > 100 and all(CELL.match(cell) for _, cell in items)
    assert re.search(r"^hertz: <= [\d.]+ delta_c", res.stdout, re.M)
    assert "%" not in [ln.strip() for ln in lines]
    assert not re.search(r"\d\n%", res.stdout)  # never "2" and "%" on two lines


def test_accuracy_wide_terminal_keeps_the_table() -> None:
    res = CliRunner().invoke(app, ["laws", "--accuracy"], env={"COLUMNS": "250"})
    assert res.exit_code == 0 and "┃ law" in res.stdout
    assert re.search(r"│ hertz +│ [+-]\d+ % / [+-]\d\.\d{3} +│", res.stdout)


def test_blocks_fit_the_width_and_wrap_keeps_percent_with_its_number() -> None:
    header = ["law", "0.3", "1000", "verified range"]
    rows = [["hertz", "-0 % / +0.000", "+395 % / -0.881", "<= 1.5 delta_c"]]
    assert table_width(header, rows) == 5 + 13 + 15 + 14 + 3 * 4 + 1
    lines = law_blocks(header, rows, 30)
    assert lines == ["hertz: <= 1.5 delta_c", "  0.3: -0 % / +0.000", "  1000: +395 % / -0.881"]
    assert wrapped("in force alone (RMS 2 %), in", 18).splitlines() == [
        "in force alone",
        "(RMS 2 %), in",
    ]
