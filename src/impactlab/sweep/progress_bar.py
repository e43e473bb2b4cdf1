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
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)

from impactlab._compile_notice import gives_way

__all__ = ["progress_bar"]


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
            TextColumn("[bold]{task.description}"),
            BarColumn(),
            MofNCompleteColumn(),
            TextColumn("impacts"),
            TextColumn("{task.fields[rate]}"),
            TimeElapsedColumn(),
            TextColumn("ETA"),
            TimeRemainingColumn(),
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
