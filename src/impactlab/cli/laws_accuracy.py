"""``impactlab laws [NAME] --accuracy``: every law against the shipped FE curves
(docs/laws/accuracy.md), one table per material pair, or one block per law where the table
does not fit the terminal: a number is never broken across lines."""

from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence
from typing import Any

from rich.table import Table
from rich.text import Text

from impactlab.cli._common import console, emit
from impactlab.cli.printing import versioned
from impactlab.contact import builtin_law_names, get_law

#: The narrowest last column [characters] of the table (the verified range, text that wraps).
_MIN_TEXT_COLUMN = 24
#: Spaces between the cells of one block's line.
_GAP = "   "


def table_width(header: Sequence[str], rows: Sequence[Sequence[str]]) -> int:
    """The width [characters] the table needs so that no cell but the last (a text) folds:
    every column as wide as its widest cell, rich's borders and padding (3 per column, 1 at
    the end)."""
    widths = [max(len(r[i]) for r in [header, *rows] if i < len(r)) for i in range(len(header))]
    return sum(widths[:-1]) + min(widths[-1], _MIN_TEXT_COLUMN) + 3 * len(widths) + 1


def wrapped(text: str, width: int) -> str:
    """``text`` wrapped to ``width`` at spaces, keeping a number with its " %" and every word
    whole (its own lines kept)."""
    keep = "\0"  # a space that textwrap does not break at
    lines = []
    for line in text.splitlines() or [""]:
        parts = textwrap.wrap(
            line.replace(" %", keep + "%"),
            width,
            break_long_words=False,
            break_on_hyphens=False,
        )
        lines += [p.replace(keep, " ") for p in parts] or [""]
    return "\n".join(lines)


def law_blocks(header: Sequence[str], rows: Sequence[Sequence[str]], width: int) -> list[str]:
    """The table as one block per row: ``law: verified range``, then the cells as
    ``delta_max/delta_c: cell`` items, as many on a line as ``width`` holds (each item whole,
    aligned in columns)."""
    ratios = header[1:-1]
    lines: list[str] = []
    for row in rows:
        name, cells = row[0], row[1 : 1 + len(ratios)]
        verified = row[-1] if len(row) == len(header) else ""
        lines.append(wrapped(f"{name}: {verified}" if verified else f"{name}:", width))
        items = [f"{r}: {c}" for r, c in zip(ratios, cells, strict=True)]
        item_width = max((len(i) for i in items), default=0)
        per_line = max(1, (width - 2 + len(_GAP)) // (item_width + len(_GAP)))
        for start in range(0, len(items), per_line):
            chunk = items[start : start + per_line]
            lines.append("  " + _GAP.join(i.ljust(item_width) for i in chunk).rstrip())
    return lines


def _results(only: str | None) -> list[Any]:
    """The accuracy of the built-in laws against every shipped case; with a law of one's own
    (``only``, registered) that law beside them, for the cases of its pair only."""
    from impactlab.fe import accuracy as acc

    measured = acc.measured_laws()
    if only is None or only in measured:
        return acc.accuracy()
    if only in builtin_law_names():
        raise ValueError(
            f"law {only!r} is built from the shipped FE curves, not measured against them: "
            "see docs/laws/tabulated.md for its round trip"
        )
    results = [
        r for r in acc.accuracy((*measured, only)) if any(a.law == only and a.built for a in r.laws)
    ]
    if not results:
        raise ValueError(_no_case(only, [r.case for r in acc.accuracy(())]))
    return results


def _no_case(only: str, cases: Sequence[Any]) -> str:
    """Why no shipped FE case (``cases``) measures the registered law ``only``: none has its
    E*/S_y and nu, or those that have them yield on the other body."""
    from impactlab.contact import registered_laws
    from impactlab.contact.indentation_data import yielding_body
    from impactlab.contact.tabulated import NU_TOLERANCE, RATIO_TOLERANCE

    mine = registered_laws()[only].own_curves
    ratio, side = mine.e_star_over_sy, mine.yielding
    pair = f"E*/S_y = {ratio:.4g}, nu = {mine.nu:g}, a yielding {side}"
    same = [
        c
        for c in cases
        if abs(math.log(c.e_star_over_sy / ratio)) <= math.log1p(RATIO_TOLERANCE)
        and abs(c.pair.nu - mine.nu) <= NU_TOLERANCE
    ]
    other = [c for c in same if yielding_body(c.pair) != side]
    if other:
        names = ", ".join(repr(c.name) for c in other)
        return (
            f"law {only!r} holds for its own pair only ({pair}): the shipped FE case(s) of "
            f"that E*/S_y and nu ({names}) are of a yielding {yielding_body(other[0].pair)}, "
            "and curves differ once the other body yields: nothing to measure it against"
        )
    spans = ", ".join(f"{c.e_star_over_sy:.0f}" for c in cases)
    sides = sorted({yielding_body(c.pair) for c in cases})
    of = f"; all of a yielding {sides[0]}" if len(sides) == 1 else ""
    return (
        f"law {only!r} holds for its own pair only ({pair}), and none of the shipped FE cases "
        f"has that pair (their E*/S_y, matched within {100 * RATIO_TOLERANCE:g} %: {spans}{of}): "
        "nothing to measure it against"
    )


def print_accuracy(name: str | None, as_json: bool) -> None:
    """The accuracy of every law (``name``: that one) against the shipped FE curves: JSON, a
    table per material pair, or blocks where the table is wider than the terminal."""
    from impactlab.fe import accuracy as acc
    from impactlab.fe.accuracy_views import table_rows

    only = str(get_law(name).name) if name else None
    results = _results(only)
    if as_json:
        emit(versioned(acc.report(results, only)), as_json=True, units=acc.UNITS)
        return
    if not results:
        raise ValueError("no FE reference curves are shipped (impactlab/fe/data/)")
    width = console.width
    for res in results:
        header, rows = table_rows(res, only)
        c = res.case
        title = (
            f"{c.description}: E*/S_y = {c.e_star_over_sy:.0f}, delta_c = {c.delta_c * 1e6:.4g} um"
            "\nforce error / delta_r/delta_max error, at delta_max/delta_c ="
        )
        if table_width(header, rows) > width:
            console.print(Text(wrapped(title, width)))
            console.print(Text("\n".join(law_blocks(header, rows, width))))
        else:
            table = Table(title=title, show_header=True, header_style="bold")
            for i, col in enumerate(header):  # numbers never wrap; the verified range may
                last = i == len(header) - 1
                table.add_column(col, overflow="fold" if last else "ellipsis", no_wrap=not last)
            for row in rows:
                table.add_row(*row)
            console.print(table)
        console.print(Text(wrapped(f"recommendation: {res.recommendation()}", width) + "\n"))
    tolerances = (
        f"verified range: within {100 * acc.FORCE_TOLERANCE:g} % in force and "
        f"{acc.RESIDUAL_TOLERANCE:g} in delta_r/delta_max of FE (docs/laws/accuracy.md)."
    )
    console.print(Text(wrapped(tolerances, width)))
