"""Values read from a TOML input file that TOML itself does not check: a switch must be a
TOML boolean (``true``/``false``), since Python reads any non-empty string, ``"false"``
included, as true."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

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
