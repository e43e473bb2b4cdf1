"""The progress bar of a sweep run on stderr (count, rate, elapsed, ETA); it gives way to the
engine's compile notice (``impactlab._compile_notice.gives_way``) and comes back with the next
chunk."""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.table import Column

from impactlab._compile_notice import gives_way

__all__ = ["progress_bar"]

#: The bar's narrowest width, and the widest rate it makes room for ("1,234,567/s").
_MIN_BAR, _RATE = 10, 11


def bar_columns(total: int, width: int) -> list[ProgressColumn]:
    """The bar's columns on a terminal ``width`` wide: the study's name cut with an ellipsis
    to leave the count, rate, elapsed time and ETA (for ``total`` impacts) whole."""
    count = 2 * len(str(total)) + 1  # "done/total"
    # count, "impacts", rate, elapsed, "ETA", remaining; a space between each two of 8 columns
    numbers = count + len("impacts") + _RATE + 7 + len("ETA") + 7 + 7
    name = max(8, width - numbers - _MIN_BAR)

    def whole(min_width: int = 0) -> Column:
        return Column(no_wrap=True, min_width=min_width)

    return [
        TextColumn(
            "[bold]{task.description}",
            table_column=Column(no_wrap=True, overflow="ellipsis", max_width=name),
        ),
        BarColumn(),
        MofNCompleteColumn(table_column=whole(count)),
        TextColumn("impacts", table_column=whole()),
        TextColumn("{task.fields[rate]}", table_column=whole(_RATE)),
        TimeElapsedColumn(table_column=whole(7)),
        TextColumn("ETA", table_column=whole()),
        TimeRemainingColumn(table_column=whole(7)),
    ]


@contextmanager
def progress_bar(
    total: int, done: int, label: str, mode: bool | None
) -> Iterator[Callable[[int], None]]:
    """A rich progress bar on stderr (count, rate, elapsed, ETA). ``mode``: None = when stderr is
    a terminal, True = always, False = never."""
    if mode is False:
        yield lambda n: None
        return
    console = Console(stderr=True, force_terminal=True if mode else None)
    if not console.is_terminal:
        yield lambda n: None
        return
    with (
        Progress(
            *bar_columns(total, console.width),
            console=console,
            transient=False,
            redirect_stderr=False,  # a compile notice: the bar gives way to it (gives_way)
        ) as prog,  # fmt: skip
        gives_way(prog),
    ):
        task = prog.add_task(label, total=total, completed=done, rate="")
        t0 = time.perf_counter()
        count = [0]

        def advance(n: int) -> None:
            if not prog.live.is_started:  # after a compile notice
                prog.start()
            count[0] += n
            dt = time.perf_counter() - t0
            rate = f"{count[0] / dt:,.0f}/s" if dt > 0 else ""
            prog.update(task, advance=n, rate=rate)

        yield advance
