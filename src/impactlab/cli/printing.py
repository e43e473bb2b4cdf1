"""What the commands print through: the console (made when it is used), the SI unit of every
printed field, the (quantity, value, unit) table and ``--json``'s JSON or that table."""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any

from rich.console import Console
from rich.table import Table
from rich.text import Text

from impactlab._display import field_rows
from impactlab._json import to_json
from impactlab._version import __version__
from impactlab.schema.printed import EXTRA_UNITS, SI_UNITS

__all__ = ["EXTRA_UNITS", "SI_UNITS", "console", "emit", "print_rows", "versioned"]


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


def print_rows(rows: list[tuple[str, str, str]], title: str = "") -> None:
    """A (quantity, value, unit) table on stdout (cells are text, never rich markup)."""
    table = Table(title=Text(title) if title else None, show_header=True, header_style="bold")
    table.add_column("quantity", overflow="fold")
    # fold, never cut: a word longer than the column (a source's address) is shown in full
    table.add_column("value", justify="right", overflow="fold")
    table.add_column("unit")
    for name, text, unit in rows:
        value = Text(text, justify="right" if unit else "left")  # numbers right, texts left
        table.add_row(Text(name), value, Text(unit))
    console.print(table)


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
