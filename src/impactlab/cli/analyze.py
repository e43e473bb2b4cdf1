"""``impactlab analyze``: marker tracks + dent scan -> e, mu, delta_p, L_s, T and F."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import typer

from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli._common import UserError, console, emit, load_toml, parse_rod_table, show
from impactlab.experiment import ExperimentResult, MarkerGeometry, analyze
from impactlab.experiment.checks import output_folder

#: The labels of the summary's quantities, by display unit (SI value x scale).
_LABELS: dict[tuple[float, str], dict[str, str]] = {
    (1.0, ""): {"e": "e (tip, normal)", "mu": "mu (Eq. 28)"},
    (180.0 / math.pi, "deg"): {"angle": "angle at impact"},
    (1.0, "m/s"): {
        "v_i": "v_i (tip, vertical)",
        "v_c_in_x": "v_Cx before",
        "v_c_in_y": "v_Cy before",
        "v_c_out_x": "v_Cx after",
        "v_c_out_y": "v_Cy after",
        "dv_cy": "dv_Cy",
    },
    (1.0, "rad/s"): {"spin_out": "spin after"},
    (1e6, "um"): {
        "delta_p": "delta_p (max depth)",
        "L_s": "L_s (length - width)",
        "pileup": "pile-up height",
    },
    (1e3, "ms"): {"T": "T (Eq. 12)"},
    (1.0, "N"): {"F": "F (Eq. 29)"},
}
#: display: key -> (scale, unit, label)
_DISPLAY = {k: (sc, u, lab) for (sc, u), labels in _LABELS.items() for k, lab in labels.items()}
#: the engine comparison's fields: name -> (scale, unit)
_MODEL = {
    "e": (1.0, ""),
    "delta_p": (1e6, "um"),
    "sliding_length": (1e6, "um"),
    "duration": (1e3, "ms"),
    "spin_out": (1.0, "rad/s"),
}


def _rod_from(spec: str | None) -> tuple[Rod, dict[str, Any]]:
    """(rod, the TOML data) from --rod: None/'paper' or a TOML file with a [rod] table."""
    if spec is None or spec.strip().lower() == "paper":
        return PAPER_ROD, {}
    path = Path(spec)
    data = load_toml(path)
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
    rod = Rod(
        length=vals["length"],
        tip_radius=vals["tip_radius"],
        mass=vals["mass"],
        inertia=vals.get("inertia"),
    )
    return rod, data


def _geometry_from(spec: str | None, rod_data: dict[str, Any]) -> MarkerGeometry | None:
    data = load_toml(Path(spec)) if spec is not None else rod_data
    table = data.get("markers")
    if table is None:
        if spec is not None:
            raise UserError(
                f"--geometry {spec!r}: the file needs a [markers] table "
                '(units = "mm", M1 = [x, y, z], ...)'
            )
        return None
    if not isinstance(table, dict):
        raise UserError('[markers] must be a table (units = "mm", M1 = [x, y, z], ...)')
    return MarkerGeometry.from_mapping(table)


def analyze_cmd(
    markers: Path = typer.Argument(..., help="Marker tracks: C3D (.c3d) or CSV (.csv)."),
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
        help="Flat material preset (e.g. aisi-1010): also run the impact engine with the "
        "measured initial state, for comparison.",
    ),
    geometry: str | None = typer.Option(
        None,
        "--geometry",
        help="TOML file with a 'markers' table: the markers in the rod's body frame (origin at "
        "the centre of mass, x towards the tip); default: estimated.",
    ),
    up: str = typer.Option(
        "+z", "--up", help="The lab's upward axis in the marker data (+z, +y, ...)."
    ),
    marker_units: str | None = typer.Option(
        None, "--marker-units", help="Length unit of the marker coordinates when the file has none."
    ),
    pixel_size: str | None = typer.Option(
        None, "--pixel-size", help="Pixel size of a plain height map ('2 um')."
    ),
    height_unit: str | None = typer.Option(
        None, "--height-unit", help="Height unit of a plain height map ('um')."
    ),
    flip_heights: bool = typer.Option(
        False, "--flip-heights", help="The scan stores depths as heights: turn it over."
    ),
    out: Path | None = typer.Option(
        None, "--out", help="Directory for results.json and the figures (dent.png, kinematics.png)."
    ),
    gravity: bool = typer.Option(
        False,
        "--gravity/--no-gravity",
        help="Gravity during the contact in the inversion (default: no, as the paper).",
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (SI)."),
) -> None:
    """Analyse one drop: velocities before/after the impact from the marker tracks (e, mu,
    angle), the dent's depth and sliding length from the scan, and the impact duration T and
    mean force F from the paper's Eqs. 12 and 29.

    Partial results are printed and saved even when a file is bad; the exit status is then 2.

    Example: impactlab analyze drop.c3d dent.x3p --geometry markers.toml --out results/
    """
    rod_obj, rod_data = _rod_from(rod)
    geo = _geometry_from(geometry, rod_data)
    folder = output_folder(out, "--out") if out is not None else None
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
    )
    show(res, as_json=as_json, table=_print_summary)
    if res.errors:
        raise UserError("; ".join(f"{k}: {v}" for k, v in res.errors.items()))


def _print_summary(res: ExperimentResult) -> None:
    """The measured quantities in display units, then warnings and the files written."""
    summ = res.summary()
    data: dict[str, Any] = {}
    units: dict[str, str] = {}
    for key, est in summ.items():
        scale, unit, label = _DISPLAY.get(key, (1.0, est.unit, key))
        s = f"{est.value * scale:.5g}"
        if est.sigma > 0:
            s += f" ± {est.sigma * scale:.2g}"
        data[label] = s
        units[label] = unit
    if res.kinematics is not None:
        data["geometry"] = res.kinematics.geometry_source
    if res.dent is not None:
        data["sliding direction"] = f"{res.dent.sliding_angle:.1f}" + (
            " (ambiguous)" if res.dent.direction_ambiguous else ""
        )
        units["sliding direction"] = "deg (scan x)"
    if res.model is not None:
        for k, v in res.model.items():
            if isinstance(v, float) and k in _MODEL:
                scale, unit = _MODEL[k]
                data[f"model {k} ({res.model['law']})"] = f"{v * scale:.5g}"
                units[f"model {k} ({res.model['law']})"] = unit
    names = (Path(p).name if p else "-" for p in (res.markers_path, res.scan_path))
    title = "impactlab analyze: " + " + ".join(names)
    emit(data, as_json=False, title=title, units=units)
    for w in res.warnings:
        console.print(f"warning: {w}")
    for name, path in {**res.figures, **res.files}.items():
        console.print(f"saved {name}: {path}")


def register(app: typer.Typer) -> None:
    """Add ``impactlab analyze`` to ``app``."""
    app.command("analyze")(analyze_cmd)
