"""``impactlab materials``: the material presets."""

from __future__ import annotations

from dataclasses import asdict

import typer

from impactlab.cli._common import console, emit
from impactlab.materials import PRESETS


def materials(
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output."),
) -> None:
    """List the material presets (E in GPa, yield strength in MPa, Brinell hardness in
    kgf/mm^2; --json: SI).

    Example: impactlab materials --json
    """
    data = {key: asdict(m) for key, m in PRESETS.items()}
    if as_json:
        emit(data, as_json=True)
        return
    for key, m in data.items():
        emit(m, as_json=False, title=key)
    console.print(
        "Presets follow the paper's Table 1 with its unit corrections "
        "(see docs/paper/errata.md, section Table 1)."
    )


def register(app: typer.Typer) -> None:
    """Add ``impactlab materials`` to ``app``."""
    app.command("materials")(materials)
