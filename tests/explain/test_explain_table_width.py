"""``impactlab explain``'s table on terminals of common widths: whole where it fits, else
turned per drop with the measured values beside each part; no word or number broken."""

from __future__ import annotations

import io

import pytest
from rich.cells import cell_len
from rich.console import Console

from impactlab.cli.explain import _show


@pytest.mark.parametrize("width", [80, 100, 120, 250])
def test_every_prediction_whole_beside_the_measured_values(paper_explained, width) -> None:
    buf = io.StringIO()
    _show(paper_explained, Console(file=buf, width=width, force_terminal=True, color_system=None))
    text = buf.getvalue()
    assert all(cell_len(line) <= width for line in text.splitlines())
    head, rows = paper_explained.display_rows()
    words = set(text.replace("│", " ").replace("┃", " ").split())
    for cell in (*head[1:], *(c for r in rows for c in r)):
        assert all(w in words for w in cell.split()), (cell, text)
    lines = [line.strip() for line in text.splitlines()]
    drops = [r[0] for r in rows if r[0]]
    if width == 250:  # the whole table: each drop once, in its column
        assert not any(line in drops for line in lines)
        return
    for drop in drops:
        parts = lines.count(drop)  # each part of a drop under its name
        measured = next(r for r in rows if r[0] == drop)[2]  # the measured e, +- sigma
        assert parts >= 1
        assert text.count(measured) >= parts  # beside every part of its drop
