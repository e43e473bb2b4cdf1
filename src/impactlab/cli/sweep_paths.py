"""The files of ``impactlab sweep run`` and ``impactlab sweep export``, checked before any work
starts (``--out`` a store, ``--netcdf`` and the export's file: a suffix it knows, a place it
can write, and no file of the user's written over), and the end of a run none of whose cases
succeeded (on stderr, exit status 2)."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from impactlab.cli._common import UserError
from impactlab.cli.output_paths import output_file, output_store

if TYPE_CHECKING:
    from impactlab.sweep import SweepResult

__all__ = ["check_export_file", "check_run_paths", "export_suffix", "refuse_none_ok"]


def export_suffix(path: Path, name: str, formats: tuple[str, ...], hint: str = "") -> str:
    """The export format of ``path`` (``sweep.netcdf.check_suffix``) or a UserError."""
    from impactlab.sweep.netcdf import check_suffix

    try:
        return check_suffix(path, name, formats)
    except ValueError as exc:
        raise UserError(f"{exc}{hint}") from None


def check_export_file(path: Path, name: str) -> Path:
    """The file ``path`` that ``name`` asks to write (``output_file``): UserError too when it
    exists and no sweep export wrote it (``sweep.netcdf.check_replaceable``)."""
    from impactlab.sweep.netcdf import check_replaceable

    output_file(path, name)
    try:
        check_replaceable(path, name)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    return path


def check_run_paths(out: Path | None, netcdf: Path | None) -> None:
    """--out (a store) and --netcdf (a NetCDF file: .nc, .nc4) can be written, before the study
    runs."""
    if out is not None:
        output_store(out, "--out")
    if netcdf is not None:
        csv = f"; for a CSV table: impactlab sweep export STORE {netcdf.with_suffix('.csv')}"
        if netcdf.name.startswith(".") and not netcdf.suffix:  # ".nc": no name to keep
            csv = ""
        export_suffix(netcdf, "--netcdf", ("NetCDF-4",), csv)
        check_export_file(netcdf, "--netcdf")
        from impactlab.sweep.netcdf import require_netcdf

        require_netcdf()  # before the study runs


def refuse_none_ok(res: SweepResult, ds: Any) -> None:
    """One line on stderr and exit status 2 when no case of the sweep succeeded (status 0):
    every case refused or failed, its status counts named (the store keeps them)."""
    from impactlab.sweep import status_counts

    counts = status_counts(ds)
    if any(n for key, n in counts.items() if key.partition(":")[0] == "0"):
        return
    parts = "; ".join(f"{n} with status {key}" for key, n in counts.items() if n)
    print(
        f"error: no case of study {res.study.name!r} succeeded ({parts}); the store "
        f"{str(res.path)!r} keeps them (impactlab sweep info {res.path})",
        file=sys.stderr,
    )
    raise typer.Exit(2)
