"""``impactlab explain``: which physics explains measured drops, nothing tuned.

impactlab explain DROPS.csv|DROPS.toml [--law NAME] [--rate LAW ...] [--json] [--out DIR]
                  [--quiet]

Each drop runs with the rigid body, the flexible rod and the flexible rod on a rate-dependent
flat (docs/explain.md); the table sets every measured value beside each prediction (z, within 2
sigma), and a verdict line per drop says which configuration explains it best, that the one
ranked first is itself inconsistent with the measurements, or that none agrees. ``--out DIR``
writes explain.csv and explain.json there (a file of that name that impactlab explain did not
write, or a folder that cannot be made or written, stops the command before any work)."""

from __future__ import annotations

import contextlib
import json
import sys
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.text import Text

from impactlab.cli._common import UserError, console
from impactlab.cli.printing import print_wrapped

_RATE_HELP = (
    "The rate-dependent rows' law, the flat's own constants, e.g. "
    '"cowper-symonds(D=6500 1/s, q=4)" or "johnson-cook(C=0.03, rate0=1 1/s)"; repeatable, '
    "for several; 'none': no rate row. Default: the library's Cowper-Symonds (upper estimate) and "
    "Johnson-Cook (lower) on a low-carbon steel flat only."
)


def _progress(quiet: bool) -> tuple[Any, Any]:
    """(progress callback, the rich Progress to stop) on stderr, or (None, None). The bar
    starts with a report and leaves stderr as it is (no redirection): before a compile notice
    is shown it gives way (``impactlab._compile_notice.gives_way``), so the notice keeps one
    line, its counter updated in place, and the next report brings the bar back."""
    if quiet:
        return None, None
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress

    bar = Progress("{task.description}", BarColumn(), MofNCompleteColumn(),
                   console=Console(stderr=True), transient=True,
                   redirect_stderr=False)  # fmt: skip
    task: list[Any] = []

    def report(configuration: str, done: int, total: int) -> None:
        if not bar.live.is_started:
            bar.start()
        if not task:
            task.append(bar.add_task("explain", total=total))
        bar.update(task[0], completed=done, description=configuration)

    return report, bar


def _show(explanation: Any, out: Any = None) -> None:
    """The table on stdout (``cli.tables.show_table``: whole into a pipe or a file; on a
    terminal too narrow for it, turned per drop, the measured values beside each part)."""
    from impactlab.cli.tables import show_table

    head, rows = explanation.display_rows()
    title = f"which physics explains the drops ({explanation.law}/{explanation.friction}, "
    left = ("drop", "configuration", "flags", "status")
    right = [h for h in head if h not in left]
    show_table(title + "nothing tuned)", head, rows, right=right, group=0, label=1, pin=True,
               out=out)  # fmt: skip


def explain_cmd(
    measurements: Annotated[
        Path,
        typer.Argument(
            metavar="MEASUREMENTS", help="Measurements file (CSV or TOML, docs/calibrate.md)."
        ),
    ],
    law: Annotated[str, typer.Option(help="Contact law of every configuration.")] = "ghaednia",
    rate: Annotated[
        list[str] | None, typer.Option("--rate", metavar="RATE", help=_RATE_HELP)
    ] = None,
    out: Annotated[
        Path | None, typer.Option(help="Folder for explain.csv and explain.json.")
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
    quiet: Annotated[
        bool, typer.Option("--quiet/--no-quiet", "-q", help="No progress display.")
    ] = False,
) -> None:
    """Which physics explains measured drops: the rigid body, the flexible rod and the flexible
    rod on a rate-dependent flat, nothing tuned, beside every measured value.

    Example: impactlab explain examples/data/paper_drops.csv --out explained
    """
    from impactlab._compile_notice import gives_way
    from impactlab.explain import configurations, explain, save_explanation
    from impactlab.explain.saving import check_folder

    if out is not None:
        try:
            check_folder(out, "--out")  # before any work
        except (FileExistsError, NotADirectoryError, PermissionError) as exc:
            raise UserError(str(exc)) from None
    report, bar = _progress(quiet)
    try:
        configurations(rate, "--rate")  # its errors name the option
        with gives_way(bar) if bar is not None else contextlib.nullcontext():
            result = explain(measurements, law=law, rate_laws=rate, progress=report)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    finally:
        if bar is not None and bar.live.is_started:
            bar.stop()
    files = save_explanation(result, out, "--out") if out is not None else {}
    if as_json:
        doc = result.to_dict()
        doc["files"] = {k: str(v) for k, v in files.items()}
        print(json.dumps(doc, indent=2))
        return
    _show(result)
    for drop in dict.fromkeys(result.summary["drop"]):  # the verdicts say the "best: " notes
        print_wrapped(f"verdict ({drop}): {result.verdict(drop).reason}", sys.stdout)
    for note in (*_stated(), *(n for n in result.notes if not n.startswith("best: "))):
        print_wrapped(f"note: {note}", sys.stdout)
    for k, v in files.items():
        console.print(Text(f"{k}: {v}"), soft_wrap=True)
    sys.stdout.flush()


def _stated() -> tuple[str, str]:
    from impactlab.explain.result import NOTHING_TUNED, Z_DEFINITION

    return NOTHING_TUNED, Z_DEFINITION


def register(app: typer.Typer) -> None:
    """Add ``impactlab explain`` to ``app``."""
    app.command("explain")(explain_cmd)
