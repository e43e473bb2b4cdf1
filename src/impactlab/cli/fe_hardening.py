"""``impactlab fe indent --hardening FILE``: the flat's hardening table from a CSV file."""

from __future__ import annotations

import csv
import re
from pathlib import Path

from impactlab._validation import read_text_file
from impactlab.cli._common import UserError

#: Words of a header cell that name the stress column (with its unit, if any), and the
#: plastic-strain column.
_STRESS = re.compile(r"stress|sigma|(?<![a-z])[kmg]?pa\b", re.IGNORECASE)
_UNIT = re.compile(r"(?<![a-z])(?P<prefix>[kmg]?)pa\b", re.IGNORECASE)
_STRAIN = re.compile(r"strain|eps", re.IGNORECASE)
#: The stress unit a header may name, in Pa.
_PREFIX = {"": 1.0, "k": 1e3, "m": 1e6, "g": 1e9}


def _kind(cell: str) -> str | None:
    """ "strain" or "stress" when a header cell names one of them, else None."""
    if _STRAIN.search(cell):
        return "strain"
    return "stress" if _STRESS.search(cell) else None


def _header(row: list[str], path: Path) -> tuple[bool, float] | None:
    """(strain first, the stress unit in Pa) when ``row`` is a header of two cells that name
    a column (``plastic_strain, stress_MPa``; one named cell names the other too); None for any
    other first line (a title: the columns then are stress [Pa], plastic strain). A UserError
    for a header that names both columns the same."""
    if len(row) != 2:
        return None
    kinds = [_kind(c) for c in row]
    if kinds[0] is not None and kinds[0] == kinds[1]:
        raise UserError(
            f"--hardening {path}: line 1 ({','.join(row)!r}) names both columns {kinds[0]}; "
            "name them 'stress_Pa, plastic_strain' (or 'plastic_strain, stress_Pa')"
        )
    if kinds == [None, None]:
        return None
    strain_first = kinds[0] == "strain" or kinds[1] == "stress"
    unit = _UNIT.search(row[1] if strain_first else row[0])
    return strain_first, _PREFIX[unit["prefix"].lower()] if unit else 1.0


def read_hardening(path: Path) -> list[tuple[float, float]]:
    """A hardening CSV as (true stress [Pa], true plastic strain) rows: two columns, stress
    [Pa] first, one row each; a first line of two cells that name the columns
    (``plastic_strain, stress_MPa``) sets their order and the stress unit (Pa, kPa, MPa, GPa);
    any other first line that is not numbers is a title."""
    if not path.is_file():
        raise FileNotFoundError(f"--hardening file not found: {path}")
    try:
        text = read_text_file(path, "CSV", f"--hardening {str(path)!r}")
    except ValueError as exc:  # not UTF-8 text
        raise UserError(str(exc)) from None
    rows: list[tuple[float, float]] = []
    swap, scale = False, 1.0
    for i, row in enumerate(csv.reader(text.splitlines())):
        if not row or not "".join(row).strip():
            continue
        try:
            a, b = float(row[0]), float(row[1])
        except (ValueError, IndexError):
            if i == 0:
                swap, scale = _header(row, path) or (False, 1.0)  # a header or a title
                continue
            order = (
                "plastic_strain, stress_Pa' (the header's order)"
                if swap
                else ("stress_Pa, plastic_strain'")
            )
            raise UserError(
                f"--hardening {path}: line {i + 1} must be '{order}, got {','.join(row)!r}"
            ) from None
        stress, strain = (b, a) if swap else (a, b)
        rows.append((stress * scale, strain))
    if not rows:  # empty, blank or a header alone
        raise UserError(
            f"--hardening {path}: the file has no data rows; give rows of 'stress_Pa, "
            "plastic_strain', the first at plastic strain 0"
        )
    return rows
