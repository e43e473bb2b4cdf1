"""What the commands print through: the console (made when it is used), the SI unit of every
printed field, the (quantity, value, unit) table and ``--json``'s JSON or that table."""

from __future__ import annotations

import json
import os
import re
import shutil
import sys
import textwrap
from collections.abc import Mapping
from typing import Any, TextIO

from rich.console import Console
from rich.table import Table
from rich.text import Text

from impactlab._display import field_rows
from impactlab._json import to_json
from impactlab._version import __version__
from impactlab.schema.printed import EXTRA_UNITS, SI_UNITS

__all__ = [
    "EXTRA_UNITS",
    "KEEP",
    "SI_UNITS",
    "console",
    "emit",
    "print_rows",
    "print_wrapped",
    "versioned",
]

#: Joins two words that a terminal's wrapping keeps on one line (a name and its number);
#: printed as a space.
KEEP = "\u00a0"

#: A number and its unit ("7833.4 kg/m^3", "3.1894e-9 kg m^2", "10 %"): kept on one line.
_QUANTITY = re.compile(
    r"(?<![\w.])([-+]?\d[\d.]*(?:e[-+]?\d+)?) "
    r"(kg m\^2|N s|%|[A-Za-z\u00b0\u00b5][A-Za-z0-9^/*]{0,9})(?![\w^/*])"
)


def _kept(text: str) -> str:
    """``text`` with the space between each number and its unit made a :data:`KEEP`."""
    return _QUANTITY.sub(lambda m: f"{m[1]}{KEEP}{m[2].replace(' ', KEEP)}", text)


def _wrapped(text: str, width: int) -> list[str]:
    """The lines of ``text`` wrapped to ``width`` between words (a number with its unit, words
    joined by :data:`KEEP`, never apart), each line's continuations indented 2 more spaces; a
    word wider than ``width`` stays whole on its own line."""
    lines = []
    for line in _kept(text).split("\n"):
        indent = " " * (len(line) - len(line.lstrip(" ")))
        lines += textwrap.wrap(
            line, width, subsequent_indent=indent + "  ", break_long_words=False,
            break_on_hyphens=False,
        ) or [line]  # fmt: skip
    return [line.replace(KEEP, " ") for line in lines]


def _terminal_width(stream: TextIO) -> int | None:
    """The width of ``stream`` when it is a terminal (``COLUMNS`` first), else None."""
    try:
        if not stream.isatty():
            return None
    except (AttributeError, ValueError):  # no isatty, or closed
        return None
    columns = os.environ.get("COLUMNS", "")
    if columns.isdigit() and int(columns) > 0:
        return int(columns)
    try:
        return os.get_terminal_size(stream.fileno()).columns or 80
    except (AttributeError, ValueError, OSError):
        return shutil.get_terminal_size().columns


def print_wrapped(text: str, file: TextIO | None = None) -> None:
    """Print ``text`` (a ``warning:``, ``error:`` or ``note:`` line) on ``file`` (stderr by
    default): on a terminal wrapped between words to its width, continuations indented 2
    spaces; into a pipe or a file as one line (:data:`KEEP` as a space)."""
    stream = sys.stderr if file is None else file
    width = _terminal_width(stream)
    if width is None:
        print(text.replace(KEEP, " "), file=stream)
    else:
        print("\n".join(_wrapped(text, max(width, 20))), file=stream)


def versioned(data: Mapping[str, Any]) -> dict[str, Any]:
    """``data`` with ``impactlab_version`` at its top level, as every ``--json`` document has
    it (a listing keyed by name too: the key sits beside the names)."""
    return {**data, "impactlab_version": __version__}


class _CurrentConsole:
    """The command's console, made when it is used: rich's ``Console`` reads ``COLUMNS`` (and
    the terminal's size) when it is created, so one made at import would keep the width of
    whatever environment first imported this module."""

    def __getattr__(self, name: str) -> Any:
        return getattr(Console(), name)


console = _CurrentConsole()


#: The columns' borders and padding of :func:`print_rows`'s table: 4 bars, 2 spaces a column.
_FRAME = 10


def _fitted(rows: list[tuple[str, str, str]], width: int) -> tuple[int, int, int] | None:
    """The (quantity, value, unit) column widths that fit ``rows`` into ``width`` on a
    terminal, or None where the table fits as it is (or nothing would fit): the value column
    as wide as its longest word (a number with its unit) that the terminal can hold, the
    quantities' names whole where that leaves room."""
    name_w = max(len("quantity"), *(len(r[0]) for r in rows))
    unit_w = max(len("unit"), *(len(r[2]) for r in rows))
    texts = [line for r in rows for line in r[1].split("\n")]
    if name_w + unit_w + max(len("value"), *map(len, texts)) + _FRAME <= width:
        return None
    room = width - _FRAME - unit_w  # for the quantity and value columns
    most = room - min(name_w, 10)  # a quantity's name folds before a value's word does
    words = [len(w) for t in texts for w in _kept(t).split() if len(w) <= most]
    value_w = max(room - name_w, *words)
    if value_w < 5 or room - value_w < 1:
        return None
    return room - value_w, value_w, unit_w


def print_rows(rows: list[tuple[str, str, str]], title: str = "") -> None:
    """A (quantity, value, unit) table on stdout (cells are text, never rich markup). On a
    terminal too narrow for it, a value is wrapped between words (a number with its unit kept
    together); a word wider than the column is folded, never cut."""
    widths = _fitted(rows, console.width) if rows and console.is_terminal else None
    table = Table(title=Text(title) if title else None, show_header=True, header_style="bold")
    table.add_column("quantity", overflow="fold", width=widths and widths[0])
    # fold, never cut: a word longer than the column (a source's address) is shown in full
    table.add_column("value", justify="right", overflow="fold", width=widths and widths[1])
    table.add_column("unit", width=widths and widths[2])
    for name, text, unit in rows:
        if widths is not None:
            text = "\n".join(_wrapped_cell(text, widths[1]))
        value = Text(text, justify="right" if unit else "left")  # numbers right, texts left
        table.add_row(Text(name), value, Text(unit))
    console.print(table)


def _wrapped_cell(text: str, width: int) -> list[str]:
    """The lines of a value cell ``width`` wide: wrapped between words, a number with its
    unit kept together, a word wider than the cell folded (never cut)."""
    lines = []
    for line in _kept(text).split("\n"):
        wrapped = textwrap.wrap(line, width, break_long_words=False, break_on_hyphens=False)
        for part in wrapped or [""]:  # a longer word alone on its line: folded
            lines += [part[i : i + width] for i in range(0, len(part), width)] or [""]
    return [line.replace(KEEP, " ") for line in lines]


def emit(
    data: Mapping[str, Any],
    *,
    as_json: bool,
    title: str = "",
    units: Mapping[str, str] | None = None,
    sigmas: Mapping[str, Any] | None = None,
) -> None:
    """Print ``data`` (SI values) as JSON (``--json``: quantities as ``{"value", "unit",
    "sigma"}``, docs/json-schema.md) or as a table in display units (``impactlab._display``).
    ``units``: SI units of fields that are not in :data:`SI_UNITS` (or differ there)."""
    si = {**SI_UNITS, **(units or {})}
    if as_json:
        print(json.dumps(to_json(data, si, sigmas), indent=2))
        return
    print_rows(field_rows(data, si, sigmas), title)
