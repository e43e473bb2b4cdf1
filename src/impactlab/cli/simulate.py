"""``impactlab simulate``: one impact of a rod or sphere on a flat.

Every given value is used and checked (a zero mass is an error, never the paper's mass); a rod
needs its angle, with a unit; options that do not apply to the body are refused. The result's
warnings (``impactlab.flags``) go to stderr, one line each, and into ``--json``.
"""

from __future__ import annotations

import json
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import typer

from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.cli._common import (
    UserError,
    angle_quantity,
    console,
    emit,
    field_units,
    load_toml,
    positive,
    quantity,
)
from impactlab.dynamics import ImpactResult, simulate
from impactlab.dynamics.plotting import save_figures
from impactlab.experiment.checks import output_folder
from impactlab.flags import ResultFlag
from impactlab.friction import DEFAULT_MU

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
#: Options of a rod that a sphere does not have.
_ROD_ONLY = ("angle", "length", "inertia", "constant_angle")
#: Command-line spelling of the keys whose option is not ``--<key>``.
_FLAGS = {"gravity": "--no-gravity", "constant_angle": "--constant-angle"}
_MISSING_ANGLE = (
    'a rod needs its angle to the flat: give --angle with a unit, e.g. --angle "20 deg" or '
    '--angle "0.35 rad" (or angle = "20 deg" in the --config file)'
)


@dataclass(frozen=True)
class _Options:
    """The merged options (config file < command line) and where each came from."""

    values: dict[str, Any]
    from_cli: frozenset[str]
    config: str

    def label(self, key: str) -> str:
        """How the user wrote ``key``: "--mass" or "mass (in case.toml)"."""
        if key in self.from_cli:
            return _FLAGS.get(key, "--" + key.replace("_", "-"))
        return f"{key} (in {self.config})"

    def given(self, key: str) -> bool:
        return self.values.get(key) not in (None, False)

    def size(self, key: str, unit: str) -> float | None:
        """The given positive quantity (None: not given)."""
        return positive(self.values.get(key), unit, self.label(key))

    def size_or(self, key: str, unit: str, default: float) -> float:
        """The given positive quantity, else ``default``."""
        value = self.size(key, unit)
        return default if value is None else value


def _merge(config: dict[str, Any], cli: dict[str, Any], config_path: Path | None) -> _Options:
    section = config.get("simulate", config)
    unknown = sorted(set(section) - set(_KEYS))
    if unknown:
        raise UserError(f"unknown key(s) {unknown} in the config file; known: {list(_KEYS)}")
    given = {k: v for k, v in cli.items() if v is not None}
    return _Options({**section, **given}, frozenset(given), str(config_path))


def _body(opt: _Options) -> tuple[Rod | Sphere, float | None]:
    """The body and the rod's angle [rad] (None for a sphere); defaults: the paper's rod."""
    kind = str(opt.values.get("body", "rod")).lower()
    if kind not in ("rod", "sphere"):
        raise UserError(f"body must be 'rod' or 'sphere', got {kind!r}")
    if kind == "sphere":
        extra = [opt.label(k) for k in _ROD_ONLY if opt.given(k)]
        if extra:
            raise UserError(
                f"{', '.join(extra)}: a sphere has no angle, length or inertia; leave "
                f"{'it' if len(extra) == 1 else 'them'} out (or simulate a rod)"
            )
        sphere = Sphere(
            radius=opt.size_or("radius", "m", PAPER_ROD.tip_radius), mass=opt.size("mass", "kg")
        )
        return sphere, None
    if not opt.given("angle"):
        raise UserError(_MISSING_ANGLE)
    rod = Rod(
        length=opt.size_or("length", "m", PAPER_ROD.length),
        tip_radius=opt.size_or("radius", "m", PAPER_ROD.tip_radius),
        mass=opt.size_or("mass", "kg", PAPER_ROD.mass),
        inertia=opt.size("inertia", "kg*m^2"),
    )
    return rod, angle_quantity(opt.values["angle"], opt.label("angle"))


def run_simulate(opt: _Options) -> ImpactResult:
    """One impact from the merged options (SI after parsing)."""
    body, rod_angle = _body(opt)
    cfg = opt.values
    if cfg.get("vy") is None:
        raise UserError('--vy is required, e.g. --vy "-1.41 m/s"')
    vyv = quantity(cfg.get("vy"), "m/s", opt.label("vy"))
    vxv = quantity(cfg.get("vx", 0.0), "m/s", opt.label("vx"))
    w = quantity(cfg.get("spin", 0.0), "rad/s", opt.label("spin"))
    return simulate(
        body,
        law=str(cfg.get("law", "ghaednia")),
        friction=str(cfg.get("friction", "coulomb")),
        mu=float(cfg.get("mu", DEFAULT_MU)),
        angle=rod_angle,
        velocity=(vxv or 0.0, vyv or 0.0),
        spin=w or 0.0,
        law_params=cfg.get("law_params"),
        gravity=bool(cfg.get("gravity", True)),
        constant_angle=bool(cfg.get("constant_angle", False)),
        rtol=cfg.get("rtol"),
    )


def _flag_names(flags: int) -> str:
    names = [str(f.name).lower() for f in ResultFlag if f.value and flags & f.value]
    return ", ".join(names) or "none"


def _report(result: ImpactResult, *, out: Path | None, as_json: bool, sphere: bool) -> None:
    hidden = {"velocity_in", "velocity_out", *(("angle", "angle_out") if sphere else ())}
    data = {k: v for k, v in result.to_dict().items() if k not in hidden}
    data["vx_out"], data["vy_out"] = result.velocity_out
    for text in result.warnings:
        print(f"warning: {text}", file=sys.stderr)
    files: list[str] = []
    if out is not None:
        files = [str(p) for p in save_figures(result, out)]
        (out / "impact_result.json").write_text(json.dumps(data, indent=2, default=str))
        files.append(str(out / "impact_result.json"))
    if as_json:
        emit({**data, "files": files}, as_json=True)
        return
    table = {k: v for k, v in data.items() if k != "warnings"}
    table["flags"] = _flag_names(int(data.get("flags", 0)))
    emit(table, as_json=False, title="impact", units=field_units(table))
    for f in files:
        console.print(f"saved {f}")


#: Help of the options that are keys of the config file.
_HELP = {
    "angle": 'Rod angle to the flat with its unit, "20 deg" or "0.35 rad" (a rod needs it).',
    "vy": 'Vertical velocity, e.g. "-1.41 m/s" (required).',
    "vx": "Horizontal velocity (default 0).",
    "spin": 'Angular velocity, e.g. "5 rad/s" (counter-clockwise positive; default 0).',
    "law": "Contact law (default ghaednia).",
    "friction": "impulse_ratio, coulomb (default) or mindlin.",
    "inertia": 'Rod I_C, e.g. "0.0036 kg*m^2" (default m L^2/12).',
    "radius": "Tip / sphere radius (default the paper's 8.8 mm).",
    "length": "Rod length (default 0.3048 m).",
    "mass": "Mass (rod default 0.4607 kg; sphere default from the density).",
}


def _option(key: str) -> Any:
    return typer.Option(None, "--" + key, help=_HELP[key])


def simulate_cmd(
    body: str = typer.Argument(None, help="rod (the paper's rod by default) or sphere."),
    angle: str = _option("angle"),
    vy: str = _option("vy"),
    vx: str = _option("vx"),
    spin: str = _option("spin"),
    mu: float = typer.Option(
        None, "--mu", help=f"Friction coefficient (default {DEFAULT_MU:g}, as in the Python API)."
    ),
    law: str = _option("law"),
    friction: str = _option("friction"),
    inertia: str = _option("inertia"),
    radius: str = _option("radius"),
    length: str = _option("length"),
    mass: str = _option("mass"),
    no_gravity: bool = typer.Option(False, "--no-gravity", help="Switch gravity off."),
    constant_angle: bool = typer.Option(
        False, "--constant-angle", help="Freeze the lever arms (paper's assumption; rod only)."
    ),
    config: Path = typer.Option(
        None, "--config", help="TOML file of these keys (or a 'simulate' table); options win."
    ),
    as_json: bool = typer.Option(
        False, "--json", help="Machine-readable output (with the result's flags and warnings)."
    ),
    plot: bool = typer.Option(
        False, "--plot", help="Save force-time, force-penetration, contact-path and dent figures."
    ),
    out: Path = typer.Option(
        None, "--out", help="Folder for --plot and the JSON result (default: the current one)."
    ),
) -> None:
    """Simulate one impact and print the result summary (SI units); warnings go to stderr.

    Example: impactlab simulate rod --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 --plot
    """
    # the options named like the config file's keys, as given (None: not given)
    cli = {k: v for k, v in locals().items() if k in _KEYS}
    cli["gravity"] = False if no_gravity else None
    cli["constant_angle"] = True if constant_angle else None
    if out is not None and not plot:
        raise UserError("--out applies only with --plot (where to save the figures)")
    opt = _merge(load_toml(config), cli, config)
    folder = output_folder(Path(".") if out is None else out, "--out") if plot else None
    sphere = str(opt.values.get("body", "rod")).lower() == "sphere"
    _report(run_simulate(opt), out=folder, as_json=as_json, sphere=sphere)


def register(app: typer.Typer) -> None:
    """Add ``impactlab simulate`` to ``app``."""
    app.command("simulate")(simulate_cmd)
