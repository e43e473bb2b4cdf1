"""``impactlab reproduce``: regenerate the seed paper's tables, figures and the report."""

from __future__ import annotations

import typer


def reproduce_cmd(
    out: str = typer.Option(
        "reproduction",
        "--out",
        help="Folder to write into (created; "
        "a non-empty folder must come from a previous reproduction, whose files this run "
        "does not write are removed).",
    ),
    no_simulate: bool = typer.Option(
        False, "--no-simulate", help="Skip the simulations (analytic part only)."
    ),
) -> None:
    """Reproduce the paper (doi:10.1007/s00419-015-1108-2): Tables 2-4 side by side with
    impactlab's numbers, Figs. 4 and 5, force plots, and report.md / report.html.

    Example: impactlab reproduce --out reproduction
    """
    from impactlab.paper.quantities import (  # lazy: a fast start
        duration_checks,
        extrapolation_line,
        summary_line,
    )
    from impactlab.paper.reproduction import prepare_output, reproduce

    # the folder checked (and refused) under the option's name, before any computation
    res = reproduce(prepare_output(out, "--out"), simulate=not no_simulate)
    for c in duration_checks(res.experimental):
        typer.echo(c.text())
    # the numbers reproduced, undecided, not reproduced and (--no-simulate) not compared
    typer.echo(summary_line(res.comparison))
    if not no_simulate:
        typer.echo(extrapolation_line(res.simulations))
    if no_simulate:
        typer.echo("simulations skipped (--no-simulate): analytic part only")
    # the analytic part compiles nothing: the engine's first compilation only with simulations
    first = "" if no_simulate else "; a first run's includes compiling the engine"
    typer.echo(
        f"report: {res.report_md} and {res.report_html} (reproduced in "
        f"{res.elapsed_s:.1f} s after the imports{first})"
    )


def register(app: typer.Typer) -> None:
    """Add ``impactlab reproduce`` to ``app``."""
    app.command("reproduce")(reproduce_cmd)
