"""A drop's contact table and its legend (``impactlab drop``, ``simulate rod --flexible``) at
any terminal width: plain lines where they fit, else turned with every number whole, the
legend filled to the terminal; into a pipe or a file plain lines and a 100-column legend."""

from __future__ import annotations

import io
import math
import textwrap

import pytest
from rich.cells import cell_len
from rich.console import Console

from impactlab import FlexibleRod, simulate_drop
from impactlab.cli.drop_contacts import LEGEND, LEGEND_WIDTH, _contact_rows, print_contacts


@pytest.fixture(scope="module")
def drop():
    return simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0, -1.41))


def _print(drop, width: int, terminal: bool = True) -> str:
    buf = io.StringIO()
    print_contacts(drop, Console(file=buf, width=width, force_terminal=terminal,
                                 color_system=None, soft_wrap=not terminal))  # fmt: skip
    return buf.getvalue()


def test_a_pipe_gets_one_line_a_contact_and_the_100_column_legend(drop) -> None:
    text = _print(drop, 80, terminal=False)
    lines = text.splitlines()
    assert lines[0] == "contacts"
    assert lines[1].split()[:3] == ["#", "end", "start"]
    assert [ln.split()[0] for ln in lines[2 : 2 + drop.n_contacts]] == [
        str(k) for k in range(1, drop.n_contacts + 1)
    ]
    assert text.endswith(textwrap.fill(LEGEND, width=LEGEND_WIDTH) + "\n")


def test_a_wide_terminal_gets_the_same_plain_lines(drop) -> None:
    assert _print(drop, 200) == _print(drop, 80, terminal=False)


@pytest.mark.parametrize("width", [100, 80, 60])
def test_a_narrow_terminal_gets_the_table_turned_every_number_whole(drop, width) -> None:
    text = _print(drop, width)
    assert all(cell_len(line) <= width for line in text.splitlines()), text
    words = set(text.replace("│", " ").replace("┃", " ").split())
    header, rows = _contact_rows(drop)
    for cell in (*header, *(c for r in rows for c in r)):
        assert all(w in words for w in cell.split()), (cell, text)
    assert text.endswith(textwrap.fill(LEGEND, width=min(width, LEGEND_WIDTH)) + "\n")
