"""``impactlab materials``: the material library, with each entry's condition and source."""

from __future__ import annotations

import math
from dataclasses import asdict
from pathlib import Path

import typer
from rich.table import Table
from rich.text import Text

from impactlab.cli._common import UserError, console, emit
from impactlab.cli.printing import versioned
from impactlab.materials import BRITTLE, PRESETS, get_material
from impactlab.materials.inputs import EXAMPLE, library_key
from impactlab.references import REFERENCES


def _hb(value: float) -> str:
    return "-" if math.isnan(value) else f"{value:g}"


def materials(
    name: str | None = typer.Argument(
        None, help="Show one material in full: a library name or alias (e.g. 'aisi-1010')."
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (SI)."),
) -> None:
    """List the material library: E [GPa], nu, yield strength S_y [MPa], Brinell hardness HB
    [kgf/mm^2; '-': not in the source], density [kg/m^3] and the condition (the sources:
    --json, in SI with each source's citation and address, and docs/materials.md).

    Any command's --material/--flat takes one of these names, or a material by values
    ("E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"; HB=, n=, brittle=yes optional), or a
    TOML file of the same keys.

    Example: impactlab materials --json; impactlab materials 6061-t6
    """
    if name is not None:
        _one(name, as_json)
        return
    if as_json:
        data = {}
        for key, m in PRESETS.items():
            ref = REFERENCES[m.source]
            data[key] = {
                **asdict(m),
                "brittle": key in BRITTLE,
                "citation": ref.citation,
                "url": ref.url,
            }
        emit(versioned(data), as_json=True)
        return
    table = Table(show_header=True, header_style="bold", title="material library")
    for col in ("name", "E GPa", "nu", "Sy MPa", "HB", "rho", "condition"):
        table.add_column(col, justify="left" if col in ("name", "condition") else "right")
    for key, m in PRESETS.items():
        table.add_row(
            Text(key + ("*" if key in BRITTLE else "")),
            f"{m.E / 1e9:.4g}",
            f"{m.nu:g}",
            f"{m.yield_strength / 1e6:.4g}",
            _hb(m.brinell_hardness),
            "-" if m.density is None else f"{m.density:.0f}",
            Text(m.condition or "paper, Table 1"),
        )
    console.print(table)
    console.print(
        Text(
            "rho in kg/m^3, HB in kgf/mm^2. * brittle: Sy holds the compressive strength (no "
            "fracture model). Sources: "
            "impactlab materials --json, docs/materials.md. Any other material: --flat "
            f'"{EXAMPLE}".'
        )
    )


def _one(name: str, as_json: bool) -> None:
    """One library material in full: its values (SI in --json), condition, source and note."""
    if not name.strip() or "=" in name or name.strip().endswith(".toml") or Path(name).exists():
        raise UserError(  # values or a file define a material for --flat, not a library entry
            f"NAME: {name!r} is not a library name (see 'impactlab materials'); a material by "
            "values or a TOML file is given to --flat or --material of the other commands"
        )
    try:
        key = library_key(get_material(name, "NAME"))  # a library name or alias, else one line
    except ValueError as exc:  # shown here is a library entry: not "or give its properties"
        raise UserError(str(exc).split(", or give its properties")[0]) from None
    if key is None:  # a definition by values or a file: not a library entry
        raise UserError(f"NAME: {name!r} is not a library name (see 'impactlab materials')")
    m = PRESETS[key]
    ref = REFERENCES[m.source]
    data = {
        "key": key,
        **asdict(m),
        "brittle": key in BRITTLE,
        "citation": ref.citation,
        "url": ref.url,
    }
    # no impactlab_version: the entry's JSON is read back as a material (get_material)
    emit(versioned(data) if as_json else data, as_json=as_json, title=f"material {key!r}")


def register(app: typer.Typer) -> None:
    """Add ``impactlab materials`` to ``app``."""
    app.command("materials")(materials)
