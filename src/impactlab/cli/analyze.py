"""``impactlab analyze``: marker tracks + dent scan -> e, mu, delta_p, sliding_length,
duration and mean_force."""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer
from rich.text import Text

from impactlab._display import field_row
from impactlab._validation import ImplausibleInputWarning
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli._common import (
    UserError,
    console,
    load_toml,
    parse_rod_table,
    print_rows,
)
from impactlab.cli.analyze_measurements import append_drop, check_measurements
from impactlab.cli.invert_inputs import check_measure
from impactlab.cli.printing import print_wrapped

if TYPE_CHECKING:
    from impactlab.experiment import ExperimentResult, MarkerGeometry

#: The start of ``Rod``'s warning of a mass that makes a uniform rod wider than its tip.
HEAVY_ROD_TEXT = "the diameter that the mass, length and density imply"


def _rod_from(spec: str | None) -> tuple[Rod, dict[str, Any]]:
    """(rod, the TOML data) from --rod: None/'paper' or a TOML file with a [rod] table."""
    if spec is None or spec.strip().lower() == "paper":
        return PAPER_ROD, {}
    path = Path(spec)
    data = load_toml(path, "--rod")
    table = data.get("rod")
    if not isinstance(table, dict):
        raise UserError(
            f"--rod {spec!r}: the file needs a [rod] table (mass, length, tip_radius, "
            "inertia), or use --rod paper"
        )
    vals = parse_rod_table(table, "rod.")
    missing = [k for k in ("mass", "length", "tip_radius") if k not in vals]
    if missing:
        raise UserError(f"[rod] of {spec} misses {', '.join(missing)}")
    with warnings.catch_warnings():  # analyze() reports it as the result's "rod:" doubt
        warnings.filterwarnings("ignore", HEAVY_ROD_TEXT, ImplausibleInputWarning)
        rod = Rod(
            length=vals["length"],
            tip_radius=vals["tip_radius"],
            mass=vals["mass"],
            inertia=vals.get("inertia"),
        )
    return rod, data


def _geometry_from(spec: str | None, rod_data: dict[str, Any]) -> MarkerGeometry | None:
    from impactlab.experiment import MarkerGeometry  # lazy: a fast CLI start

    data = load_toml(Path(spec), "--geometry") if spec is not None else rod_data
    table = data.get("markers")
    if table is None:
        if spec is not None:
            raise UserError(
                f"--geometry {spec!r}: the file needs a [markers] table "
                '(units = "mm", M1 = [x, y, z], ...)'
            )
        return None
    where = f"--geometry {spec!r}" if spec is not None else "the [markers] table of --rod"
    if not isinstance(table, dict):
        raise UserError(f'{where}: [markers] must be a table (units = "mm", M1 = [x, y, z], ...)')
    try:
        return MarkerGeometry.from_mapping(table)
    except (TypeError, ValueError) as exc:
        raise UserError(f"{where}: {exc}") from None


def analyze_cmd(
    markers: Path = typer.Argument(
        ...,
        help="Marker tracks: C3D (.c3d), or text (.csv, .txt or .tsv): impactlab's marker CSV, "
        "a Qualisys QTM TSV export or a Vicon Nexus CSV export (Trajectories).",
    ),
    scan: Path = typer.Argument(
        ..., help="Dent scan (X3P, SUR, PLU, DATX, VK, OPD, GWY, SDF, NetCDF, ..., .npy/.csv)."
    ),
    rod: str | None = typer.Option(
        None,
        "--rod",
        help="'paper' (default) or a TOML file with a [rod] table (mass, length, tip_radius, "
        "inertia) and optionally [markers].",
    ),
    flat: str | None = typer.Option(
        None,
        "--flat",
        help="Flat material (a library name such as aisi-1010, 'E=..., nu=..., Sy=..., rho=...' "
        "or a TOML file): also run the impact engine with the measured initial state, for "
        "comparison.",
    ),
    geometry: str | None = typer.Option(
        None,
        "--geometry",
        help="TOML file with a 'markers' table: the markers in the rod's body frame (origin at "
        "the centre of mass, x towards the tip); default: estimated.",
    ),
    up: str = typer.Option(
        "+z",
        "--up",
        help="The lab's upward axis in the marker data (+z, +y, ...), or a vector "
        "('0, 0.98, 0.17': a camera tilted from the vertical).",
    ),
    marker_units: str | None = typer.Option(
        None,
        "--marker-units",
        help="Length unit of the marker coordinates ('mm'): needed for a CSV file without a "
        "'# units:' line, which it must agree with otherwise; for a C3D file it replaces the "
        "POINT:UNITS parameter (a file that states a wrong unit).",
    ),
    pixel_size: str | None = typer.Option(
        None,
        "--pixel-size",
        help="Pixel size of a height map whose file does not state it ('2.5 um', with a "
        "decimal point; rectangular pixels: '2 um, 3 um', x then y, each with its unit); a file "
        "that states it must agree.",
    ),
    height_unit: str | None = typer.Option(
        None,
        "--height-unit",
        help="Height unit of a height map whose file does not state it ('um'); a file that "
        "states it must agree.",
    ),
    flip_heights: bool = typer.Option(
        False, "--flip-heights", help="The scan stores depths as heights: turn it over."
    ),
    out: Path | None = typer.Option(
        None,
        "--out",
        help="Directory for results.json and the figures (dent.png, kinematics.png); a file "
        "there that no analysis wrote is never removed or written over.",
    ),
    gravity: bool = typer.Option(
        False,
        "--gravity/--no-gravity",
        help="Gravity during the contact in the inversion (default: no, as the paper).",
    ),
    measure: str = typer.Option(
        "slip",
        "--measure",
        help="How the inversion reads the scan's Ls: 'slip' (default, the paper: the rod's "
        "material point at the contact) or 'travel' (the contact's travel, the mark's extent).",
    ),
    measurements: Path | None = typer.Option(
        None,
        "--measurements",
        help="Append this drop to a CSV measurements file for impactlab calibrate (created if "
        "missing): one line in the file's units, the rest of the file left as written "
        "(docs/calibrate.md). A result that is not ok is refused unless --include-doubtful.",
    ),
    label: str | None = typer.Option(
        None,
        "--label",
        help="The drop's label in --measurements (default: the marker file's name without "
        "its extension); a label the file has already is refused.",
    ),
    include_doubtful: bool = typer.Option(
        False,
        "--include-doubtful",
        help="Append a result that is not ok (a doubt, a failed stage) to --measurements "
        "anyway, after a '#' comment line naming why, with a warning.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (SI)."),
) -> None:
    """Analyse one drop: velocities before/after the impact from the marker tracks (e, mu,
    angle), the dent's depth and sliding length from the scan, and the impact duration T and
    mean force F from the paper's Eqs. 12 and 29.

    Partial results are printed and saved even when a file is bad; the exit status is then 2.
    A result in doubt (an estimated marker geometry that the impulse relation finds tilted or
    cannot check; a rod whose mass and inertia do not fit; a velocity change that implies e
    outside [0, 1]; a T or F that cannot be the impact's) says so (an "ok  no" row, a warning,
    "ok": false in --json) with exit status 0.

    With --measurements FILE.csv the drop is appended to that file as one row (its angle,
    incoming velocity and spin, mu, the rod, and e, spin_out, delta_p and the scar's length with
    their uncertainties), ready for impactlab calibrate.

    Examples:

    \b
      impactlab analyze drop.c3d dent.x3p --geometry markers.toml --out results/

    \b
      impactlab analyze drop20.c3d dent20.x3p --geometry markers.toml \\
        --measurements drops.csv --label d20
      impactlab calibrate drops.csv \\
        -p "flat_yield_strength=uniform(100 MPa, 1 GPa)"
    """
    from impactlab.experiment import analyze  # lazy: a fast CLI start
    from impactlab.experiment.checks import check_input_file, check_output_folder, output_folder
    from impactlab.experiment.profilometry.heightmap import pixel_pair

    rod_obj, rod_data = _rod_from(rod)
    geo = _geometry_from(geometry, rod_data)
    if label is not None and measurements is None:
        raise UserError("--label names the drop in --measurements: give --measurements FILE.csv")
    if include_doubtful and measurements is None:
        raise UserError(
            "--include-doubtful applies to --measurements: give --measurements FILE.csv"
        )
    name = label if label is not None else markers.stem
    if measurements is not None:
        check_measurements(measurements, name)
    measure = check_measure(measure, "--measure")  # before --out is made
    if pixel_size is not None:
        pixel_pair(pixel_size, "pixel_size (--pixel-size)")  # before --out is made
    if out is not None:
        check_output_folder(out, "--out")
    check_input_file(markers, "MARKERS")  # a misspelt path: nothing read, --out untouched
    check_input_file(scan, "SCAN")
    folder = output_folder(out, "--out") if out is not None else None
    with warnings.catch_warnings():  # the doubts: printed once, with the result's warnings
        warnings.filterwarnings("ignore", message="not ok: ", category=ImplausibleInputWarning)
        res = analyze(
            markers,
            scan,
            rod_obj,
            flat=flat,
            geometry=geo,
            up=up,
            marker_units=marker_units,
            pixel_size=pixel_size,
            height_unit=height_unit,
            flip_heights=flip_heights,
            out_dir=folder,
            gravity=gravity,
            measure=measure,
        )
    appended = (
        append_drop(measurements, res, name, include_doubtful) if measurements is not None else None
    )
    if as_json:
        options = {"rod": rod or "paper", "flat": flat, "geometry": geometry, "up": up,
                   "marker_units": marker_units, "pixel_size": pixel_size,
                   "height_unit": height_unit, "flip_heights": flip_heights,
                   "gravity": gravity, "measure": measure}  # fmt: skip
        from impactlab.experiment.result_json import analysis_json  # lazy: a fast CLI start

        print(json.dumps(analysis_json(res, options), indent=2))
        for w in res.warnings:  # on stderr too, as every command's with --json
            print_wrapped(f"warning: {w}")
    else:
        _print_summary(res)
    failed = "; ".join(f"{k}: {v}" for k, v in res.errors.items())
    if isinstance(appended, UserError | OSError):
        if failed:  # the stages' errors, that the summary points to, then why nothing appended
            print_wrapped(f"error: {failed}")
        raise appended
    if appended is not None:
        for w in appended[1]:
            print_wrapped(f"warning: {w}")
        typer.echo(f"appended drop {name!r} to {measurements} ({appended[0]} drops)", err=True)
    if failed:
        raise UserError(failed)


def _print_summary(res: ExperimentResult) -> None:
    """The measured quantities in display units (``impactlab._display``), then warnings and
    the files written."""
    from impactlab.experiment.result import model_rows  # loaded with analyze already

    rows = [field_row(k, est.value, est.unit, est.sigma) for k, est in res.summary().items()]
    if res.kinematics is not None:
        rows.append(("geometry", res.kinematics.geometry_source, ""))
    why = []
    if res.kinematics is not None and not res.kinematics.ok:
        why.append("the marker geometry is in doubt")
    if getattr(res, "implausible", None):  # (a result's stand-in may lack it)
        why.append("the result is implausible")
    see = ["the warnings"] if why else []
    if getattr(res, "errors", None):  # a stage failed: its error ends the output
        why.append(f"the {' and '.join(res.errors)} stage failed")
        see.append("the error")
    if why:
        rows.append(("ok", f"no: {' and '.join(why)} (see {' and '.join(see)})", ""))
    if res.dent is not None:
        name, text, unit = field_row("sliding_direction", res.dent.sliding_angle, "rad")
        ambiguous = " (ambiguous)" if res.dent.direction_ambiguous else ""
        rows.append((name, text + ambiguous, unit + " (scan x)"))
    rows += model_rows(res.model)
    names = (Path(p).name if p else "-" for p in (res.markers_path, res.scan_path))
    print_rows(rows, "impactlab analyze: " + " + ".join(names))
    for w in res.warnings:  # on stderr, as every command's warnings
        print_wrapped(f"warning: {w}")
    for name, path in {**res.figures, **res.files}.items():
        console.print(Text(f"saved {name}: {path}"))


def register(app: typer.Typer) -> None:
    """Add ``impactlab analyze`` to ``app``."""
    app.command("analyze")(analyze_cmd)
