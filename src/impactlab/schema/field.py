"""``Field``: one result field's name, SI unit, meaning and symbol."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Field"]


@dataclass(frozen=True)
class Field:
    """One result field: ``name``, SI ``unit`` (pint-parseable, ``"1"`` dimensionless), a
    one-line ``description`` and an optional math ``symbol`` (LaTeX, for docs and plots)."""

    name: str
    unit: str
    description: str
    symbol: str = ""
