"""``impactlab simulate``: one impact of a rod or sphere on a flat."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import typer

from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.cli._common import UserError, console, emit, field_units, load_toml, quantity
from impactlab.dynamics import ImpactResult, simulate
from impactlab.dynamics.plotting import save_figures
from impactlab.friction import DEFAULT_MU
from impactlab.units import angle_to_rad

_KEYS = (
    "body",
    "angle",
    "vx",
    "vy",
    "spin",
    "mu",
    "law",
    "friction",
    "inertia",
    "length",
    "radius",
    "mass",
    "gravity",
    "constant_angle",
    "rtol",
    "law_params",
)


def _angle(value: Any) -> float:
    """An angle: a bare number is in degrees (as the --angle help says), else a quantity."""
    try:
        return math.radians(float(value))
    except (TypeError, ValueError):
        return angle_to_rad(value, name="angle")


def _merge(config: dict[str, Any], cli: dict[str, Any]) -> dict[str, Any]:
    section = config.get("simulate", config)
    unknown = sorted(set(section) - set(_KEYS))
    if unknown:
        raise UserError(f"unknown key(s) {unknown} in the config file; known: {list(_KEYS)}")
    merged = dict(section)
    merged.update({k: v for k, v in cli.items() if v is not None})
    return merged


def _body(cfg: dict[str, Any]) -> tuple[Rod | Sphere, float | None]:
    """The body and the rod's angle [rad] (None for a sphere); defaults: the paper's rod."""
    kind = str(cfg.get("body", "rod")).lower()
    if kind not in ("rod", "sphere"):
        raise UserError(f"body must be 'rod' or 'sphere', got {kind!r}")
    R = quantity(cfg.get("radius"), "m", "radius")
    m = quantity(cfg.get("mass"), "kg", "mass")
    if kind == "sphere":
        return Sphere(radius=R or PAPER_ROD.tip_radius, mass=m), None
    rod = Rod(
        length=quantity(cfg.get("length"), "m", "length") or PAPER_ROD.length,
        tip_radius=R or PAPER_ROD.tip_radius,
        mass=m or PAPER_ROD.mass,
        inertia=quantity(cfg.get("inertia"), "kg*m^2", "inertia"),
    )
    return rod, _angle(cfg.get("angle", "20 deg"))


def run_simulate(cfg: dict[str, Any]) -> ImpactResult:
    """One impact from the merged options (config file < command line; SI after parsing)."""
    body, angle = _body(cfg)
    if cfg.get("vy") is None:
        raise UserError('--vy is required, e.g. --vy "-1.41 m/s"')
    vyv = quantity(cfg.get("vy"), "m/s", "vy")
    vxv = quantity(cfg.get("vx", 0.0), "m/s", "vx")
    w = quantity(cfg.get("spin", 0.0), "rad/s", "spin")
    return simulate(
        body,
        law=str(cfg.get("law", "ghaednia")),
        friction=str(cfg.get("friction", "coulomb")),
        mu=float(cfg.get("mu", DEFAULT_MU)),
        angle=angle,
        velocity=(vxv or 0.0, vyv or 0.0),
        spin=w or 0.0,
        law_params=cfg.get("law_params"),
        gravity=bool(cfg.get("gravity", True)),
        constant_angle=bool(cfg.get("constant_angle", False)),
        rtol=cfg.get("rtol"),
    )


def _report(result: ImpactResult, *, plot: bool, out: Path, as_json: bool) -> None:
    data = {k: v for k, v in result.to_dict().items() if k not in ("velocity_in", "velocity_out")}
    data["vx_out"], data["vy_out"] = result.velocity_out
    files: list[str] = []
    if plot:
        files = [str(p) for p in save_figures(result, out)]
        (out / "impact_result.json").write_text(json.dumps(data, indent=2, default=str))
        files.append(str(out / "impact_result.json"))
    if as_json:
        emit({**data, "files": files}, as_json=True)
        return
    emit(data, as_json=False, title="impact", units=field_units(data))
    for f in files:
        console.print(f"saved {f}")


def simulate_cmd(
    body: str = typer.Argument(None, help="rod (the paper's rod by default) or sphere."),
    angle: str = typer.Option(
        None, "--angle", help='Rod angle to the flat, e.g. "20 deg" (a bare number is in degrees).'
    ),
    vy: str = typer.Option(None, "--vy", help='Vertical velocity, e.g. "-1.41 m/s".'),
    vx: str = typer.Option(None, "--vx", help="Horizontal velocity (default 0)."),
    spin: str = typer.Option(
        None, "--spin", help='Angular velocity, e.g. "5 rad/s" (counter-clockwise positive).'
    ),
    mu: float = typer.Option(
        None, "--mu", help=f"Friction coefficient (default {DEFAULT_MU:g}, as in the Python API)."
    ),
    law: str = typer.Option(None, "--law", help="Contact law (default ghaednia)."),
    friction: str = typer.Option(
        None, "--friction", help="impulse_ratio, coulomb (default) or mindlin."
    ),
    inertia: str = typer.Option(
        None, "--inertia", help='Rod I_C, e.g. "0.0036 kg*m^2" (default m L^2/12).'
    ),
    radius: str = typer.Option(
        None, "--radius", help="Tip / sphere radius (default the paper's 8.8 mm)."
    ),
    length: str = typer.Option(None, "--length", help="Rod length (default 0.3048 m)."),
    mass: str = typer.Option(
        None, "--mass", help="Mass (rod default 0.4607 kg; sphere default from the density)."
    ),
    no_gravity: bool = typer.Option(False, "--no-gravity", help="Switch gravity off."),
    constant_angle: bool = typer.Option(
        False, "--constant-angle", help="Freeze the lever arms (paper's assumption)."
    ),
    config: Path = typer.Option(
        None,
        "--config",
        help="TOML file with these keys "
        "(optionally under a 'simulate' table); options override it.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output."),
    plot: bool = typer.Option(
        False,
        "--plot",
        help="Save force-time, force-penetration, contact-path and dent figures (PNG and PDF).",
    ),
    out: Path = typer.Option(Path("."), "--out", help="Directory for --plot and the JSON result."),
) -> None:
    """Simulate one impact and print the result summary (SI units).

    Example: impactlab simulate rod --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 --plot
    """
    cfg = _merge(
        load_toml(config),
        {
            "body": body,
            "angle": angle,
            "vx": vx,
            "vy": vy,
            "spin": spin,
            "mu": mu,
            "law": law,
            "friction": friction,
            "inertia": inertia,
            "radius": radius,
            "length": length,
            "mass": mass,
            "gravity": False if no_gravity else None,
            "constant_angle": True if constant_angle else None,
        },
    )
    _report(run_simulate(cfg), plot=plot, out=out, as_json=as_json)


def register(app: typer.Typer) -> None:
    """Add ``impactlab simulate`` to ``app``."""
    app.command("simulate")(simulate_cmd)
