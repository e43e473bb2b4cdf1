"""The glossary is the reference for names: every name a result prints or stores (each field
of ``impactlab.schema``: an impact's outputs, result fields and history columns, a drop's fields
and history columns) and each kinematic input of a batch or sweep has a row of its own in
docs/glossary.md, whose unit column agrees with the schema's, and the ``regime`` row names
every regime."""

from __future__ import annotations

import re
from pathlib import Path

from impactlab import schema
from impactlab.dynamics import REGIME_NAMES
from impactlab.dynamics.drop_result import SUMMARY_FIELDS as DROP_SUMMARY
from impactlab.dynamics.results import SUMMARY_FIELDS as IMPACT_SUMMARY

GLOSSARY = Path(__file__).resolve().parents[2] / "docs" / "glossary.md"
#: the kinematic inputs of a batch (``simulate_batch``, ``simulate_drops``) and of a study
INPUTS = ("angle", "vx", "vy", "spin", "mu", "speed", "incidence")


def _rows() -> dict[str, list[str]]:
    """name -> the cells of its glossary row (a row may name several: `a`, `b`)."""
    rows: dict[str, list[str]] = {}
    for line in GLOSSARY.read_text(encoding="utf-8").splitlines():
        if line.startswith("| ") and not line.startswith("| ---"):
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            for name in re.findall(r"`([^`]+)`", cells[0]):
                rows.setdefault(name, cells)
    return rows


def test_every_printed_or_stored_name_has_a_row() -> None:
    rows = _rows()
    names = [*schema.FIELDS, *IMPACT_SUMMARY, *DROP_SUMMARY, *INPUTS]
    missing = sorted({n for n in names if n not in rows})
    assert not missing, f"no row in docs/glossary.md for {missing}"
    assert {"regime", "vn_out", "contact_x", "energy_error", "vx_out"} <= set(rows)


def test_unit_column_agrees_with_the_schema() -> None:
    wrong = {}
    for name, cells in _rows().items():
        if name not in schema.FIELDS:
            continue
        names = re.findall(r"`([^`]+)`", cells[0])
        units = [u.strip() for u in cells[2].split(",")]
        unit = units[names.index(name)] if len(units) == len(names) else units[0]
        if unit != schema.unit(name):
            wrong[name] = (unit, schema.unit(name))
    assert not wrong, f"glossary unit -> schema unit: {wrong}"


def test_regime_row_names_every_regime() -> None:
    cells = _rows()["regime"]
    for code, name in REGIME_NAMES.items():
        assert f"`{name}`" in cells[3] and str(code) in cells[3], (code, name, cells[3])
