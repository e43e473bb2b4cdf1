"""``impactlab drop``: the drop of a flexible rod (the paper's by default) or, with ``--rigid``,
of the rigid rod on a flat, through the whole contact sequence (``simulate_drop``).

Quantities carry units as in ``impactlab simulate``; the angle is required, with its unit.
Options that do not apply (mode counts or damping with ``--rigid``) are refused.
"""

from __future__ import annotations

from typing import Any

import typer

from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod
from impactlab.bodies.flexible_rod import DEFAULT_N_AXIAL, DEFAULT_N_BENDING
from impactlab.cli._common import UserError, angle_quantity, emit, quantity
from impactlab.contact.rate import RATE_LAWS
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import UNITS, DropResult
from impactlab.friction import DEFAULT_MU

#: ``--rate`` values ("none": a rate-independent flat).
RATE_CHOICES = ("none", *RATE_LAWS)

#: The totals printed after the contact table: field -> (display unit, scale from SI).
_TOTALS: dict[str, tuple[str, float]] = {
    "n_contacts": ("", 1.0),
    "e": ("-", 1.0),
    "e_raw": ("-", 1.0),
    "delta_p": ("um", 1e6),
    "scar_length": ("um", 1e6),
    "sliding_length": ("um", 1e6),
    "duration": ("ms", 1e3),
    "max_force": ("N", 1.0),
    "normal_impulse": ("N*s", 1.0),
    "tangential_impulse": ("N*s", 1.0),
    "spin_out": ("rad/s", 1.0),
    "mu_apparent": ("-", 1.0),
    "vibration_energy": ("J", 1.0),
    "energy_error": ("-", 1.0),
    "rate_factor": ("-", 1.0),
}

#: Columns of the contact table: (title, ContactRecord field, scale from SI).
_COLUMNS: tuple[tuple[str, str, float], ...] = (
    ("end", "end", 1.0),
    ("t0 [ms]", "start", 1e3),
    ("T [ms]", "duration", 1e3),
    ("dmax [um]", "delta_max", 1e6),
    ("Fmax [N]", "max_force", 1.0),
    ("Pn [N*s]", "normal_impulse", 1.0),
    ("Pt [N*s]", "tangential_impulse", 1.0),
    ("slip [um]", "slip", 1e6),
    ("reload", "reload", 1.0),
)


def _count(value: int | None, name: str, default: int) -> int:
    if value is None:
        return default
    if value < 0:
        raise UserError(f"{name} must be an integer >= 0, got {value}")
    return value


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
    n_axial = _count(modes_axial, "--modes-axial", DEFAULT_N_AXIAL)
    n_bending = _count(modes_bending, "--modes-bending", DEFAULT_N_BENDING)
    return FlexibleRod.paper(
        n_axial=n_axial,
        n_bending=n_bending,
        axial_residual=n_axial >= 1,
        damping=0.0 if damping is None else damping,
    )


def _rate(rate: str) -> str | None:
    name = rate.strip().lower()
    if name not in RATE_CHOICES:
        raise UserError(f"--rate must be one of {', '.join(RATE_CHOICES)}, got {rate!r}")
    return None if name == "none" else name


def _contact_table(result: DropResult) -> str:
    """Every contact, one line each, in display units (plain text, fixed width)."""
    rows = [["#", *(title for title, _f, _s in _COLUMNS)]]
    for i, c in enumerate(result.contacts, 1):
        cells = [str(i)]
        for _t, name, scale in _COLUMNS:
            v = getattr(c, name)
            cells.append(f"{v * scale:.4g}" if isinstance(v, float) else str(v))
        rows.append(cells)
    widths = [max(len(r[j]) for r in rows) for j in range(len(rows[0]))]
    lines = ["  ".join(cell.rjust(w) for cell, w in zip(r, widths, strict=True)) for r in rows]
    return "contacts\n" + "\n".join(lines)


def _totals(result: DropResult) -> tuple[dict[str, Any], dict[str, str]]:
    """The totals in display units, and their units."""
    data: dict[str, Any] = {"body": result.body, "law": result.law}
    data["friction"] = f"{result.friction} (mu = {result.mu:g})"
    data["rate"] = result.rate or "none"
    units: dict[str, str] = {}
    for key, (unit, scale) in _TOTALS.items():
        v = getattr(result, key)
        data[key] = v * scale if isinstance(v, float) else v
        units[key] = unit
    return data, units


def drop_cmd(
    angle: str = typer.Option(
        None, "--angle", help='Rod angle to the flat with its unit, "20 deg" or "0.35 rad".'
    ),
    vy: str = typer.Option(None, "--vy", help='Vertical velocity, e.g. "-1.41 m/s" (required).'),
    vx: str = typer.Option(None, "--vx", help="Horizontal velocity (default 0)."),
    spin: str = typer.Option(None, "--spin", help='Angular velocity, e.g. "5 rad/s" (default 0).'),
    mu: float = typer.Option(
        DEFAULT_MU, "--mu", help="Coulomb friction coefficient (the only friction model here)."
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
    """
    if angle is None:
        raise UserError('--angle is required, with a unit, e.g. --angle "20 deg"')
    if vy is None:
        raise UserError('--vy is required, e.g. --vy "-1.41 m/s"')
    body = _body(rigid, modes_axial, modes_bending, damping)
    result = simulate_drop(
        body,
        law=law,
        friction="coulomb",
        mu=mu,
        angle=angle_quantity(angle, "--angle"),
        velocity=(quantity(vx, "m/s", "--vx") or 0.0, quantity(vy, "m/s", "--vy") or 0.0),
        spin=quantity(spin, "rad/s", "--spin") or 0.0,
        gravity=not no_gravity,
        rate=_rate(rate),
    )
    if as_json:
        emit({**result.to_dict(), "units": UNITS}, as_json=True)
        return
    print(_contact_table(result))
    data, units = _totals(result)
    emit(data, as_json=False, title="drop", units=units)


def register(app: typer.Typer) -> None:
    """Add ``impactlab drop`` to ``app``."""
    app.command("drop")(drop_cmd)
