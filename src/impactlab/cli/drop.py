"""``impactlab drop``: the drop of a flexible rod (the paper's by default) or, with ``--rigid``,
of the rigid rod on a flat, through the whole contact sequence (``simulate_drop``).

Any rod (length L between the end-sphere centres, tip radius, mass and/or diameter), any body
material and any flat (``--material``/``--flat``: a library name, properties or a TOML file).
Quantities carry units as in ``impactlab simulate``; the angle is required, with its unit; the
velocity is --vy (and --vx) or --speed and --incidence. Options that do not apply (mode counts
or damping with ``--rigid``, ``--inertia`` without it) are refused. ``--config`` reads the
options' keys from a TOML file (at the top level or in a ``[drop]`` table; the command line
wins), with ``impactlab simulate``'s rules (``cli.config_file``).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any, cast

import typer

from impactlab._json import jsonable, to_json
from impactlab.bodies import PAPER_ROD
from impactlab.cli._common import (
    KINEMATIC_HELP,
    SI_UNITS,
    STOP_HELP,
    UserError,
    angle_quantity,
    as_option,
    check_rate_flat,
    check_rate_law,
    emit,
    gravity_option,
    length_help,
    load_toml,
    positive,
    quantity,
    rate_help,
    rate_name,
)
from impactlab.cli.config_file import (
    ConfigOptions,
    approach_worded,
    command_table,
    merge_config,
    option_material,
    renamed_options,
)
from impactlab.cli.config_values import option_numbers, plain_number, text
from impactlab.cli.drop_body import MODES_ALIASES, MODES_HELP, drop_body
from impactlab.cli.drop_contacts import print_contacts
from impactlab.cli.printing import print_wrapped
from impactlab.cli.simulate_from import run_from
from impactlab.dynamics.drop import DEFAULT_TIME_LIMIT, simulate_drop
from impactlab.dynamics.drop_checks import DropError
from impactlab.dynamics.drop_result import UNITS, DropResult
from impactlab.friction import DEFAULT_MU
from impactlab.materials import AISI_1010


def missing_as_nan(data: Any, units: Mapping[str, str]) -> Any:
    """``data`` with each None (a value that does not exist, also in a pair) under a key with a
    unit made NaN: the JSON writes it as a quantity of value null (docs/json-schema.md)."""
    if isinstance(data, list) and any(isinstance(v, Mapping) for v in data):
        return [missing_as_nan(v, units) for v in data]
    if not isinstance(data, Mapping):
        return data
    out = {}
    for k, v in data.items():
        if k in units and (v is None or (isinstance(v, list) and None in v)):
            v = math.nan if v is None else [math.nan if x is None else x for x in v]
        out[k] = missing_as_nan(v, units)
    return out


def report_drop(result: DropResult, *, as_json: bool) -> None:
    """Print a drop: JSON (SI, docs/json-schema.md), or the contact table and the totals."""
    if as_json:
        balance = {key: "J" for key in result.energy_balance}  # its terms, by name
        units = {**SI_UNITS, **UNITS, **balance}
        data = result.to_dict()
        recorded = data.pop("input")  # the call as recorded: --from reads it back as it is
        doc = to_json(missing_as_nan(data, units), units) | {"input": jsonable(recorded)}
        print(json.dumps(doc, indent=2))
        return
    print_contacts(result)
    emit(result.summary(), as_json=False, title="drop", units=result.display_units())


#: The help of ``--config``: the file's form, and why a [simulate] table is not read.
CONFIG_HELP = (
    "TOML file of these options by key (--modes-axial 16: modes_axial = 16, or n_axial = 16; "
    "--no-gravity: gravity = false; --rigid: rigid = true; a material: a name, a table or a "
    "TOML file, from this file's folder), at the top level or in a [drop] table; options given "
    "here win (a velocity, either form, replaces the file's; --gravity and --flexible undo the "
    "file's switches). A file may hold a [drop] and a [simulate] "
    "table, each command reading its own; a [simulate] table alone is refused: its keys are "
    "simulate's (there a rod is rigid unless flexible = true)."
)


def _on_command_line(ctx: typer.Context, name: str) -> bool:
    """True when the option ``name`` was given on the command line (not its default)."""
    source = ctx.get_parameter_source(name)  # typer's click enum: compared by name
    return source is not None and source.name == "COMMANDLINE"


def drop_cmd(
    ctx: typer.Context,
    angle: str = typer.Option(None, "--angle", help=KINEMATIC_HELP["angle"]),
    vy: str = typer.Option(None, "--vy", help=KINEMATIC_HELP["vy"]),
    vx: str = typer.Option(None, "--vx", help=KINEMATIC_HELP["vx"]),
    speed: str = typer.Option(None, "--speed", help=KINEMATIC_HELP["speed"]),
    incidence: str = typer.Option(None, "--incidence", help=KINEMATIC_HELP["incidence"]),
    spin: str = typer.Option(None, "--spin", help=KINEMATIC_HELP["spin"]),
    length: str = typer.Option(None, "--length", help=length_help("the paper's rod, 304.8 mm")),
    radius: str = typer.Option(
        None,
        "--radius",
        "--tip-radius",
        help="Tip radius R of the rounded ends, e.g. '8.8 mm' (bare number: m; default 8.8 mm).",
    ),
    mass: str = typer.Option(
        None,
        "--mass",
        help="Rod mass, e.g. '0.46 kg' (bare number: kg; default the paper's 0.4607 kg).",
    ),
    diameter: str = typer.Option(
        None,
        "--diameter",
        help="Rod diameter d, e.g. '12 mm': the mass follows from d, L and the density "
        "(with --mass too: the mass, up to two hemispherical ends of radius R included, is "
        "checked against the density to 2 %).",
    ),
    material: str = typer.Option(
        None,
        "--material",
        help="Rod material (library name, properties, TOML file; default aisi-201).",
    ),
    flat: str = typer.Option(
        None,
        "--flat",
        help="Flat material (library name, properties, TOML file; default aisi-1010).",
    ),
    mu: str = typer.Option(
        DEFAULT_MU, "--mu", show_default=False, help="Friction coefficient, >= 0 (default 0)."
    ),
    friction: str = typer.Option(
        "coulomb",
        "--friction",
        show_default=False,
        help="Friction model: impulse_ratio, coulomb (default), mindlin or partial_slip.",
    ),
    law: str = typer.Option(
        "ghaednia", "--law", show_default=False, help="Contact law (default ghaednia)."
    ),
    rate: str = typer.Option("none", "--rate", show_default=False, help=rate_help()),
    rigid: bool = typer.Option(
        None,
        "--rigid/--flexible",
        show_default=False,
        help="The rigid rod (no modes) instead, or the flexible one (default); either replaces "
        "the --config file's rigid.",
    ),
    inertia: str = typer.Option(
        None,
        "--inertia",
        help='With --rigid: the rod\'s I_C, e.g. "0.0036 kg*m^2" (bare number: kg*m^2; default '
        "from its size).",
    ),
    modes_axial: int = typer.Option(
        None, "--modes-axial", *MODES_ALIASES["modes_axial"], help=MODES_HELP["modes_axial"]
    ),
    modes_bending: int = typer.Option(
        None, "--modes-bending", *MODES_ALIASES["modes_bending"], help=MODES_HELP["modes_bending"]
    ),
    damping: str = typer.Option(
        None, "--damping", help="Modal damping ratio zeta of every mode, in [0, 1) (default 0)."
    ),
    gravity: bool = gravity_option(),
    rtol: str = typer.Option(
        None,
        "--rtol",
        help="Relative tolerance of the integration, in [1e-13, 1e-5] (default 1e-7). To check "
        "the contacts and totals, run again with more modes (--modes-axial, --modes-bending: "
        "twice and four times the counts shown: impactlab.dynamics.mode_convergence) as well as "
        "tighter.",
    ),
    stop: str = typer.Option(None, "--stop", help=STOP_HELP[0].upper() + STOP_HELP[1:]),
    time_limit: str = typer.Option(
        None,
        "--time-limit",
        help="Longest simulated time after the first touch, e.g. '2 s' (bare number: s; "
        f"default {DEFAULT_TIME_LIMIT * 1e3:g} ms): a long or slow rod may need more.",
    ),
    t_max: str = typer.Option(None, "--t-max", hidden=True),  # --time-limit before 0.3
    from_file: Path = typer.Option(
        None,
        "--from",
        help="Drop again the drop recorded in a drop's JSON (drop --json), with the options "
        "given on top (--rtol and --time-limit too): the rule of 'impactlab simulate --from' (the "
        "body's options and --config refused).",
    ),
    config: Path = typer.Option(None, "--config", help=CONFIG_HELP),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output."),
) -> None:
    """Drop a rod (the paper's by default; flexible, or --rigid) on a flat (AISI 1010 by
    default) and follow the whole contact sequence; prints every contact, what the columns
    mean, and the totals (display units).

    Examples:

    \b
      impactlab drop --angle "30 deg" --vy "-2 m/s" --length "200 mm" \\
        --radius "5 mm" --diameter "10 mm" --material brass-c360 --flat al-6061-t6

    \b
      impactlab drop --angle "20 deg" --vy "-1.41 m/s" --mu 0.2

    \b
      impactlab drop --angle "45 deg" --vy "-2.18 m/s" --mu 0.13 \\
        --rate cowper-symonds

    \b
      impactlab drop --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 \\
        --flat al-6061-t6 --rate "cowper-symonds(D=6500 1/s, q=4)"

    \b
      impactlab drop --angle "70 deg" --vy "-3.45 m/s" --mu 0.1 --rigid --json

    \b
      impactlab drop --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 \\
        --friction partial_slip

    \b
      impactlab drop --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 --stop flight
    """
    # the options named like the config file's keys, as given on the command line (else None)
    cli = {k: v if _on_command_line(ctx, k) else None for k, v in locals().items() if k in KEYS}
    cli = option_numbers(cli, ("mu", "damping", "rtol"))
    cli = renamed_options(cli, {"t_max": t_max if _on_command_line(ctx, "t_max") else None})
    if from_file is not None:  # the recorded drop, with the options given on top
        if config is not None:
            raise UserError(
                "--config and --from: --from takes the recorded input, with options on top; "
                "leave out --config"
            )
        result = run_from(from_file, cli, drop_only=True)
    else:
        section = command_table(load_toml(config, "--config"), "drop", "simulate", str(config))
        result = run_drop(merge_config(section, cli, config, KEYS, _FLAGS, _NOTES))
    for line in result.warnings:
        print_wrapped(f"warning: {line}")
    report_drop(cast(DropResult, result), as_json=as_json)  # drop_only: a drop


def run_drop(opt: ConfigOptions) -> DropResult:
    """The drop of the merged options (config file < command line; SI after parsing), its
    errors naming each value as the user gave it (``opt.label``)."""
    v = opt.values

    def name(key: str, like: str | None = None) -> str:  # the API's keywords (time_limit) too
        return opt.label(key, like) if key in KEYS else key

    if not opt.given("angle"):
        raise UserError(
            '--angle is required, with a unit, e.g. --angle "20 deg" (or angle = "20 deg" in the '
            "--config file)"
        )
    velocity = opt.velocity()
    sizes = {
        "length": opt.size("length", "m"),
        "tip_radius": opt.size("radius", "m"),
        "mass": opt.size("mass", "kg"),
        "diameter": opt.size("diameter", "m"),
    }
    modes = {k: v.get(k) for k in ("modes_axial", "modes_bending", "damping")}
    rod_material = option_material(opt, "material", PAPER_ROD.material)
    inertia = opt.size("inertia", "kg*m^2")
    flat = option_material(opt, "flat", AISI_1010)
    law = text(v.get("law", "ghaednia"), name("law"))
    rate = rate_name(text(v.get("rate", "none"), name("rate")), name("rate"))
    check_rate_flat(rate, flat, name("rate"))  # the command line's way to other constants
    check_rate_law(rate, law, name("rate"), name("law"))
    try:  # the rod's refusals name each option; a mass that does not fit, as typed
        body = drop_body(opt.given("rigid"), modes, sizes, rod_material, inertia, name)
    except UserError as exc:
        raise UserError(approach_worded(str(exc), opt)) from None
    try:
        return simulate_drop(
            body,
            flat,
            law=law,
            friction=text(v.get("friction", "coulomb"), name("friction")),
            mu=plain_number(v.get("mu", DEFAULT_MU), name("mu")),
            angle=angle_quantity(v["angle"], name("angle")),
            velocity=velocity,
            spin=quantity(v.get("spin"), "rad/s", name("spin")) or 0.0,
            gravity=bool(v.get("gravity", True)),
            rate=rate,
            history=False,
            stop=text(v.get("stop", "sequence"), name("stop")),
            rtol=None if v.get("rtol") is None else plain_number(v["rtol"], name("rtol")),
            time_limit=positive(v.get("time_limit"), "s", name("time_limit")) or DEFAULT_TIME_LIMIT,
        )
    except UserError:
        raise
    except DropError as exc:  # "raise {time_limit}": the option's or the key's name
        raise UserError(exc.worded(name)) from None
    except ValueError as exc:  # the API's message names its keyword (mu): name the option
        raise UserError(as_option(approach_worded(str(exc), opt), KEYS, name)) from None


#: The options of ``drop`` a ``--config`` file gives by key (``--from`` reads them as given).
KEYS: tuple[str, ...] = ("angle", "vy", "vx", "speed", "incidence", "spin", "length", "radius")
KEYS += ("mass", "diameter", "inertia", "material", "flat", "mu", "friction", "law", "rate")
KEYS += ("rigid", "modes_axial", "modes_bending", "damping", "gravity", "rtol", "stop")
KEYS += ("time_limit",)
#: Command-line spelling of the keys whose option is not ``--<key>``.
_FLAGS = {"gravity": "--no-gravity/--gravity", "rigid": "--rigid/--flexible"}
#: Keys of ``impactlab simulate``'s config file that are not the drop's: why.
_NOTES = {
    "body": "impactlab simulate's: a drop drops a rod",
    "flexible": "impactlab simulate's: the drop's rod is flexible unless rigid = true",
    "constant_angle": "impactlab simulate's: a drop's lever arms move",
    "law_params": "impactlab simulate's only",
}


def register(app: typer.Typer) -> None:
    """Add ``impactlab drop`` to ``app``."""
    app.command("drop")(drop_cmd)
