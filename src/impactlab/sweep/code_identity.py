"""Which code computed a store's results: a hash of the sources that decide a case's outputs.

A store is resumed chunk by chunk, possibly after impactlab was updated. The package version
alone does not change with every change of the physics (a new flag, a corrected kernel), so
chunks computed before and after such a change would mix in one store without a word. The
store's engine identity therefore carries ``results_code_hash``: the SHA-256 of the compiled
engine's sources (``ENGINE_SOURCES``), of the Python code around it that turns inputs into a
case's outputs and flags (dynamics, bodies, materials, friction, the sweep's evaluators), and of
the data the laws read (the FE curves of the tabulated laws, the laws' verified ranges).
Presentation (plots, display, the CLI, the docs) is not part of it.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

from impactlab._compiled_cache import ENGINE_SOURCES, source_hash

__all__ = ["RESULT_SOURCES", "results_code_hash"]

#: Everything, relative to the package, whose change can change a stored case's outputs.
RESULT_SOURCES = (
    *ENGINE_SOURCES,
    "dynamics",
    "bodies",
    "materials",
    "friction.py",
    "units.py",
    "contact/data/fe-curves.json",
    "contact/data/verified-ranges.json",
    "sweep/engine.py",
    "sweep/flexible.py",
    "sweep/models.py",
    "sweep/inputs.py",
    "sweep/material_inputs.py",
    "sweep/material_record.py",
)


@cache
def results_code_hash() -> str:
    """``source_hash`` (16 hex digits) of ``RESULT_SOURCES`` as installed, computed once."""
    return source_hash(Path(__file__).resolve().parent.parent, RESULT_SOURCES)
