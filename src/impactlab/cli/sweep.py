"""``impactlab sweep``: run grids and Monte Carlo studies into a resumable Zarr store.

    impactlab sweep STUDY.toml [--out store.zarr] [--scheduler tcp://host:port] [--workers N]
                    [--backend threads|processes|dask] [--restart] [--quiet]
                    [--netcdf out.nc] [--plot DIR]
    impactlab sweep uncertainty STUDY.toml|STORE [--json] [...]
    impactlab sweep info STORE
    impactlab sweep plot STORE --out DIR
    impactlab sweep export STORE OUT.nc
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer
from typer.core import TyperGroup

from impactlab.cli._common import UserError, emit


class _DefaultRun(TyperGroup):
    """``impactlab sweep STUDY.toml ...`` means ``impactlab sweep run STUDY.toml ...``."""

    def parse_args(self, ctx: Any, args: list[str]) -> list[str]:
        first = next((a for a in args if not a.startswith("-")), None)
        if first is not None and first not in self.commands:
            args = ["run", *args]
        return super().parse_args(ctx, args)


def _status_counts(ds: Any) -> dict[str, int]:
    msgs = ds.attrs.get("status_messages", {})
    codes, counts = np.unique(np.asarray(ds["status"].values), return_counts=True)
    return {f"{int(c)}: {msgs.get(str(int(c)), '?')}": int(n)
            for c, n in zip(codes, counts, strict=True)}


def _run(study_path: Path, out: Path | None, scheduler: str | None, workers: int | None,
         backend: str | None, quiet: bool, restart: bool) -> Any:
    from impactlab.sweep import Study, run_sweep

    study = Study.from_toml(study_path)
    try:
        return run_sweep(study, out, scheduler=scheduler, workers=workers, backend=backend,
                         quiet=quiet, restart=restart)
    except (OSError, TimeoutError) as exc:
        if scheduler is not None:
            raise UserError(f"cannot use the Dask scheduler {scheduler!r}: {exc}") from None
        raise
    except RuntimeError as exc:
        if "impactlab.dynamics.batch" in str(exc):
            raise UserError(str(exc)) from None
        raise


def _report_uncertainty(ds: Any, outputs: list[str] | None, percentiles: list[float] | None,
                        as_json: bool) -> None:
    from impactlab.sweep import Study, format_report, uncertainty_report

    spec = None
    try:
        spec = Study.from_dict(json.loads(ds.attrs["study"])).uncertainty
    except (KeyError, ValueError):
        spec = None
    outs = outputs or (list(spec.outputs) if spec else None)
    pcts = percentiles or (list(spec.percentiles) if spec else [2.5, 50.0, 97.5])
    grid_dims = [d for d in ds.dims if d != "sample"]
    points: list[dict[str, int]] = [{}]
    for d in grid_dims:
        points = [{**p, d: i} for p in points for i in range(ds.sizes[d])]
    reports = {}
    for p in points:
        sub = ds.isel(p) if p else ds
        title = ", ".join(f"{d} = {sub[d].values!s}" for d in p) or str(ds.attrs.get("title"))
        reports[title] = uncertainty_report(sub, outs, None, pcts)
    if as_json:
        print(json.dumps({k: r.to_dict() for k, r in reports.items()}, indent=2, default=float))
        return
    for title, rep in reports.items():
        print(format_report(rep, title=f"uncertainty: {title}"))


_Out = Annotated[Path | None, typer.Option(
    "--out", "-o", help="Zarr store (default: ./NAME.zarr, NAME: the study name or file name).")]
_Scheduler = Annotated[str | None, typer.Option(
    "--scheduler", help="Dask scheduler address, tcp://host:port.")]
_Workers = Annotated[int | None, typer.Option(
    "--workers", "-w", min=1, help="Local cores to use (default: all).")]
_Quiet = Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar, no summary.")]
_Json = Annotated[bool, typer.Option("--json", help="Machine-readable output.")]
_Store = Annotated[Path, typer.Argument(help="A sweep's Zarr store.")]


def register(app: typer.Typer) -> None:
    sweep_app = typer.Typer(
        cls=_DefaultRun,
        help="Grids and Monte Carlo studies of many impacts into a resumable Zarr store "
             "(impactlab sweep STUDY.toml; see docs/sweep.md).",
        no_args_is_help=True,
    )

    @sweep_app.command("run")
    def run(
        study: Annotated[Path, typer.Argument(help="Study file (TOML), see examples/.")],
        out: _Out = None,
        scheduler: _Scheduler = None,
        workers: _Workers = None,
        backend: Annotated[str | None, typer.Option(
            "--backend", help="threads (default), processes or dask.")] = None,
        restart: Annotated[bool, typer.Option(
            "--restart", help="Discard a store of a different study, start fresh.")] = False,
        quiet: _Quiet = False,
        netcdf: Annotated[Path | None, typer.Option(
            "--netcdf", help="Also export to NetCDF.")] = None,
        plot: Annotated[Path | None, typer.Option(
            "--plot", help="Write plots into this folder.")] = None,
        as_json: _Json = False,
    ) -> None:
        """Run (or resume) the sweep of a study file.

        Example: impactlab sweep examples/study-regime-map.toml --out map.zarr --plot plots/
        """
        res = _run(study, out, scheduler, workers, backend, quiet, restart)
        ds = res.dataset
        if netcdf is not None:
            from impactlab.sweep import export_netcdf

            export_netcdf(ds, netcdf)
        files = []
        if plot is not None:
            from impactlab.sweep import plot_sweep

            files = [str(f) for f in plot_sweep(ds, plot)]
        if res.study.uncertainty is not None and not quiet:
            _report_uncertainty(ds, None, None, as_json=False)
        if quiet and not as_json:
            return
        s = res.stats
        summary = {
            "store": str(res.path),
            "cases": s.n_cases,
            "chunks": s.n_chunks,
            "chunks_resumed": s.chunks_before,
            "chunks_computed": s.chunks_computed,
            "wall_time": s.wall_s,
            "throughput": s.throughput,
            "backend": s.backend,
            "status": _status_counts(ds),
        }
        if netcdf is not None:
            summary["netcdf"] = str(netcdf)
        if files:
            summary["plots"] = files
        emit(summary, as_json=as_json, title=f"sweep {res.study.name}",
             units={"wall_time": "s", "throughput": "impacts/s"})

    @sweep_app.command("uncertainty")
    def uncertainty(
        source: Annotated[Path, typer.Argument(
            help="A Monte Carlo study file, or its Zarr store.")],
        out: _Out = None,
        scheduler: _Scheduler = None,
        workers: _Workers = None,
        outputs: Annotated[list[str] | None, typer.Option(
            "--output", help="Output to report (repeatable).")] = None,
        percentiles: Annotated[list[float] | None, typer.Option(
            "--percentile", help="Percentile (repeatable).")] = None,
        quiet: _Quiet = False,
        as_json: _Json = False,
    ) -> None:
        """Spread of e, delta_p, L_s, T, F over a Monte Carlo sample and the inputs that drive it.

        Example: impactlab sweep uncertainty examples/study-uncertainty.toml
        """
        from impactlab.sweep import open_sweep

        if source.is_dir():
            ds = open_sweep(source)
        else:
            ds = _run(source, out, scheduler, workers, None, quiet or as_json, False).dataset
        _report_uncertainty(ds, outputs, percentiles, as_json)

    @sweep_app.command("info")
    def info(
        store: _Store,
        as_json: _Json = False,
    ) -> None:
        """Progress and contents of a store (chunks done, status counts)."""
        from impactlab.sweep import SweepStore, open_sweep

        ds = open_sweep(store)
        done = len(SweepStore(store).done_chunks())
        data = {
            "title": ds.attrs.get("title"),
            "study_hash": ds.attrs.get("study_hash"),
            "mode": ds.attrs.get("mode"),
            "dims": {str(k): int(v) for k, v in ds.sizes.items()},
            "cases": ds.attrs.get("n_cases"),
            "chunks_done": f"{done} of {ds.attrs.get('n_chunks')}",
            "outputs": list(ds.attrs.get("outputs", [])),
            "status": _status_counts(ds),
        }
        emit(data, as_json=as_json, title=str(store))

    @sweep_app.command("plot")
    def plot_cmd(
        store: _Store,
        out: Annotated[Path, typer.Option("--out", "-o", help="Folder for the PNG files.")],
    ) -> None:
        """Regime map (with mu_c), maps of e, delta_p, L_s, T over angle and velocity."""
        from impactlab.sweep import open_sweep, plot_sweep

        files = plot_sweep(open_sweep(store), out)
        if not files:
            raise UserError(
                "nothing to plot: the sweep needs an 'angle' dimension (with 'mu' for the "
                "regime map) or a 'sample' dimension"
            )
        for f in files:
            print(f)

    @sweep_app.command("export")
    def export(
        store: _Store,
        target: Annotated[Path, typer.Argument(help="NetCDF file to write.")],
    ) -> None:
        """Export a store to NetCDF-4."""
        from impactlab.sweep import export_netcdf, open_sweep

        export_netcdf(open_sweep(store), target)
        print(target, file=sys.stdout)

    app.add_typer(sweep_app, name="sweep")
