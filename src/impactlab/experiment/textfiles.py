"""Plain-text data files with ``# key: value`` header lines (marker CSVs, CSV height maps)."""

from __future__ import annotations

import re
from pathlib import Path

from impactlab._validation import read_text_file
from impactlab.experiment.errors import FileFormatError

#: What a spreadsheet pads a one-cell line with: field separators and blanks.
_PADDING = " \t,;"
#: A leading decimal number of a header value.
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?")
#: The header keys that the readers use (marker CSVs, CSV height maps): stated twice, they must
#: agree.
READ_KEYS = frozenset({"units", "unit", "rate", "pixel_size", "pixel_size_y", "height_unit"})


def split_commented(
    text: str, *, keep_tab_lines: bool = False
) -> tuple[dict[str, str], list[tuple[int, str]]]:
    """Split ``text`` into its ``# key: value`` metadata (keys lower-cased) and its data lines.

    Blank lines and other ``#`` comments are skipped; data lines keep their 1-based line numbers
    (for error messages) and their original text. The field separators that a spreadsheet pads
    a one-cell line with (``# units: mm,,,,``) are stripped from both ends of a value. With
    ``keep_tab_lines`` a line of tabs only is a data line (a row of empty cells), not a blank.
    A key that the readers use (``READ_KEYS``) stated twice with different values (``# units:
    m`` then ``# units: mm``) is a ValueError naming both lines (the same value twice, in any
    case or spacing, is fine).
    """
    meta: dict[str, str] = {}
    where: dict[str, tuple[int, str]] = {}
    rows: list[tuple[int, str]] = []
    for ln, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if not s:
            if keep_tab_lines and "\t" in line:
                rows.append((ln, line))
            continue
        if s.startswith("#"):
            body = s.lstrip("#").strip()
            if ":" in body:
                key, value = body.split(":", 1)
                key, value = key.strip().lower(), value.strip(_PADDING)
                if key in meta and key in READ_KEYS and _same(meta[key]) != _same(value):
                    ln0, line0 = where[key]
                    raise ValueError(
                        f"lines {ln0} and {ln} state {key} twice, differently: "
                        f"{line0.strip(_PADDING)!r} and {s.strip(_PADDING)!r}; keep the right one"
                    )
                meta[key] = value
                where.setdefault(key, (ln, s))
            continue
        rows.append((ln, line))
    return meta, rows


def _same(value: str) -> tuple[float | None, str]:
    """A header value as compared for a key stated twice: its leading number as a number
    (``2 um`` and ``2.0 um`` agree), case and blanks do not count."""
    text = "".join(value.split()).lower()
    m = _NUMBER.match(text)
    if m is None:
        return None, text
    return float(m.group(0)), text[m.end() :]


#: A number written with a decimal comma (``-0,25``, ``1,5e-3``).
_DECIMAL_COMMA = re.compile(r"^[-+]?\d*,\d+(?:[eE][-+]?\d+)?$")


def parse_number(cell: str, sep: str | None) -> float:
    """The number in ``cell`` (stripped); a decimal comma (``0,25``) read as a decimal point
    where the fields are not separated by commas (``sep``: ``;``, a tab, None for blanks).
    ValueError otherwise."""
    try:
        return float(cell)
    except ValueError:
        if sep != "," and _DECIMAL_COMMA.match(cell):
            return float(cell.replace(",", "."))
        raise


def not_a_number(cell: str) -> str:
    """The message for a ``cell`` that is not a number, with a hint where it holds a comma."""
    hint = ""
    if "," in cell:
        hint = (
            " (decimal commas are read where semicolons or tabs separate the fields; with "
            "commas between them write decimal points)"
        )
    return f"{cell!r} is not a number{hint}"


def read_text(path: Path, kind: str) -> str:
    """The UTF-8 text of the data file ``path`` (:func:`read_text_file`); FileFormatError
    naming it otherwise (Windows-1252 text named as such, with how to save it as UTF-8)."""
    try:
        return read_text_file(path, kind)
    except ValueError as exc:  # not UTF-8 text
        raise FileFormatError(path, str(exc)) from None
