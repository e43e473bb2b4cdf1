"""``impactlab fe indent --hardening FILE``: the flat's hardening table from a CSV file."""

from __future__ import annotations

import csv
import re
from pathlib import Path

from impactlab._validation import read_text_file
from impactlab.cli._common import UserError

#: Words of a header cell that name the stress column, and the plastic-strain column.
_STRESS = re.compile(r"stress|sigma|\b[kmg]?pa\b", re.IGNORECASE)
_STRAIN = re.compile(r"strain|eps", re.IGNORECASE)


def _kind(cell: str) -> str | None:
    """ "strain" or "stress" when a header cell names one of them, else None."""
    if _STRAIN.search(cell):
        return "strain"
    return "stress" if _STRESS.search(cell) else None


def _strain_first(header: list[str], path: Path) -> bool:
    """Whether a header line names the columns (plastic strain, stress), in that order; a
    UserError for a header that names both columns the same."""
    kinds = [_kind(c) for c in header[:2]] + [None] * (2 - len(header[:2]))
    if kinds[0] is not None and kinds[0] == kinds[1]:
        raise UserError(
            f"--hardening {path}: line 1 ({','.join(header)!r}) names both columns {kinds[0]}; "
            "name them 'stress_Pa, plastic_strain' (or 'plastic_strain, stress_Pa')"
        )
    return kinds[0] == "strain" or kinds[1] == "stress"


def read_hardening(path: Path) -> list[tuple[float, float]]:
    """A hardening CSV as (true stress [Pa], true plastic strain) rows: two columns, stress
    first, one row each; a header line that names the columns (``plastic_strain,
    stress_Pa``) sets their order."""
    if not path.is_file():
        raise FileNotFoundError(f"--hardening file not found: {path}")
    try:
        text = read_text_file(path, "CSV", f"--hardening {str(path)!r}")
    except ValueError as exc:  # not UTF-8 text
        raise UserError(str(exc)) from None
    rows: list[tuple[float, float]] = []
    swap = False
    for i, row in enumerate(csv.reader(text.splitlines())):
        if not row or not "".join(row).strip():
            continue
        try:
            a, b = float(row[0]), float(row[1])
        except (ValueError, IndexError):
            if i == 0:
                swap = _strain_first(row, path)  # the header
                continue
            order = (
                "plastic_strain, stress_Pa' (the header's order)"
                if swap
                else ("stress_Pa, plastic_strain'")
            )
            raise UserError(
                f"--hardening {path}: line {i + 1} must be '{order}, got {','.join(row)!r}"
            ) from None
        rows.append((b, a) if swap else (a, b))
    return rows
