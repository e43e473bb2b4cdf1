"""Which code computed a result: a hash of the sources that decide an impact's outputs.

A sweep store is resumed chunk by chunk, and a result's record is run again (``rerun``,
``impactlab simulate --from``), possibly after impactlab was updated. The package version
alone does not change with every change of the physics (a new flag, a corrected kernel), so
chunks computed before and after such a change would mix in one store, and a rerun would give
other numbers, without a word. A store's engine identity and a result's record therefore carry
``results_code_hash``: the SHA-256 of the compiled engine's sources (``ENGINE_SOURCES``), of
the Python code around it that turns inputs into a case's outputs and flags (dynamics, bodies,
materials, friction, the sweep's evaluators), and of the data the laws read (the FE curves of
the tabulated laws, the laws' verified ranges). Presentation is not part of it: the CLI, the
docs, the sweep's plots and reports, and the modules of those folders that only show a result
(``PRESENTATION``: no code of theirs runs while a sweep computes its cases,
tests/sweep/test_code_identity_scope.py), so editing them leaves every store resumable and
every record silent.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

from impactlab._compiled_cache import ENGINE_SOURCES, source_hash

__all__ = ["PRESENTATION", "RESULT_SOURCES", "result_files", "results_code_hash"]

#: Everything, relative to the package, whose change can change a stored case's outputs (a
#: folder: its ``.py`` files, less ``PRESENTATION``).
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

#: The modules inside ``RESULT_SOURCES``' folders that only present a result: left out.
PRESENTATION = (
    "dynamics/result_display.py",  # repr, print and HTML of a result
    "dynamics/plotting.py",  # figures of one impact
    "dynamics/keyword_hints.py",  # the words of an error about a velocity's keywords
    "dynamics/pint_fields.py",  # a result's fields as pint Quantities
)


def result_files(package: Path) -> tuple[str, ...]:
    """The files of ``RESULT_SOURCES`` under ``package`` (relative, a folder's ``.py`` files
    sorted), less ``PRESENTATION``."""
    names: list[str] = []
    for name in RESULT_SOURCES:
        path = package / name
        found = sorted(path.rglob("*.py")) if path.is_dir() else [path]
        names.extend(f.relative_to(package).as_posix() for f in found)
    return tuple(n for n in names if n not in PRESENTATION)


@cache
def results_code_hash() -> str:
    """``source_hash`` (16 hex digits) of ``result_files`` as installed, computed once."""
    package = Path(__file__).resolve().parent
    return source_hash(package, result_files(package))
