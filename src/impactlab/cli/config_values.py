"""Values read from a TOML input file that TOML itself does not check: a switch must be a
TOML boolean (``true``/``false``), since Python reads any non-empty string, ``"false"``
included, as true; a number a number (``true`` is none); a name text."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from impactlab._validation import percent_fraction
from impactlab.cli._common import UserError


def check_booleans(table: Mapping[str, Any], keys: Iterable[str], where: str) -> None:
    """UserError naming the key and ``where`` (the file) unless each of ``keys`` present in
    ``table`` holds a TOML boolean."""
    for key in keys:
        value = table.get(key)
        if value is not None and not isinstance(value, bool):
            raise UserError(
                f"{key} in {where} must be true or false (a TOML boolean, without quotes), "
                f"got {value!r}"
            )


def plain_number(value: Any, name: str) -> float:
    """A plain number (an option's float, or a config file's number or numeric text, or a
    percentage: ``"20 %"`` is 0.2, as in the Python API), else a UserError naming ``name``; a
    TOML boolean is no number."""
    try:
        if isinstance(value, bool):
            raise TypeError(value)
        return float(percent_fraction(value))
    except (TypeError, ValueError):
        raise UserError(f"{name} must be a number, got {value!r}") from None


def text(value: Any, name: str) -> str:
    """A name (a law, a friction model, a stop rule): TOML text, else a UserError naming
    ``name``."""
    if not isinstance(value, str):
        raise UserError(f"{name} must be text, a name in quotes, got {value!r}")
    return value


def option_numbers(cli: Mapping[str, Any], keys: Iterable[str]) -> dict[str, Any]:
    """The options ``cli`` (by key, None: not given) with each given one of ``keys`` read as a
    plain number (:func:`plain_number`: ``--mu must be a number, got 'abc'``), before any use."""
    wanted = set(keys)
    return {
        k: plain_number(v, "--" + k.replace("_", "-")) if k in wanted and v is not None else v
        for k, v in cli.items()
    }
