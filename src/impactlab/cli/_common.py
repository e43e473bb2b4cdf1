"""Shared helpers for the command modules: unit-aware options, TOML inputs, JSON/table output."""

from __future__ import annotations

import json
import tomllib
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import typer
from rich.console import Console
from rich.table import Table

from impactlab._json import jsonable
from impactlab.schema import FIELDS
from impactlab.units import angle_to_rad, to_si


class UserError(ValueError):
    """An error in the user's input: reported as one line, exit status 2."""


console = Console()


def quantity(value: str | float | None, unit: str, name: str) -> float | None:
    """Parse a CLI quantity ("8.8 mm"; a bare number is in ``unit``) to SI; None passes through."""
    if value is None:
        return None
    return to_si(value, unit, name=name)


def positive(value: str | float | None, unit: str, name: str) -> float | None:
    """:func:`quantity`, and > 0: a given value is always used (None passes through)."""
    x = quantity(value, unit, name)
    if x is not None and not x > 0:
        raise UserError(f"{name} must be > 0, got {value!r}")
    return x


def angle_quantity(value: Any, name: str) -> float:
    """An angle with its unit ("20 deg", "0.35 rad") in radians. A bare number is refused: 0.35
    could be degrees or radians."""
    text = str(value).strip()
    try:
        float(text)
    except ValueError:
        return angle_to_rad(text, name=name)
    raise UserError(f"{name} {text} has no unit: give a unit, e.g. '20 deg' or '0.35 rad'")


#: The rod's properties in a [rod] table or as options, with their SI units.
ROD_FIELDS: dict[str, str] = {"mass": "kg", "length": "m", "tip_radius": "m", "inertia": "kg*m^2"}


#: The rod options' help (the defaults are the paper's rod).
_ROD_HELP = {
    "mass": "Rod mass (default 0.4607 kg).",
    "length": "Rod length (default 0.3048 m).",
    "tip_radius": "Tip radius (default 8.8 mm).",
    "inertia": "I_C about the centre of mass, e.g. '3.6e-3 kg*m^2' (default m L^2/12).",
}


def rod_option(key: str) -> Any:
    """The command-line option of the rod property ``key`` (``--tip-radius``)."""
    return typer.Option(None, "--" + key.replace("_", "-"), help=_ROD_HELP[key])


def parse_rod_table(table: Mapping[str, Any], prefix: str) -> dict[str, float]:
    """The rod's properties in SI from a [rod] table (``prefix`` "rod.") or from the options
    (``prefix`` "--"); an unknown key is an error listing the allowed ones."""
    out: dict[str, float] = {}
    for key, value in table.items():
        if key not in ROD_FIELDS:
            raise UserError(f"unknown key {key!r} in [rod]; allowed: {', '.join(ROD_FIELDS)}")
        name = prefix + (key.replace("_", "-") if prefix == "--" else key)
        out[key] = positive(value, ROD_FIELDS[key], name)  # type: ignore[assignment]
    return out


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


def show(result: Any, *, as_json: bool, table: Callable[[Any], None]) -> None:
    """Print ``result`` as JSON (its ``to_dict()``) with ``--json``, else with ``table``."""
    if as_json:
        emit(result.to_dict(), as_json=True)
    else:
        table(result)
