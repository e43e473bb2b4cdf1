"""Plain-text data files with ``# key: value`` header lines (marker CSVs, CSV height maps)."""

from __future__ import annotations

#: What a spreadsheet pads a one-cell line with: field separators and blanks.
_PADDING = " \t,;"


def split_commented(
    text: str, *, keep_tab_lines: bool = False
) -> tuple[dict[str, str], list[tuple[int, str]]]:
    """Split ``text`` into its ``# key: value`` metadata (keys lower-cased) and its data lines.

    Blank lines and other ``#`` comments are skipped; data lines keep their 1-based line numbers
    (for error messages) and their original text. The field separators that a spreadsheet pads
    a one-cell line with (``# units: mm,,,,``) are stripped from both ends of a value. With
    ``keep_tab_lines`` a line of tabs only is a data line (a row of empty cells), not a blank.
    """
    meta: dict[str, str] = {}
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
                meta[key.strip().lower()] = value.strip(_PADDING)
            continue
        rows.append((ln, line))
    return meta, rows
