"""One name per quantity: every public parameter of the top-level API and of the contact laws'
API (``impactlab.contact``: ``register_law``, ``IndentationCurves``, ...) and of the FE
reference (``impactlab.fe``) and of ``impactlab.explain``, every result field
(the ``to_dict`` keys of the result classes, a batch's columns) and every history column is a
name of docs/glossary.md (first column of its tables) or of the schema (``impactlab.schema``:
the impact's and the drop's fields and history columns)."""

from __future__ import annotations

import dataclasses
import inspect
import math
import re
from pathlib import Path
from typing import Any

import pytest

import impactlab
import impactlab.contact
import impactlab.explain
import impactlab.fe
from impactlab import schema
from impactlab.analytic.result import InversionResult
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.results import ImpactResult, assemble_result
from impactlab.flags import ResultFlag

GLOSSARY = Path(__file__).resolve().parents[2] / "docs" / "glossary.md"


def glossary_names() -> set[str]:
    """The backticked names in the first column of the glossary's tables."""
    names: set[str] = set()
    for line in GLOSSARY.read_text(encoding="utf-8").splitlines():
        if line.startswith("| ") and not line.startswith("| ---"):
            names |= set(re.findall(r"`([^`]+)`", line.split("|")[1]))
    return names


#: The names of the schema tables (``impactlab.schema``: the impact's and the drop's, with units
#: and meanings).
KNOWN = glossary_names() | set(schema.FIELDS)


#: The public modules whose callables' parameters are checked.
MODULES = (impactlab, impactlab.contact, impactlab.explain, impactlab.fe)


def _public_parameters() -> dict[str, str]:
    """Parameter name -> the first public callable of ``MODULES``' ``__all__`` that takes it."""
    out: dict[str, str] = {}
    for module in MODULES:
        for name in module.__all__:
            obj = getattr(module, name)
            if not (
                inspect.isfunction(obj) or (inspect.isclass(obj) and dataclasses.is_dataclass(obj))
            ):
                continue
            for p in inspect.signature(obj).parameters.values():  # type: ignore[arg-type]
                if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and not p.name.startswith("_"):
                    out.setdefault(p.name, f"{module.__name__}.{name}")
    return out


def _fake(cls: type) -> Any:
    """An instance of the result dataclass ``cls`` with placeholder values (its ``to_dict``
    keys do not depend on them)."""
    values: dict[str, Any] = {}
    for f in dataclasses.fields(cls):
        if f.default is not dataclasses.MISSING:
            values[f.name] = f.default
        elif f.type in ("float", "float | None"):
            values[f.name] = math.nan
        elif f.type == "int":
            values[f.name] = 0
        elif f.type == "str":
            values[f.name] = "hertz"
        elif f.type.startswith("tuple[float, float]"):
            values[f.name] = (0.0, 0.0)
        else:
            values[f.name] = ()
    values["flags"] = ResultFlag.NONE
    if cls is ImpactResult:
        return assemble_result(values)
    obj = object.__new__(cls)
    obj.__dict__.update(values)
    return obj


def _result_fields() -> dict[str, str]:
    out = {k: "ImpactResult.to_dict" for k in _fake(ImpactResult).to_dict()}
    out |= {k: "DropResult.to_dict" for k in _fake(DropResult).to_dict() if k not in out}
    out |= {f.name: "InversionResult.to_dict" for f in dataclasses.fields(InversionResult)}
    out |= {k: "BatchResult column" for k in (*schema.OUTPUT_FIELDS, "status") if k not in out}
    return {k if isinstance(k, str) else k.name: v for k, v in out.items()}


def _history_columns() -> dict[str, str]:
    out = {f.name: "ImpactResult.history" for f in schema.HISTORY_FIELDS}
    return out | {f.name: "DropResult.history" for f in schema.DROP_HISTORY_FIELDS}


@pytest.mark.parametrize(
    "names",
    [_public_parameters(), _result_fields(), _history_columns()],
    ids=["parameters", "result fields", "history columns"],
)
def test_every_public_name_is_in_the_glossary(names: dict[str, str]) -> None:
    missing = {n: where for n, where in names.items() if n not in KNOWN}
    assert not missing, f"not in docs/glossary.md nor impactlab.schema: {missing}"


def test_renamed_names_are_gone_from_the_tables() -> None:
    """A drop's names before 0.3 are no glossary name (they read the new ones, with a warning)."""
    old = set(schema.RENAMED_DROP_HISTORY) - set(schema.FIELDS)
    assert old and not old & glossary_names()
    assert not set(schema.RENAMED_DROP_FIELDS) & {f.name for f in schema.DROP_FIELDS}


def test_the_check_can_fail() -> None:
    assert "no_such_quantity" not in KNOWN
    assert {"simulate", "invert"} <= set(impactlab.__all__)
    assert {"velocity", "v_i", "gravity", "g"} <= set(_public_parameters())
    # the contact laws' API: register_law's keyword and IndentationCurves' field
    assert {"switch_interference", "elastic_limit", "residual_ratio"} <= set(_public_parameters())
