"""``impactlab sweep``: run grids and Monte Carlo studies into a resumable Zarr store.

impactlab sweep STUDY.toml [--out store.zarr] [--scheduler tcp://host:port] [--workers N]
                [--backend threads|processes|dask] [--restart] [--quiet]
                [--netcdf out.nc] [--plot DIR] [--max-cases N] [--worker-timeout S]
impactlab sweep uncertainty STUDY.toml|STORE [--json] [...]
impactlab sweep info STORE
impactlab sweep plot STORE --out DIR
impactlab sweep export STORE OUT.csv|OUT.nc
"""

from __future__ import annotations

import json
import os
import re
import sys
import warnings
from pathlib import Path
from typing import Annotated, Any

import typer

from impactlab._json import to_json
from impactlab._oserror import system_error_line as _system_error_line
from impactlab.cli._common import SI_UNITS, UserError, emit
from impactlab.cli.output_paths import existing_store, output_dir
from impactlab.cli.printing import print_wrapped, versioned
from impactlab.cli.sweep_group import DefaultRun
from impactlab.cli.sweep_paths import (
    check_export_file,
    check_run_paths,
    export_suffix,
    refuse_none_ok,
)
from impactlab.cli.sweep_run import Where, check_uncertainty_study, run_study
from impactlab.cli.sweep_summary import (
    info_table,
    print_uncertainty,
    run_summary,
    uncertainty_json,
    warn_incomplete,
)
from impactlab.flags import invalidating_names

# impactlab.sweep (Zarr, xarray, pandas, scipy.stats: about 1 s) is imported inside the commands
# that use it, so that ``impactlab --help`` and the other commands start without it.

#: ``--worker-timeout``'s default as its help states it; equal to
#: ``impactlab.sweep.backends.DEFAULT_WORKER_TIMEOUT`` (tests/core/test_cli_main.py).
WORKER_TIMEOUT_HELP_DEFAULT = 60


_Out = Annotated[
    Path | None,
    typer.Option(
        "--out", "-o", help="Zarr store (default: ./NAME.zarr, NAME: the study name or file name)."
    ),
]
_Scheduler = Annotated[
    str | None, typer.Option("--scheduler", help="Dask scheduler address, tcp://host:port.")
]
_Workers = Annotated[
    int | None,
    typer.Option("--workers", "-w", min=1, metavar="N", help="Local cores to use (default: all)."),
]
_MaxCases = Annotated[
    int | None,
    typer.Option(
        "--max-cases",
        min=1,
        metavar="N",
        help="Largest number of cases accepted (default: the study's max_cases, 100 million).",
    ),
]
_Quiet = Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar, no summary.")]
_Json = Annotated[bool, typer.Option("--json", help="Machine-readable output.")]
_Store = Annotated[Path, typer.Argument(metavar="STORE", help="A sweep's Zarr store.")]


sweep_app = typer.Typer(
    cls=DefaultRun,
    help="Grids and Monte Carlo studies of many impacts into a resumable Zarr store "
    "(impactlab sweep STUDY.toml; see docs/sweep.md).\n\n"
    "Example: impactlab sweep examples/study-regime-map.toml --out map.zarr",
    no_args_is_help=True,
)


@sweep_app.command("run", short_help="Run (or resume) the sweep of a study file.")
def run_cmd(
    study: Annotated[
        Path, typer.Argument(metavar="STUDY", help="Study file (TOML), see examples/.")
    ],
    out: _Out = None,
    scheduler: _Scheduler = None,
    workers: _Workers = None,
    backend: Annotated[
        str | None, typer.Option("--backend", help="threads (default), processes or dask.")
    ] = None,
    restart: Annotated[
        bool, typer.Option("--restart", help="Discard a store of a different study, start fresh.")
    ] = False,
    max_cases: _MaxCases = None,
    worker_timeout: Annotated[
        float | None,
        typer.Option(
            "--worker-timeout",
            min=0.001,
            metavar="SECONDS",
            help="Dask: seconds without any worker before the sweep stops with an error "
            f"(default: {WORKER_TIMEOUT_HELP_DEFAULT}).",
        ),
    ] = None,
    quiet: _Quiet = False,
    netcdf: Annotated[
        Path | None,
        typer.Option(
            "--netcdf",
            help="Also export to NetCDF-4 (.nc, .nc4; needs pip install 'impactlab[netcdf]').",
        ),
    ] = None,
    plot: Annotated[
        Path | None, typer.Option("--plot", help="Write plots into this folder.")
    ] = None,
    as_json: _Json = False,
) -> None:
    """Run (or resume) the sweep of a study file.

    Example:

    \b
      impactlab sweep examples/study-regime-map.toml --out map.zarr --plot plots/
    """
    from impactlab.experiment.checks import output_folder
    from impactlab.sweep import export_netcdf, plot_sweep

    check_run_paths(out, netcdf)
    if plot is not None:  # before the sweep: a folder no file can be made in is refused now
        plot = output_dir(plot, "--plot")  # made once the sweep ran (none for a refused one)
    where = Where(out, scheduler, workers, max_cases, worker_timeout, backend)
    res = run_study(study, where, quiet, restart)
    ds = res.dataset
    if netcdf is not None:
        export_netcdf(ds, netcdf)
    files: list[str] = []
    failed = None  # the sweep is stored: a failed plot still lets the summary print
    try:
        if plot is not None:
            files = [str(f) for f in _plots(plot_sweep, ds, output_folder(plot, "--plot"))]
    except Exception as exc:
        if os.environ.get("IMPACTLAB_DEBUG"):
            raise
        why = _system_error_line(exc) if isinstance(exc, OSError) else str(exc)
        failed = f"error: --plot {plot}: {why} (the study's results are stored in {res.path})"
    monte_carlo = res.study.uncertainty is not None
    if as_json:  # one JSON document on stdout: a Monte Carlo study's report inside it
        doc = to_json(run_summary(res, ds, netcdf, files, as_json=True), SI_UNITS)
        if monte_carlo:
            doc["uncertainty"] = uncertainty_json(ds)
        print(json.dumps(versioned(doc), indent=2))
    elif not quiet:
        if monte_carlo:
            print_uncertainty(ds, None, None, as_json=False)
        summary = run_summary(res, ds, netcdf, files, as_json=False)
        emit(summary, as_json=False, title=f"sweep {res.study.name}")
    if failed is not None:
        print_wrapped(failed)
        raise typer.Exit(1)
    refuse_none_ok(res, ds)  # every case refused or failed: say so, exit status 2


@sweep_app.command(
    "uncertainty", short_help="Spread of e, delta_p, L_s, T, F over a Monte Carlo sample."
)
def uncertainty_cmd(
    source: Annotated[
        Path,
        typer.Argument(metavar="SOURCE", help="A Monte Carlo study file, or its Zarr store."),
    ],
    outputs: Annotated[
        list[str] | None,
        typer.Option(
            "--output",
            metavar="OUTPUT",
            help="Output to report, a quantity (e, delta_p, L_s, T, F, ...; not the codes "
            "regime and flags); repeatable: --output e --output T.",
        ),
    ] = None,
    percentiles: Annotated[
        list[float] | None,
        typer.Option(
            "--percentile",
            metavar="PCT",
            help="Percentile to report, in [0, 100]; repeatable: --percentile 5 --percentile 95.",
        ),
    ] = None,
    out: _Out = None,
    scheduler: _Scheduler = None,
    workers: _Workers = None,
    max_cases: _MaxCases = None,
    quiet: _Quiet = False,
    as_json: _Json = False,
    include_flagged: Annotated[
        bool,
        typer.Option(
            "--include-flagged",
            help=f"Keep the cases flagged as not plain success ({invalidating_names()}); by "
            "default they are excluded and counted.",
        ),
    ] = False,
) -> None:
    """Spread of e, delta_p, L_s, T, F over a Monte Carlo sample and the inputs that drive it.

    Example: impactlab sweep uncertainty examples/study-uncertainty.toml
    """
    from impactlab.sweep import open_sweep

    outputs = list(dict.fromkeys(outputs)) if outputs else outputs  # each once, in order
    for p in percentiles or ():  # before any case is computed
        if not 0 <= p <= 100:
            raise UserError(f"--percentile {p:g}: a percentile lies in [0, 100]")
    if source.is_dir():
        ds = open_sweep(source)
        warn_incomplete(source)
    else:
        if not source.exists() and source.suffix == ".zarr":
            raise UserError(
                f"sweep store {str(source)!r} does not exist: give a Monte Carlo study file "
                "(TOML) or the Zarr store it ran into"
            )
        if source.is_file() and source.suffix.lower() in _EXPORTS:
            raise UserError(
                f"{str(source)!r} is a file, not a sweep store (a folder written by impactlab "
                "sweep): give a Monte Carlo study file (TOML) or the Zarr store it ran into"
            )
        check_run_paths(out, None)
        check_uncertainty_study(source, max_cases)  # before any case is computed
        where = Where(out, scheduler, workers, max_cases)
        res = run_study(source, where, quiet or as_json, False)
        ds = res.dataset
        warn_incomplete(res.path)
    try:
        print_uncertainty(ds, outputs, percentiles, as_json, include_flagged)
    except UserError:
        raise
    except ValueError as exc:  # the API's words for an output: named as --output
        raise UserError(_output_worded(str(exc))) from None


#: The suffixes of a sweep's exports (NetCDF, CSV): files that are neither a study nor a store.
_EXPORTS = (".nc", ".nc4", ".csv")


#: ``uncertainty_reports``' refusals of the outputs asked for (``impactlab.sweep.uncertainty``).
_OUTPUTS = re.compile(r"output\(s\) \[(?P<names>.*)\] not in the sweep(?P<rest>; .*)", re.DOTALL)


def _output_worded(message: str) -> str:
    """``output(s) ['foo'] not in the sweep; ...`` as ``--output 'foo': not in the sweep;
    ...``; ``output 'flags' holds ...`` as ``--output 'flags' holds ...``; others as they are."""
    found = _OUTPUTS.fullmatch(message)
    if found is not None:
        return f"--output {found['names']}: not in the sweep{found['rest']}"
    return "--" + message if message.startswith("output '") else message


@sweep_app.command("info", short_help="Progress and contents of a store.")
def info_cmd(
    store: _Store,
    as_json: _Json = False,
) -> None:
    """Progress and contents of a store (chunks done, status counts, each law's range).

    Example: impactlab sweep info map.zarr
    """
    from impactlab.sweep import store_info

    path = existing_store(store)
    info = store_info(path)  # the --json values; the table formats them
    emit(versioned(info) if as_json else info_table(info), as_json=as_json, title=str(store))


@sweep_app.command("plot", short_help="Regime map, maps and histograms of a store (PNG).")
def plot_cmd(
    store: _Store,
    out: Annotated[Path, typer.Option("--out", "-o", help="Folder for the PNG files.")],
) -> None:
    """Regime map (with mu_c on angle x mu), maps of e, delta_p, L_s, T over the swept inputs
    (angle, mu, velocities; sphere studies too), histograms of samples; names what it cannot
    draw and why.

    Example: impactlab sweep plot map.zarr --out plots/
    """
    from impactlab.experiment.checks import output_folder
    from impactlab.sweep import open_sweep, plot_sweep

    folder = output_dir(out, "--out")  # before the store is read: refused at once
    ds = open_sweep(existing_store(store))
    warn_incomplete(store)
    skipped: list[str] = []
    files = _plots(plot_sweep, ds, output_folder(folder, "--out"), skipped)
    if not files:
        raise UserError("nothing to plot: " + "; ".join(skipped))
    for f in files:
        print(f)


def _plots(plot_sweep: Any, ds: Any, folder: Path, skipped: list[str] | None = None) -> list[Any]:
    """``plot_sweep(ds, folder)``; each plot it could not draw named on stderr (one line, with
    the reason) and in ``skipped``; with ``skipped`` given and no plot drawn the caller says
    why instead."""
    from impactlab.sweep import PlotSkipped

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlotSkipped)
        files = plot_sweep(ds, folder)
    reasons = [str(w.message) for w in caught if w.category is PlotSkipped]
    for w in caught:
        if w.category is not PlotSkipped:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    if skipped is not None:
        skipped.extend(r.removeprefix("not plotted: ") for r in reasons)
    if files or skipped is None:
        for reason in reasons:
            print_wrapped(reason)
    return list(files)


@sweep_app.command("export", short_help="Export a store to a CSV table or NetCDF-4 file.")
def export_cmd(
    store: _Store,
    target: Annotated[
        Path,
        typer.Argument(
            metavar="TARGET",
            help="File to write: .csv (a table, units in the header), .nc/.nc4.",
        ),
    ],
) -> None:
    """Export a store to a CSV table (.csv: one row per case) or NetCDF-4 (.nc, .nc4).

    Example: impactlab sweep export map.zarr map.csv
    """
    from impactlab.sweep import export_file, open_sweep

    if target.is_dir():  # a folder is no file of either kind: named as the target
        raise UserError(
            f"target {str(target)!r} is a folder: give the name of the file to write, ending "
            "in .csv (CSV), .nc or .nc4 (NetCDF-4)"
        )
    export_suffix(target, "export file", ("CSV", "NetCDF-4"))
    csv = target.suffix.lower() == ".csv"
    check_export_file(target, "the CSV file" if csv else "the NetCDF file")
    export_file(open_sweep(existing_store(store)), target)
    warn_incomplete(store)  # its cases not computed yet are in the file as status -1
    print(target, file=sys.stdout)


def register(app: typer.Typer) -> None:
    """Add ``impactlab sweep`` and its subcommands to ``app``."""
    app.add_typer(sweep_app, name="sweep")
