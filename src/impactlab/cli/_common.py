"""Shared helpers for the command modules: unit-aware options, TOML inputs, JSON/table output."""

from __future__ import annotations

import json
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

from impactlab._json import jsonable
from impactlab.schema import FIELDS
from impactlab.units import to_si


class UserError(ValueError):
    """An error in the user's input: reported as one line, exit status 2."""


console = Console()


def quantity(value: str | float | None, unit: str, name: str) -> float | None:
    """Parse a CLI quantity ("8.8 mm"; a bare number is in ``unit``) to SI; None passes through."""
    if value is None:
        return None
    return to_si(value, unit, name=name)


def load_toml(path: Path | None) -> dict[str, Any]:
    """Read a TOML input file (empty dict for None); clear error if missing or malformed."""
    if path is None:
        return {}
    if not path.is_file():
        raise UserError(f"input file {str(path)!r} does not exist")
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise UserError(f"input file {str(path)!r} is not valid TOML: {exc}") from None


def field_units(data: Mapping[str, Any]) -> dict[str, str]:
    """Display units of the result fields among ``data``'s keys, from :mod:`impactlab.schema`
    ("-" for a dimensionless number, nothing for names and counts)."""
    units: dict[str, str] = {}
    for key, value in data.items():
        f = FIELDS.get(key)
        if f is None:
            continue
        if f.unit != "1":
            units[key] = f.unit
        elif isinstance(value, float):
            units[key] = "-"
    return units


def emit(
    data: Mapping[str, Any],
    *,
    as_json: bool,
    title: str = "",
    units: Mapping[str, str] | None = None,
) -> None:
    """Print ``data`` as JSON (``--json``) or as a readable two-column table."""
    if as_json:
        print(json.dumps(jsonable(data), indent=2))
        return
    units = units or {}
    table = Table(title=title or None, show_header=True, header_style="bold")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for key, value in data.items():
        text = f"{value:.6g}" if isinstance(value, float) else str(value)
        table.add_row(key, text, units.get(key, ""))
    console.print(table)
