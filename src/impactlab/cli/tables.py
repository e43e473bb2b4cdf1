"""Tables on stdout that stay readable at any width (those of the commands ``explain`` and
``calibrate``).

Into a pipe or a file a table is printed whole, as wide as it needs (rich would cut it to 80
columns), so that scripts and saved logs see every cell on one line. On a terminal no word or
number is ever broken inside: every column is at least as wide as its longest word, and cells
wrap between words. Where the table does not fit the terminal even so, it is printed turned:
per group of rows (a drop, say) the fields down and the group's rows across, each under its
label, in as many tables as the terminal's width needs (a table of one row, one field a line,
at the narrowest).
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Sequence
from typing import Literal

from rich.cells import cell_len
from rich.console import Console
from rich.table import Table
from rich.text import Text

__all__ = ["Layout", "show_table"]

#: How :func:`show_table` printed a table: whole, or turned per group.
Layout = Literal["table", "turned"]


def _longest_word(cells: Sequence[str]) -> int:
    """The width of the widest whitespace-free run in ``cells`` [terminal columns]."""
    return max((cell_len(w) for c in cells for w in c.split()), default=1)


def _fill(base: list[int], want: list[int], left: int) -> tuple[list[int], int]:
    """``base`` raised towards ``want`` by at most ``left`` in all: an even share each, a
    column that wants less than its share taking what it wants (the smallest wants are met in
    full); returns the widths and what is left."""
    out = list(base)
    order = sorted(range(len(out)), key=lambda j: want[j] - base[j])
    for k, j in enumerate(order):
        more = min(want[j] - out[j], left // (len(order) - k))
        out[j], left = out[j] + more, left - more
    for j in reversed(order):  # the rounding's rest, to the largest wants
        more = min(want[j] - out[j], left)
        out[j], left = out[j] + more, left - more
    return out, left


def _widths(head: Sequence[str], columns: Sequence[Sequence[str]], width: int) -> list[int] | None:
    """Column widths [terminal columns, without padding] for a table ``width`` wide with every
    word whole: each column's natural width where all fit; else its longest word, raised first
    towards the width of its widest cell (so that short cells stay on one line, a long header
    or text wraps), then towards that of its header (``_fill``); None where the longest words
    alone do not fit."""
    pairs = list(zip(head, columns, strict=True))
    least = [_longest_word([h, *c]) for h, c in pairs]
    body = [max([n, *(cell_len(x) for x in c)]) for n, (_, c) in zip(least, pairs, strict=True)]
    most = [max(b, cell_len(h)) for b, (h, _) in zip(body, pairs, strict=True)]
    room = width - (3 * len(head) + 1)  # per column 2 of padding and a rule, and the last rule
    if sum(most) <= room:
        return most
    if sum(least) > room:
        return None
    widths, left = _fill(least, body, room - sum(least))
    return _fill(widths, most, left)[0]


def _table(title: str | None, head: Sequence[str], columns: Sequence[Sequence[str]],
           width: int | None, right: Collection[str] = ()) -> Table | None:  # fmt: skip
    """A rich table of ``columns`` (each a sequence of cells, one per row) under ``head``:
    as wide as its cells (``width`` None: a pipe), or ``width`` wide at most with every word
    whole (None where that cannot be), or, ``width`` negative, at most -``width`` wide with a
    word wider than its column folded (never cut)."""
    widths = None if width is None or width < 0 else _widths(head, columns, width)
    if width is not None and width >= 0 and widths is None:
        return None
    table = Table(title=Text(title) if title else None, header_style="bold",
                  width=-width if width is not None and width < 0 else None)  # fmt: skip
    for j, name in enumerate(head):
        table.add_column(
            Text(name),
            justify="right" if name in right else "left",
            overflow="fold",
            width=widths[j] if widths else None,
        )
    for i in range(len(columns[0]) if columns else 0):
        table.add_row(*(Text(cells[i]) for cells in columns))
    return table


def _groups(rows: Sequence[Sequence[str]], group: int | None) -> list[tuple[str, list[int]]]:
    """(group name, row indices) in order; a row whose ``group`` cell is empty continues the
    group above; ``group`` None: one group of every row, unnamed."""
    if group is None:
        return [("", list(range(len(rows))))]
    out: list[tuple[str, list[int]]] = []
    for i, row in enumerate(rows):
        if row[group] or not out:
            out.append((row[group], []))
        out[-1][1].append(i)
    return out


def _turned(head: Sequence[str], rows: Sequence[Sequence[str]], members: Sequence[int],
            fields: Sequence[int], label: int, title: str | None,
            width: int) -> Table | None:  # fmt: skip
    """The rows ``members`` turned (``_table``'s ``width``): ``fields`` down (none that is empty
    in all of them), each row across under its ``label`` cell."""
    kept = [j for j in fields if any(rows[i][j] for i in members)]
    labels = [head[label], *(rows[i][label] for i in members)]
    cols = [[head[j] for j in kept], *([rows[i][j] for j in kept] for i in members)]
    return _table(title, labels, cols, width)


def _split(
    fits: Callable[[list[int]], bool], rows: list[int], first: list[int]
) -> list[list[int]] | None:
    """``rows`` in consecutive parts that each ``fits`` after ``first``, as few as fit and as
    even in size as fit; None where a row alone does not fit."""
    parts: list[list[int]] = []
    rest = rows
    while rest:
        n = 0
        while n < len(rest) and fits(first + rest[: n + 1]):
            n += 1
        if n == 0:
            return None
        parts, rest = [*parts, rest[:n]], rest[n:]
    size = -(-len(rows) // len(parts))  # the same count of parts, of even sizes
    even = [rows[i : i + size] for i in range(0, len(rows), size)]
    return even if len(even) == len(parts) and all(fits(first + p) for p in even) else parts


def show_table(
    title: str,
    head: Sequence[str],
    rows: Sequence[Sequence[str]],
    *,
    right: Collection[str] = (),
    group: int | None = None,
    label: int = 0,
    pin: bool = False,
    out: Console | None = None,
) -> Layout:
    """Print ``rows`` (cells as plain text, never rich markup) under ``head`` on stdout (or
    ``out``) and return the layout used.

    ``right``: the columns justified right (numbers) in the whole table. ``group``: the index
    of the column that groups the rows when the table is turned (an empty cell continues the
    group above; None: all rows one group); ``label``: the index of the column that names
    each row across a turned table. A group too wide for the terminal is split into turned
    tables of as many rows as fit (``pin``: the group's first row, a reference such as the
    measured values, repeated in each)."""
    out = Console() if out is None else out
    columns = [[str(r[j]) for r in rows] for j in range(len(head))]
    if not out.is_terminal:
        whole = _table(title, head, columns, None, right)
        assert whole is not None
        need = out.measure(whole, options=out.options.update_width(10_000)).maximum
        Console(file=out.file, width=max(out.width, need)).print(whole)
        return "table"
    whole = _table(title, head, columns, out.width, right)
    if whole is not None:
        out.print(whole)
        return "table"
    fields = [j for j in range(len(head)) if j not in (group, label)]
    out.print(Text(title, style="bold"))
    for name, members in _groups(rows, group):
        caption = name or None

        def fits(shown: list[int], caption: str | None = caption) -> bool:
            return _turned(head, rows, shown, fields, label, caption, out.width) is not None

        pinned = members[:1] if pin and len(members) > 1 else []
        parts = _split(fits, members[len(pinned) :], pinned)
        if parts is None and pinned:  # no room for the pinned row beside another
            pinned, parts = [], _split(fits, members, [])
        for part in parts or [[i] for i in members]:  # none: each row alone, words folded
            table = _turned(head, rows, pinned + part, fields, label, caption,
                            out.width if parts is not None else -out.width)  # fmt: skip
            assert table is not None
            out.print(table)
    return "turned"
