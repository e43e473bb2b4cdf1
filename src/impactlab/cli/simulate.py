"""``impactlab simulate``: one impact of a rod or sphere on a flat, or (``--flexible``) the
drop of the flexible rod through ``impactlab.simulate(FlexibleRod(...))``.

Every given value is used and checked (a zero mass is an error, never the paper's mass); a rod
needs its angle, with a unit; options that do not apply to the body are refused; ``--material``
and ``--flat`` choose the material presets. The summary prints through ``impactlab._display``
(the fields and display units of ``print(result)``), ``--json`` in SI (docs/json-schema.md). The
result's warnings (``impactlab.flags``) go to stderr, one line each, and into ``--json``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import typer

from impactlab._compile_gc import garbage_deferred
from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod, Sphere
from impactlab.cli._common import (
    UserError,
    angle_quantity,
    as_option,
    check_rate_flat,
    check_rate_law,
    gravity_option,
    load_toml,
    positive,
    quantity,
    rate_name,
)
from impactlab.cli.config_file import (
    ConfigOptions,
    approach_worded,
    command_table,
    merge_config,
    option_material,
    refuse_given,
    renamed_options,
)
from impactlab.cli.config_values import option_numbers, plain_number, text
from impactlab.cli.drop_body import MODES_ALIASES, flexible_rod, paper_mass
from impactlab.cli.simulate_from import FROM_RULE, run_from
from impactlab.cli.simulate_help import HELP
from impactlab.cli.simulate_output import check_plot_folder, report_result
from impactlab.dynamics import ImpactResult, simulate
from impactlab.dynamics.drop import DEFAULT_TIME_LIMIT
from impactlab.dynamics.drop_checks import DropError
from impactlab.dynamics.drop_result import DropResult
from impactlab.friction import DEFAULT_MU
from impactlab.materials import AISI_201, AISI_1010

_KEYS = (
    "body",
    "angle",
    "vx",
    "vy",
    "speed",
    "incidence",
    "spin",
    "mu",
    "law",
    "friction",
    "inertia",
    "length",
    "radius",
    "mass",
    "diameter",
    "gravity",
    "constant_angle",
    "rtol",
    "partial_slip_cells",
    "law_params",
    "material",
    "flat",
    "flexible",
    "modes_axial",
    "modes_bending",
    "damping",
    "rate",
    "stop",
    "time_limit",
)
#: Options of a rod that a sphere does not have.
_ROD_ONLY = ("angle", "length", "inertia", "constant_angle", "diameter")
#: Options of the flexible rod (``--flexible``) only: its modes and their damping (no rigid
#: rod's), then those of any drop (``impactlab drop --rigid`` takes them).
_FLEX_ONLY = ("modes_axial", "modes_bending", "damping", "rate", "stop", "time_limit")
#: Options the flexible rod's drop does not have.
_NOT_FLEX = ("inertia", "constant_angle")
#: Command-line spelling of the keys whose option is not ``--<key>``.
_FLAGS = {
    "gravity": "--no-gravity/--gravity",
    "constant_angle": "--constant-angle/--no-constant-angle",
    "flexible": "--flexible/--rigid",
}
#: Keys of ``impactlab drop``'s config file that are not simulate's: why.
_NOTES = {"rigid": "impactlab drop's: simulate's rod is rigid unless flexible = true"}
_MISSING_ANGLE = (
    'a rod needs its angle to the flat: give --angle with a unit, e.g. --angle "20 deg" or '
    '--angle "0.35 rad" (or angle = "20 deg" in the --config file)'
)


def _merge(config: dict[str, Any], cli: dict[str, Any], config_path: Path | None) -> ConfigOptions:
    section = command_table(config, "simulate", "drop", str(config_path))
    return merge_config(section, cli, config_path, _KEYS, _FLAGS, _NOTES)


def _body(opt: ConfigOptions) -> tuple[Rod | Sphere | FlexibleRod, float | None]:
    """The body and the rod's angle [rad] (None for a sphere); defaults: the paper's rod."""
    kind = text(opt.values.get("body", "rod"), opt.label("body")).lower()
    if kind not in ("rod", "sphere"):
        raise UserError(f"body must be 'rod' or 'sphere', got {kind!r}")
    material = option_material(opt, "material", AISI_201)
    flexible = opt.given("flexible")
    if kind == "sphere":  # first: a hint to add --flexible would be refused for a sphere
        if opt.given("diameter"):  # a sphere's size: its radius, where --diameter was given
            raise UserError(
                f"{opt.label('diameter')} is a rod's; a sphere's size is its radius, "
                f'{opt.label("radius", "diameter")} (half the diameter, e.g. "5 mm")'
            )
        refuse_given(opt, _ROD_ONLY, "a sphere has no angle, length or inertia (simulate a rod)")
        refuse_given(
            opt,
            ("flexible", *_FLEX_ONLY),
            "a sphere has no drop options (modes, damping, rate, stop rule, time limit: a rod's "
            "drop, impactlab drop or impactlab simulate rod --flexible)",
        )
        sphere = Sphere(
            radius=opt.size_or("radius", "m", PAPER_ROD.tip_radius),
            mass=opt.size("mass", "kg"),
            material=material,
        )
        return sphere, None
    if not flexible:
        _refuse_drop_options(opt)
    if not opt.given("angle"):
        raise UserError(_MISSING_ANGLE)
    angle = angle_quantity(opt.values["angle"], opt.label("angle"))
    diameter, mass = opt.size("diameter", "m"), opt.size("mass", "kg")
    length = opt.size("length", "m")
    tip = opt.size_or("radius", "m", PAPER_ROD.tip_radius)
    sizes: dict[str, float | None] = {
        "length": PAPER_ROD.length if length is None else length,
        "tip_radius": tip,
        "mass": paper_mass(
            length is not None, mass, diameter, material, opt.label, tip != PAPER_ROD.tip_radius
        ),
        "diameter": diameter,
    }
    if flexible:
        refuse_given(
            opt,
            _NOT_FLEX,
            "the flexible rod's inertia follows from its modes, and its lever arms move",
        )
        return flexible_rod(opt.values, sizes, material, opt.label), angle
    rod = Rod(**sizes, material=material, inertia=opt.size("inertia", "kg*m^2"))  # type: ignore[arg-type]
    return rod, angle


def _refuse_drop_options(opt: ConfigOptions) -> None:
    """The rigid rod's refusal of the flexible rod's options, each pointing to what takes it:
    the modes and their damping to ``--flexible`` only (``drop --rigid`` has none), the rate,
    stop rule and time limit to ``--flexible`` or ``impactlab drop --rigid``."""
    groups = (
        (_FLEX_ONLY[:3], "only a drop has modes and modal damping, the flexible rod's: add {}"),
        (
            _FLEX_ONLY[3:],
            "only a drop has a rate-dependent flat, a stop rule or a time limit: add {}, "
            "run the rigid rod's drop (impactlab drop --rigid)",
        ),
    )
    for keys, why in groups:
        given = [k for k in keys if opt.given(k)]
        if given:
            them = "it" if len(given) == 1 else "them"
            flexible = opt.label("flexible", given[0])  # --flexible, or the file's key
            raise UserError(
                f"{', '.join(opt.label(k) for k in given)}: {why.format(flexible)} or leave "
                f"{them} out"
            )


def run_simulate(opt: ConfigOptions) -> ImpactResult | DropResult:
    """One impact (or, with ``--flexible``, the drop of the flexible rod) from the merged
    options (SI after parsing)."""
    body, rod_angle = _body(opt)
    cfg = opt.values
    velocity = opt.velocity()
    common: dict[str, Any] = {
        "flat": option_material(opt, "flat", AISI_1010),
        "law": text(cfg.get("law", "ghaednia"), opt.label("law")),
        "friction": text(cfg.get("friction", "coulomb"), opt.label("friction")),
        "mu": plain_number(cfg.get("mu", DEFAULT_MU), opt.label("mu")),
        "velocity": velocity,
        "spin": quantity(cfg.get("spin", 0.0), "rad/s", opt.label("spin")) or 0.0,
        "law_params": cfg.get("law_params"),
        "gravity": bool(cfg.get("gravity", True)),
        "rtol": None if cfg.get("rtol") is None else plain_number(cfg["rtol"], opt.label("rtol")),
    }
    if cfg.get("partial_slip_cells") is not None:  # checked by simulate (an integer, 4 to 64)
        common["partial_slip_cells"] = cfg["partial_slip_cells"]
    if isinstance(body, FlexibleRod):  # the drop: a DropResult
        rate = rate_name(text(cfg.get("rate", "none"), opt.label("rate")), opt.label("rate"))
        check_rate_flat(rate, common["flat"], opt.label("rate"))
        check_rate_law(rate, common["law"], opt.label("rate"), opt.label("law"))
        stop = text(cfg.get("stop", "sequence"), opt.label("stop"))
        limit = positive(cfg.get("time_limit"), "s", opt.label("time_limit"))
        return simulate(body, angle=rod_angle, rate=rate, stop=stop, history=False,
                        time_limit=DEFAULT_TIME_LIMIT if limit is None else limit,
                        **common)  # fmt: skip
    return simulate(
        body,
        angle=rod_angle,
        constant_angle=bool(cfg.get("constant_angle", False)),
        **common,
    )


#: Other spellings of an option (the rod's tip radius is tip_radius elsewhere, the mode counts
#: FlexibleRod's n_axial and n_bending).
_ALIASES = {"radius": ("--tip-radius",), **MODES_ALIASES}


def _option(key: str) -> Any:
    return typer.Option(None, "--" + key.replace("_", "-"), *_ALIASES.get(key, ()), help=HELP[key])


def simulate_cmd(
    body: str = typer.Argument(None, help="rod (the paper's rod by default) or sphere."),
    angle: str = _option("angle"),
    vy: str = _option("vy"),
    vx: str = _option("vx"),
    speed: str = _option("speed"),
    incidence: str = _option("incidence"),
    spin: str = _option("spin"),
    mu: str = typer.Option(
        None,
        "--mu",
        help=f"Friction coefficient (default {DEFAULT_MU:g}, as impactlab.simulate).",
    ),
    law: str = _option("law"),
    friction: str = _option("friction"),
    inertia: str = _option("inertia"),
    radius: str = _option("radius"),
    length: str = _option("length"),
    mass: str = _option("mass"),
    diameter: str = _option("diameter"),
    material: str = _option("material"),
    flat: str = _option("flat"),
    gravity: bool = gravity_option(),
    constant_angle: bool = typer.Option(
        None,
        "--constant-angle/--no-constant-angle",
        show_default=False,
        help="Freeze the lever arms (paper's assumption; rod only) or not (default).",
    ),
    flexible: bool = typer.Option(
        None,
        "--flexible/--rigid",
        show_default=False,
        help="The flexible rod: its whole drop, every contact (rod only); or the rigid rod "
        "(default).",
    ),
    modes_axial: int = _option("modes_axial"),
    modes_bending: int = _option("modes_bending"),
    damping: str = _option("damping"),
    rate: str = _option("rate"),
    stop: str = _option("stop"),
    time_limit: str = _option("time_limit"),
    t_max: str = typer.Option(None, "--t-max", hidden=True),  # --time-limit before 0.3
    rtol: str = typer.Option(None, "--rtol", help=HELP["rtol"]),
    partial_slip_cells: int = _option("partial_slip_cells"),
    config: Path = typer.Option(
        None, "--config", help="TOML file of these keys (or a 'simulate' table); options win."
    ),
    from_file: Path = typer.Option(None, "--from", help=FROM_RULE),
    as_json: bool = typer.Option(
        False, "--json", help="Machine-readable output, SI (docs/json-schema.md)."
    ),
    plot: bool = typer.Option(
        False, "--plot", help="Save force-time, force-penetration, contact-path and dent figures."
    ),
    out: Path = typer.Option(
        None,
        "--out",
        help="Folder of the --plot figures and their JSON result (only with --plot; default: "
        "the current one).",
    ),
) -> None:
    """Simulate one impact and print its summary (display units: um, ms, deg; --json: SI);
    warnings go to stderr.

    Examples:

    \b
      impactlab simulate rod --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 --plot

    \b
      impactlab simulate sphere --radius "5 mm" --vy "-1 m/s" --material aisi-1010

    \b
      impactlab simulate sphere --radius "3 mm" --speed "2.5 m/s" \\
        --incidence "30 deg" --material aisi-52100 --flat al-6061-t6

    \b
      impactlab simulate rod --flexible --angle "20 deg" --vy "-1.41 m/s" --mu 0.2
    """
    # the options named like the config file's keys, as given (None: not given)
    cli = {k: v for k, v in locals().items() if k in _KEYS}  # switches: True, False or None
    cli = option_numbers(cli, ("mu", "damping", "rtol"))
    cli = renamed_options(cli, {"t_max": t_max})
    if out is not None and not plot:
        raise UserError("--out applies only with --plot (where to save the figures)")
    if from_file is not None and config is not None:
        raise UserError(
            "--config and --from: --from takes the recorded input, with options on top; "
            "leave out --config"
        )
    folder = None
    if plot:  # checked before anything runs: the folder, and no user's file written over
        from impactlab.cli.output_paths import output_dir

        folder = output_dir(Path(".") if out is None else out, "--out")
        check_plot_folder(folder)
    # one impact or drop, then the process ends: a first compile's garbage is left to the exit
    with garbage_deferred():
        if from_file is not None:
            result = run_from(from_file, cli)
            if plot and isinstance(result, DropResult):
                raise UserError("--plot: the flexible rod's drop has no figures here; leave it out")
        opt = _merge(load_toml(config, "--config"), cli, config)
        if plot and opt.given("flexible"):
            raise UserError("--plot: the flexible rod's drop has no figures here; leave it out")
        if from_file is None:
            try:
                result = run_simulate(opt)
            except UserError as exc:  # named already; a mass that does not fit: as typed
                raise UserError(approach_worded(str(exc), opt)) from None
            except ValueError as exc:  # the API's message names its parameter: name the option
                if isinstance(exc, DropError):  # "raise time_limit": the option's spelling
                    raise UserError(exc.worded(opt.label)) from None
                message = approach_worded(str(exc), opt)  # --vy, --spin as typed
                raise UserError(as_option(message, _KEYS, opt.label)) from None
        report_result(result, out=folder, as_json=as_json)


def register(app: typer.Typer) -> None:
    """Add ``impactlab simulate`` to ``app``."""
    app.command("simulate")(simulate_cmd)
