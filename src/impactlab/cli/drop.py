"""``impactlab drop``: the drop of a flexible rod (the paper's by default) or, with ``--rigid``,
of the rigid rod on a flat, through the whole contact sequence (``simulate_drop``).

Quantities carry units as in ``impactlab simulate``; the angle is required, with its unit.
Options that do not apply (mode counts or damping with ``--rigid``) are refused.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from typing import Any

import typer

from impactlab._display import display_unit, field_row, flag_names
from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod
from impactlab.bodies.flexible_rod import DEFAULT_N_AXIAL, DEFAULT_N_BENDING
from impactlab.cli._common import (
    KINEMATIC_HELP,
    SI_UNITS,
    UserError,
    angle_quantity,
    emit,
    quantity,
)
from impactlab.contact.rate import RATE_LAWS
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import UNITS, DropResult
from impactlab.friction import DEFAULT_MU
from impactlab.materials import Material

#: ``--rate`` values ("none": a rate-independent flat).
RATE_CHOICES = ("none", *RATE_LAWS)

#: The totals printed after the contact table (SI units: ``SI_UNITS``).
TOTALS = (
    "n_contacts",
    "e",
    "e_raw",
    "delta_p",
    "delta_max",
    "scar_length",
    "sliding_length",
    "duration",
    "mean_force",
    "max_force",
    "normal_impulse",
    "tangential_impulse",
    "spin_out",
    "mu_apparent",
    "vibration_energy",
    "energy_error",
    "rate_factor",
)

#: Columns of the contact table: ContactRecord fields (display units: ``impactlab._display``).
_COLUMNS = (
    "end",
    "start",
    "duration",
    "delta_max",
    "max_force",
    "normal_impulse",
    "tangential_impulse",
    "slip",
    "reload",
)


def _count(value: int | None, name: str, default: int) -> int:
    if value is None:
        return default
    if value < 0:
        raise UserError(f"{name} must be an integer >= 0, got {value}")
    return value


def flexible_rod(
    values: Mapping[str, Any], sizes: Mapping[str, float], material: Material, label: Any = None
) -> FlexibleRod:
    """A FlexibleRod of the given ``sizes`` (length, tip_radius, mass) and ``material`` with
    the mode counts and damping of ``values`` (``modes_axial``, ``modes_bending``,
    ``damping``; None: the defaults). ``label(key)`` spells an option in errors."""
    name = label or (lambda key: "--" + key.replace("_", "-"))
    n_axial = _count(values.get("modes_axial"), name("modes_axial"), DEFAULT_N_AXIAL)
    n_bending = _count(values.get("modes_bending"), name("modes_bending"), DEFAULT_N_BENDING)
    damping = values.get("damping")
    return FlexibleRod(
        length=sizes["length"],
        tip_radius=sizes["tip_radius"],
        mass=sizes["mass"],
        material=material,
        n_axial=n_axial,
        n_bending=n_bending,
        axial_residual=n_axial >= 1,
        damping=0.0 if damping is None else float(damping),
    )


def _body(
    rigid: bool, modes_axial: int | None, modes_bending: int | None, damping: float | None
) -> FlexibleRod | Rod:
    """The paper's rod, flexible (with the given mode counts and damping) or rigid."""
    if rigid:
        given = [
            name
            for name, v in (
                ("--modes-axial", modes_axial),
                ("--modes-bending", modes_bending),
                ("--damping", damping),
            )
            if v is not None
        ]
        if given:
            raise UserError(f"{', '.join(given)}: a rigid rod has no modes; leave out --rigid")
        return PAPER_ROD
    paper = {"length": PAPER_ROD.length, "tip_radius": PAPER_ROD.tip_radius, "mass": PAPER_ROD.mass}
    modes = {"modes_axial": modes_axial, "modes_bending": modes_bending, "damping": damping}
    return flexible_rod(modes, paper, PAPER_ROD.material)


def rate_name(rate: str, name: str = "--rate") -> str | None:
    """The rate law of ``--rate`` (None for "none"); UserError listing the choices."""
    key = rate.strip().lower()
    if key not in RATE_CHOICES:
        raise UserError(f"{name} must be one of {', '.join(RATE_CHOICES)}, got {rate!r}")
    return None if key == "none" else key


def _contact_rows(result: DropResult) -> tuple[list[str], list[list[str]]]:
    """The contact table's header (field [display unit]) and rows, in display units."""
    header = ["#"]
    for key in _COLUMNS:
        unit = display_unit(key, SI_UNITS.get(key, "")).unit
        header.append(key if unit == "-" else f"{key} [{unit}]")
    rows = []
    for i, c in enumerate(result.contacts, 1):
        cells = [str(i)]
        for key in _COLUMNS:
            v = getattr(c, key)
            cells.append(field_row(key, v, SI_UNITS.get(key))[1])
        rows.append(cells)
    return header, rows


def _contact_table(result: DropResult) -> str:
    """Every contact, one line each, in display units (plain text, fixed width)."""
    header, rows = _contact_rows(result)
    table = [header, *rows]
    widths = [max(len(r[j]) for r in table) for j in range(len(header))]
    lines = ["  ".join(cell.rjust(w) for cell, w in zip(r, widths, strict=True)) for r in table]
    return "contacts\n" + "\n".join(lines)


def drop_summary(result: DropResult) -> dict[str, Any]:
    """The set-up and the totals of a drop (SI values; ``impactlab._display`` shows them)."""
    data: dict[str, Any] = {"body": result.body, "law": result.law}
    data["friction"] = result.friction
    data["mu"] = result.mu
    data["rate"] = result.rate or "none"
    data.update({key: getattr(result, key) for key in TOTALS})
    data["flags"] = flag_names(result.flags)
    return data


def report_drop(result: DropResult, *, as_json: bool) -> None:
    """Print a drop: JSON (SI, docs/json-schema.md), or the contact table and the totals."""
    if as_json:
        balance = {key: "J" for key in result.energy_balance}  # its terms, by name
        emit(result.to_dict(), as_json=True, units={**UNITS, **balance})
        return
    print(_contact_table(result))
    emit(drop_summary(result), as_json=False, title="drop", units=UNITS)


def drop_cmd(
    angle: str = typer.Option(None, "--angle", help=KINEMATIC_HELP["angle"]),
    vy: str = typer.Option(None, "--vy", help=KINEMATIC_HELP["vy"]),
    vx: str = typer.Option(None, "--vx", help=KINEMATIC_HELP["vx"]),
    spin: str = typer.Option(None, "--spin", help=KINEMATIC_HELP["spin"]),
    mu: float = typer.Option(DEFAULT_MU, "--mu", help="Friction coefficient, >= 0 (default 0)."),
    friction: str = typer.Option(
        "coulomb",
        "--friction",
        help="Friction model: impulse_ratio, coulomb (default), mindlin or partial_slip.",
    ),
    law: str = typer.Option("ghaednia", "--law", help="Contact law (default ghaednia)."),
    rate: str = typer.Option(
        "none", "--rate", help=f"Rate-dependent flat: {', '.join(RATE_CHOICES)} (default none)."
    ),
    rigid: bool = typer.Option(False, "--rigid", help="The rigid rod (no modes) instead."),
    modes_axial: int = typer.Option(
        None, "--modes-axial", help=f"Axial modes (default {DEFAULT_N_AXIAL}, + 2 residual)."
    ),
    modes_bending: int = typer.Option(
        None, "--modes-bending", help=f"Bending modes (default {DEFAULT_N_BENDING})."
    ),
    damping: float = typer.Option(
        None, "--damping", help="Modal damping ratio zeta of every mode, in [0, 1) (default 0)."
    ),
    no_gravity: bool = typer.Option(False, "--no-gravity", help="Switch gravity off."),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output."),
) -> None:
    """Drop the paper's rod (flexible, or --rigid) on the AISI 1010 flat and follow the whole
    contact sequence; prints every contact and the totals (display units).

    Examples:

      impactlab drop --angle "20 deg" --vy "-1.41 m/s" --mu 0.2

      impactlab drop --angle "45 deg" --vy "-2.18 m/s" --mu 0.13 --rate cowper-symonds

      impactlab drop --angle "70 deg" --vy "-3.45 m/s" --mu 0.1 --rigid --json

      impactlab drop --angle "20 deg" --vy "-1.41 m/s" --mu 0.2 --friction partial_slip
    """
    if angle is None:
        raise UserError('--angle is required, with a unit, e.g. --angle "20 deg"')
    if vy is None:
        raise UserError('--vy is required, e.g. --vy "-1.41 m/s"')
    body = _body(rigid, modes_axial, modes_bending, damping)
    result = simulate_drop(
        body,
        law=law,
        friction=friction,
        mu=mu,
        angle=angle_quantity(angle, "--angle"),
        velocity=(quantity(vx, "m/s", "--vx") or 0.0, quantity(vy, "m/s", "--vy") or 0.0),
        spin=quantity(spin, "rad/s", "--spin") or 0.0,
        gravity=not no_gravity,
        rate=rate_name(rate),
    )
    for text in result.warnings:
        print(f"warning: {text}", file=sys.stderr)
    report_drop(result, as_json=as_json)


def register(app: typer.Typer) -> None:
    """Add ``impactlab drop`` to ``app``."""
    app.command("drop")(drop_cmd)
