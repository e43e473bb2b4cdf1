"""The (quantity, value, unit) table of the commands at any terminal width: on a terminal no
line wider than it, no word of a value broken where the column can hold it (a source's
address, a plot's path), a number never apart from its unit; a word wider than the column
is folded, never cut. Into a pipe or a file, the table as before."""

from __future__ import annotations

import io
import re

import pytest
from rich.console import Console
from rich.table import Table
from rich.text import Text

import impactlab.cli.printing as printing
from impactlab.cli.printing import print_rows

BODY = (
    "Sphere: radius = 3 mm, mass = 0.00088594 kg, density = 7833.4 kg/m^3, inertia = "
    "3.1894e-9 kg m^2, material = AISI 52100 bearing steel, hardened"
)
ROD = (
    "Rod: length = 304.8 mm, tip_radius = 8.8 mm, mass = 0.4607 kg, inertia = 0.0035667 kg "
    "m^2, overall_length = 322.4 mm, material = AISI 1010 steel"
)
URL = (
    "https://hallaweb.jlab.org/tech/Detectors/public_html/manuals/data_sheets-manuals/M-N/M/"
    "materials/nickel/08-11-04/MatWeb%20-%20Online%20Material%20Data%20Sheet.htm"
)
PLOTS = (
    "/tmp/study/plots-laws/e_angle.png\n/tmp/study/plots-laws/sliding_length_angle.png\n"
    "/tmp/study/plots-laws/delta_p_angle.png"
)
ROWS = [
    ("body", BODY, ""),
    ("rod", ROD, ""),
    ("density", "7833.4", "kg/m^3"),
    ("sliding_direction", "12.5 (ambiguous)", "deg (scan x)"),
    ("plots", PLOTS, ""),
    ("url", URL, ""),
]
QUANTITIES = ["3 mm", "0.00088594 kg", "7833.4 kg/m^3", "3.1894e-9 kg m^2", "304.8 mm",
              "8.8 mm", "0.4607 kg", "0.0035667 kg m^2", "322.4 mm"]  # fmt: skip


def _show(rows: list[tuple[str, str, str]], width: int, terminal: bool, monkeypatch) -> str:
    buf = io.StringIO()
    console = Console(file=buf, width=width, force_terminal=terminal, color_system=None)
    monkeypatch.setattr(printing, "console", console)
    print_rows(rows, "impactlab simulate")
    return buf.getvalue()


def _cells(text: str) -> list[str]:
    """The value cells' lines, in order."""
    return [line.split("│")[2].strip() for line in text.splitlines() if line.count("│") == 4]


@pytest.mark.parametrize("width", [60, 80, 100])
def test_on_a_terminal_a_quantity_keeps_its_unit(monkeypatch, width: int) -> None:
    text = _show(ROWS, width, True, monkeypatch)
    assert all(len(line) <= width for line in text.splitlines())
    assert "…" not in text
    cells = _cells(text)
    for quantity in QUANTITIES:
        assert any(quantity in cell for cell in cells), (quantity, text)
    for path in PLOTS.split("\n") if width >= 80 else ():  # within the room left: whole
        assert path in cells, (path, text)
    start = next(i for i, c in enumerate(cells) if c.startswith("https://"))
    assert URL in "".join(cells[start:])  # wider than the terminal: folded, in full
    if width >= 100:  # the value column takes the room the quantities leave
        assert max(map(len, cells)) == width - 10 - len("deg (scan x)") - len("sliding_direction")
        assert "sliding_direction" in text


def test_a_table_that_fits_is_as_before(monkeypatch) -> None:
    rows = [("e", "0.44332", "-"), ("duration", "0.021137", "ms"), ("law", "ghaednia", "")]
    assert _show(rows, 80, True, monkeypatch) == _before(rows, 80, True)


@pytest.mark.parametrize("width", [80, 100])
def test_into_a_pipe_the_table_is_as_before(monkeypatch, width: int) -> None:
    assert _show(ROWS, width, False, monkeypatch) == _before(ROWS, width, False)


def _before(rows: list[tuple[str, str, str]], width: int, terminal: bool) -> str:
    """The table as print_rows laid it out before it knew the terminal's width."""
    buf = io.StringIO()
    console = Console(file=buf, width=width, force_terminal=terminal, color_system=None)
    table = Table(title=Text("impactlab simulate"), show_header=True, header_style="bold")
    table.add_column("quantity", overflow="fold")
    table.add_column("value", justify="right", overflow="fold")
    table.add_column("unit")
    for name, text, unit in rows:
        table.add_row(Text(name), Text(text, justify="right" if unit else "left"), Text(unit))
    console.print(table)
    return buf.getvalue()


def test_simulate_shows_its_body_with_whole_quantities(monkeypatch, cli_main) -> None:
    """``impactlab simulate sphere`` at 80 columns: "3.1894e-9 kg" then "m^2" on the next
    line read as a mass."""
    buf = io.StringIO()
    console = Console(file=buf, width=80, force_terminal=True, color_system=None)
    monkeypatch.setattr(printing, "console", console)
    code, _, err = cli_main("simulate", "sphere", "--radius", "3 mm", "--speed", "2.5 m/s",
                            "--incidence", "30 deg", "--material", "aisi-52100", "--flat",
                            "al-6061-t6")  # fmt: skip
    assert code == 0, err
    cells = _cells(buf.getvalue())
    for quantity in (r"radius = 3 mm", r"\d kg/m\^3", r"\de-9 kg m\^2"):
        assert any(re.search(quantity, cell) for cell in cells), (quantity, buf.getvalue())
