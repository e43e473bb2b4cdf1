"""The contacts of a drop as ``impactlab drop`` and ``impactlab simulate --flexible`` print them:
one line a contact, in display units, with a legend of its columns; turned on a terminal too
narrow for it."""

from __future__ import annotations

import textwrap

from rich.console import Console
from rich.text import Text

from impactlab._display import display_unit, field_row
from impactlab.cli.printing import SI_UNITS
from impactlab.cli.tables import show_table
from impactlab.dynamics.drop_result import DropResult

__all__ = ["LEGEND", "print_contacts"]

#: The legend's width in a pipe or a file, and its largest on a terminal [characters].
LEGEND_WIDTH = 100

#: What the contact table's columns and the less obvious totals mean (printed under the table).
LEGEND = (
    "end: the end that touched (0 the tip, 1 the other end); start: from the first touch; "
    "sliding_length: int v_t dt over the contact (signed along +x, as an impact's); reload: "
    "True if the contact began on an existing dent. "
    "e_raw: e with the gravity impulse of the sequence kept (e removes it, as a ballistic fit "
    "of marker data would, so a nearly lossless drop's e can exceed 1: flagged "
    "gravity-dominated); mu_apparent: the paper's Eq. 28 on the simulated velocities."
)

#: Columns of the contact table: ContactRecord fields (display units: ``impactlab._display``).
_COLUMNS = (
    "end",
    "start",
    "duration",
    "delta_max",
    "max_force",
    "normal_impulse",
    "tangential_impulse",
    "sliding_length",
    "reload",
)


def _contact_rows(result: DropResult) -> tuple[list[str], list[list[str]]]:
    """The contact table's header (field [display unit]) and rows, in display units."""
    header = ["#"]
    for key in _COLUMNS:
        unit = display_unit(key, SI_UNITS.get(key, "")).unit
        header.append(key if unit == "-" else f"{key} [{unit}]")
    rows = []
    for i, c in enumerate(result.contacts, 1):
        cells = [str(i)]
        for key in _COLUMNS:
            v = getattr(c, key)
            cells.append(field_row(key, v, SI_UNITS.get(key))[1])
        rows.append(cells)
    return header, rows


def _contact_lines(header: list[str], rows: list[list[str]]) -> list[str]:
    """Every contact, one line each (plain text, fixed width, the columns right-justified)."""
    table = [header, *rows]
    widths = [max(len(r[j]) for r in table) for j in range(len(header))]
    return ["  ".join(cell.rjust(w) for cell, w in zip(r, widths, strict=True)) for r in table]


def print_contacts(result: DropResult, out: Console | None = None) -> None:
    """The contact table and its legend on stdout (or ``out``), in display units. Into a pipe
    or a file, and on a terminal wide enough: plain text, one line a contact, the legend
    filled to 100 columns. On a narrower terminal the table is turned (its columns down, the
    contacts across, ``cli.tables.show_table``) and the legend filled to the terminal's width,
    so that no number or word is broken."""
    out = Console(soft_wrap=True) if out is None else out
    header, rows = _contact_rows(result)
    lines = _contact_lines(header, rows)
    width = out.width if out.is_terminal else LEGEND_WIDTH
    if not out.is_terminal or max(map(len, lines)) <= width:
        out.print(Text("\n".join(["contacts", *lines])))
    else:
        show_table("contacts", header, rows, right=header, label=0, out=out)
    out.print(Text(textwrap.fill(LEGEND, width=min(width, LEGEND_WIDTH))))
