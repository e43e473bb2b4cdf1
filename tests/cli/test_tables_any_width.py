"""The commands' wide tables (``impactlab explain``, ``impactlab calibrate``) at any terminal
width: no line wider than the terminal, no word or number broken inside, the whole table where
it fits, turned per group where it does not; into a pipe or a file, whole on one line a row."""

from __future__ import annotations

import io
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from rich.cells import cell_len
from rich.console import Console

from impactlab.cli.tables import show_table

BOX = re.compile(r"[│┃┏┓┗┛┡┩┣┫┳┻╇╋━─└┘┌┐┬┴┼├┤╭╮╯╰]")

HEAD = ("drop", "configuration", "e", "delta_p [um]", "within 2 sigma", "chi2", "verdict",
        "n_contacts", "mu_apparent", "flags", "status")  # fmt: skip
_CS = "flexible rod + rate-dependent flat (cowper-symonds, upper estimate)"
ROWS = [
    ("20 deg", "measured (+- sigma)", "0.5 +- 0.03", "22 +- 2.2", "", "", "", "", "0.2", "", ""),
    ("", "rigid body", "0.4225 (z -2.58)", "62.05 (z +18.2)", "0/2", "435", "", "1", "0.2",
     "law_extrapolated", "ok"),
    ("", "flexible rod", "0.7239 (z +7.46)", "32.47 (z +4.76)", "0/2", "144.5", "", "4",
     "0.1671", "law_extrapolated", "ok"),
    ("", _CS, "0.7392 (z +7.97)", "22.89 (z +0.405)", "1/2", "129.6", "first, inconsistent",
     "4", "0.1659", "law_extrapolated", "ok"),
    ("45 deg", "measured (+- sigma)", "0.49 +- 0.03", "26 +- 2.6", "", "", "", "", "0.13", "",
     ""),
    ("", "rigid body", "0.4184 (z -2.39)", "111.1 (z +32.7)", "1/2", "3.1", "best", "1", "0.13",
     "-", "ok"),
]  # fmt: skip


def _terminal(width: int) -> tuple[Console, io.StringIO]:
    buf = io.StringIO()
    return Console(file=buf, width=width, force_terminal=True, color_system=None), buf


def _words(text: str) -> list[str]:
    return BOX.sub(" ", text).split()


def _check_whole_words(text: str, head: tuple[str, ...], rows: list[tuple[str, ...]]) -> None:
    """Every word of every header and cell is in ``text`` whole (none broken over lines); the
    first column groups the rows: a turned table shows its cells as titles, not its name."""
    shown = set(_words(text))
    for cell in (*head[1:], *(c for r in rows for c in r)):
        for word in cell.split():
            assert word in shown, (word, text)


def _show(width: int, **kw: object) -> tuple[str, str]:
    out, buf = _terminal(width)
    layout = show_table("which physics", HEAD, ROWS, group=0, label=1, out=out, **kw)  # type: ignore[arg-type]
    return layout, buf.getvalue()


def test_a_wide_terminal_gets_the_whole_table() -> None:
    layout, text = _show(250)
    assert layout == "table"
    assert all(cell_len(line) <= 250 for line in text.splitlines())
    _check_whole_words(text, HEAD, ROWS)
    # the long configuration wraps between its words, inside its column
    assert "0.7392 (z +7.97)" in text


@pytest.mark.parametrize("width", [120, 100, 80, 60])
def test_a_narrow_terminal_gets_each_group_turned_and_every_word_whole(width: int) -> None:
    layout, text = _show(width, pin=True)
    assert layout == "turned"
    assert all(cell_len(line) <= width for line in text.splitlines()), text
    _check_whole_words(text, HEAD, ROWS)
    # one title per group part, the groups in order; the fields down, each once per part
    lines = [line.strip() for line in text.splitlines()]
    assert lines[0] == "which physics"
    assert lines.index("20 deg") < lines.index("45 deg")
    parts_20 = lines.count("20 deg")
    # the pinned measured row beside every part of its group
    assert text.count("0.5 +- 0.03") == parts_20
    assert text.count("0.4225 (z -2.58)") == 1


def test_the_parts_of_a_group_are_as_few_and_as_even_as_fit() -> None:
    # the three configurations of 20 deg beside the measured values: two fit at 80 columns
    # (two parts), one at 60 (three parts)
    for width, parts in ((80, 2), (60, 3)):
        _, text = _show(width, pin=True)
        lines = [line.strip() for line in text.splitlines()]
        assert lines.count("20 deg") == parts, text
        assert lines.count("45 deg") == 1


def test_the_pinned_row_gives_way_where_it_leaves_no_room() -> None:
    out, buf = _terminal(40)  # a configuration alone fits, not beside the measured values
    show_table("t", HEAD, ROWS, group=0, label=1, pin=True, out=out)
    text = buf.getvalue()
    assert text.count("0.5 +- 0.03") == 1
    assert text.count("0.4225 (z -2.58)") == 1
    _check_whole_words(text, HEAD, ROWS)


def test_an_empty_field_of_a_whole_group_is_left_out_turned() -> None:
    _, text = _show(80)
    part_45 = text[text.index("45 deg") :]
    assert "verdict" in part_45  # 'best'
    rows = [("20 deg", "measured (+- sigma)", "1", "2", "", "", "", "", "0.2", "", "")]
    out, buf = _terminal(40)
    show_table("t", HEAD, rows, group=0, label=1, out=out)
    assert "verdict" not in buf.getvalue()
    assert "flags" not in buf.getvalue()


def test_a_terminal_too_narrow_for_one_row_folds_rather_than_cuts() -> None:
    layout, text = _show(24)
    assert layout == "turned"
    assert all(cell_len(line) <= 24 for line in text.splitlines())
    assert "…" not in text
    assert text.count("law_ex") == 3  # folded onto more lines, never cut


def test_a_pipe_gets_the_whole_table_one_line_a_row() -> None:
    buf = io.StringIO()
    out = Console(file=buf, width=80, force_terminal=False, color_system=None)
    assert show_table("which physics", HEAD, ROWS, group=0, label=1, out=out) == "table"
    text = buf.getvalue()
    long = "flexible rod + rate-dependent flat (cowper-symonds, upper estimate)"
    line = next(line for line in text.splitlines() if "cowper" in line)
    assert long in line and "0.7392 (z +7.97)" in line and "first, inconsistent" in line


def test_numbers_are_justified_right_in_the_whole_table() -> None:
    buf = io.StringIO()
    out = Console(file=buf, width=300, force_terminal=True, color_system=None)
    show_table("t", ("name", "value"), [("a", "1"), ("b", "100")], right={"value"}, out=out)
    rows = [line for line in buf.getvalue().splitlines() if line.startswith("│")]
    assert rows[0].index("1 │") == rows[1].index("100 │") + 2


WORD = st.text(alphabet="abcdefghij-_.0123456789", min_size=1, max_size=12)
CELL = st.lists(WORD, min_size=0, max_size=4).map(" ".join)


@settings(max_examples=60, deadline=None)
@given(
    n_cols=st.integers(2, 7),
    data=st.data(),
    width=st.integers(20, 160),
    pin=st.booleans(),
)
def test_any_table_fits_any_width_with_its_words_whole(
    n_cols: int, data: st.DataObject, width: int, pin: bool
) -> None:
    head = tuple(f"col{j} name" for j in range(n_cols))
    rows = data.draw(st.lists(st.tuples(*[CELL] * n_cols), min_size=1, max_size=6))
    rows = [(r[0], r[1] or "row", *r[2:]) for r in rows]
    out, buf = _terminal(width)
    show_table("title", head, rows, group=0, label=1, pin=pin, out=out)
    text = buf.getvalue()
    longest = max(len(w) for c in (*head, *(c for r in rows for c in r)) for w in c.split())
    assert all(cell_len(line) <= width for line in text.splitlines())
    if width >= 2 * longest + 7:  # a turned row (fields, values) fits with its words whole
        shown = tuple(h for j, h in enumerate(head[1:], 1) if j == 1 or any(r[j] for r in rows))
        _check_whole_words(text, shown, [r[1:] for r in rows])
