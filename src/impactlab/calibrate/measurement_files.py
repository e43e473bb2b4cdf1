"""The text of a measurements file and the rows of a CSV one, with their line numbers and with
errors that name the file and the line (a file that is not UTF-8 text, a row with more or
fewer fields than the header, a value under a column without a name)."""

from __future__ import annotations

import csv
from pathlib import Path

from impactlab._validation import read_text_file
from impactlab.calibrate.measurement_columns import check_column_unit

__all__ = ["csv_records", "read_text"]


def read_text(path: Path, kind: str) -> str:
    """The UTF-8 text of the measurements file ``path`` (``kind``: ``"CSV"``, ``"TOML"``);
    ValueError naming it when it is not UTF-8 text (``impactlab._validation.read_text_file``)."""
    return read_text_file(path, kind, f"measurements file {str(path)!r}")


def csv_records(path: Path) -> list[tuple[int, dict[str, str]]]:
    """The rows of a CSV file as (line number, header -> text), without blank lines, rows of
    empty fields only (``,,,,``: a spreadsheet's empty row) and ``#`` comment lines; a column
    without a name and without a value in any row (a trailing comma on every line) is left out.
    ValueError naming the file and the line for a header that names a column twice or gives
    a column a unit that is not one of it (``measurement_columns.check_column_unit``), a header
    of one column holding ';' or tabs (a file that separates its columns with them, before its
    rows are counted: their decimal commas would split them), a row whose number of fields
    differs from the header's (a truncated or ragged row) and a value in a column without a
    name."""
    numbered = [
        (number, line)
        for number, line in enumerate(read_text(path, "CSV").splitlines(), start=1)
        if line.strip() and not line.startswith("#")
    ]
    if not numbered:
        return []
    first, header = numbered[0][0], next(csv.reader([numbered[0][1]]))
    if len(header) == 1 and (";" in header[0] or "\t" in header[0]):
        sep = "';'" if ";" in header[0] else "tabs"
        raise ValueError(
            f"{path}: line {first}: the header is one column {header[0]!r}: the file "
            f"separates its columns with {sep}; a measurements CSV separates them with commas "
            "and writes decimals with a point (0.4, not 0,4)"
        )
    named = [h.strip() for h in header if h.strip()]
    twice = sorted({h for h in named if named.count(h) > 1})
    if twice:
        raise ValueError(
            f"{path}: line {first}: the header names the column(s) {twice} twice; keep one of each"
        )
    for h in named:  # a header's unit, checked once here (not glued to each row's number)
        check_column_unit(f"{path}: line {first}", h)
    records = []
    for number, line in numbered[1:]:
        fields = next(csv.reader([line]))
        if not any(f.strip() for f in fields):
            continue  # an empty row (a spreadsheet's ",,,,"), as a blank line
        if len(fields) != len(header):
            raise ValueError(
                f"{path}: line {number}: {len(fields)} fields, the header has {len(header)} "
                "(a truncated or ragged row)"
            )
        for j, (h, f) in enumerate(zip(header, fields, strict=True)):
            if not h.strip() and f.strip():
                raise ValueError(
                    f"{path}: line {number}: field {j + 1} holds {f.strip()!r} under a column "
                    f"without a name (field {j + 1} of the header, line {first}, is empty): "
                    "name the column, or remove the value (a comma too many?)"
                )
        records.append((number, {h: f for h, f in zip(header, fields, strict=True) if h.strip()}))
    return records
