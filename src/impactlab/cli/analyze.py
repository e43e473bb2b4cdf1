"""``impactlab analyze``: marker tracks + dent scan -> e, mu, delta_p, L_s, T and F."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import typer

from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli._common import UserError, console, emit, load_toml, quantity
from impactlab.experiment import ExperimentResult, MarkerGeometry, analyze

_ROD_FIELDS: dict[str, str] = {"mass": "kg", "length": "m", "tip_radius": "m", "inertia": "kg*m^2"}

# display: key -> (scale, unit, label)
_DISPLAY: dict[str, tuple[float, str, str]] = {
    "e": (1.0, "", "e (tip, normal)"),
    "mu": (1.0, "", "mu (Eq. 28)"),
    "angle": (180.0 / math.pi, "deg", "angle at impact"),
    "v_i": (1.0, "m/s", "v_i (tip, vertical)"),
    "v_c_in_x": (1.0, "m/s", "v_Cx before"),
    "v_c_in_y": (1.0, "m/s", "v_Cy before"),
    "v_c_out_x": (1.0, "m/s", "v_Cx after"),
    "v_c_out_y": (1.0, "m/s", "v_Cy after"),
    "spin_out": (1.0, "rad/s", "spin after"),
    "dv_cy": (1.0, "m/s", "dv_Cy"),
    "delta_p": (1e6, "um", "delta_p (max depth)"),
    "L_s": (1e6, "um", "L_s (length - width)"),
    "pileup": (1e6, "um", "pile-up height"),
    "T": (1e3, "ms", "T (Eq. 12)"),
    "F": (1.0, "N", "F (Eq. 29)"),
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
    vals: dict[str, float] = {}
    for k, v in table.items():
        if k not in _ROD_FIELDS:
            raise UserError(
                f"unknown key {k!r} in [rod] of {spec}; allowed: {', '.join(_ROD_FIELDS)}"
            )
        q = quantity(v, _ROD_FIELDS[k], f"rod.{k}")
        assert q is not None
        vals[k] = q
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
        ...,
        help="Profilometer scan of the dent (X3P, SUR, PLU, "
        "DATX, VK, OPD, GWY, SDF, NetCDF, ... or plain .npy/.csv).",
    ),
    rod: str | None = typer.Option(
        None,
        "--rod",
        help="'paper' (default) or a TOML file "
        "with a [rod] table (mass, length, tip_radius, inertia) "
        "and optionally [markers].",
    ),
    flat: str | None = typer.Option(
        None,
        "--flat",
        help="Flat material preset (e.g. "
        "aisi-1010): also run the impact engine with the "
        "measured initial state, for comparison.",
    ),
    geometry: str | None = typer.Option(
        None,
        "--geometry",
        help="TOML file with a 'markers'"
        " table: the markers in the rod's body frame (origin "
        "at the centre of mass, x towards the tip); default: "
        "estimated.",
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
        out_dir=out,
        gravity=gravity,
    )
    if as_json:
        emit(res.to_dict(), as_json=True)
    else:
        _print_summary(res, f"impactlab analyze: {markers.name} + {scan.name}")
    if res.errors:
        raise UserError("; ".join(f"{k}: {v}" for k, v in res.errors.items()))


def _print_summary(res: ExperimentResult, title: str) -> None:
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
        shown = {
            "e": (1.0, ""),
            "delta_p": (1e6, "um"),
            "sliding_length": (1e6, "um"),
            "duration": (1e3, "ms"),
            "spin_out": (1.0, "rad/s"),
        }
        for k, v in res.model.items():
            if isinstance(v, float) and k in shown:
                scale, unit = shown[k]
                data[f"model {k} ({res.model['law']})"] = f"{v * scale:.5g}"
                units[f"model {k} ({res.model['law']})"] = unit
    emit(data, as_json=False, title=title, units=units)
    for w in res.warnings:
        console.print(f"warning: {w}")
    for name, path in {**res.figures, **res.files}.items():
        console.print(f"saved {name}: {path}")


def register(app: typer.Typer) -> None:
    """Add ``impactlab analyze`` to ``app``."""
    app.command("analyze")(analyze_cmd)
