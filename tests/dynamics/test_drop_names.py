"""A drop's contacts are named as everywhere else: ``print(result)``'s contact rows use the
names of ``impactlab drop``'s table and of ``--json`` (start, duration, normal_impulse), and a
contact's signed slip is ``sliding_length``, the quantity of an impact's ``sliding_length``
(``slip``, its name before 0.3, still reads it with a DeprecationWarning); the glossary has a row
for every field of ``ContactRecord``."""

from __future__ import annotations

import json
import math
import re
import warnings
from dataclasses import fields
from pathlib import Path
from typing import Any

import pytest

import impactlab as il
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_records import ContactRecord

GLOSSARY = Path(__file__).resolve().parents[2] / "docs" / "glossary.md"


@pytest.fixture(scope="module")
def drop() -> il.DropResult:
    """The paper's flexible rod at 20 deg, 1.41 m/s, mu 0.2: four contacts of the tip."""
    return il.simulate(il.FlexibleRod.paper(), angle="20 deg", velocity=(0, -1.41), mu=0.2)


def test_printed_contact_rows_use_the_names_of_the_table_and_json(drop: il.DropResult) -> None:
    rows = [line for line in str(drop).splitlines() if line.lstrip().startswith("contact ")]
    assert len(rows) == drop.n_contacts == 4
    first = rows[0]
    assert "start 0 ms, duration 0.331 ms, delta_max 35.24 um" in first, first
    assert "normal_impulse 0.1685 N s" in first, first
    assert not re.search(r"\bt0\b|\bP_n\b", "\n".join(rows))
    keys = set(drop.to_dict()["contacts"][0])
    assert {"start", "duration", "delta_max", "normal_impulse", "sliding_length"} <= keys


def test_a_contact_s_slip_is_an_impact_s_sliding_length() -> None:
    """A rigid rod's drop of one contact: the contact's sliding_length is the rigid engine's
    impact's, in value and sign (negative: the tip slides towards -x)."""
    kw: dict[str, Any] = {"law": "ghaednia", "friction": "coulomb", "mu": 0.2}
    kw["angle"] = math.radians(20)
    impact = il.simulate(il.Rod.paper(), velocity=(0.0, -1.41), rtol=1e-10, **kw)
    r = simulate_drop(il.Rod.paper(), velocity=(0.0, -1.41), rtol=1e-10, **kw)
    assert r.n_contacts == 1
    c = r.contacts[0]
    assert c.sliding_length < 0 and impact.sliding_length < 0
    assert c.sliding_length == pytest.approx(impact.sliding_length, abs=1e-6 * impact.delta_max)


def test_the_tip_s_contacts_sum_to_the_sequence_sliding_length(drop: il.DropResult) -> None:
    total = sum(c.sliding_length for c in drop.contacts if c.end == 0)
    assert total == pytest.approx(drop.sequence_sliding_length, rel=1e-12)


def test_slip_reads_sliding_length_with_a_warning(drop: il.DropResult) -> None:
    c = drop.contacts[0]
    with pytest.warns(DeprecationWarning, match="'slip' is renamed 'sliding_length'"):
        assert c.slip == c.sliding_length
    d = drop.to_dict()["contacts"][0]
    assert "slip" not in d and d["sliding_length"] == c.sliding_length
    with pytest.warns(DeprecationWarning, match="'slip' is renamed 'sliding_length'"):
        assert d["slip"] == c.sliding_length
    with pytest.raises(KeyError):
        d["no_such_key"]
    assert '"slip"' not in json.dumps(drop.to_dict())


def test_a_record_reads_back_from_to_dict_json_and_an_older_record(drop: il.DropResult) -> None:
    c = drop.contacts[1]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new names: no warning
        assert ContactRecord.from_dict(c.to_dict()) == c
        quantities = {k: {"value": v, "unit": "m"} for k, v in c.to_dict().items()}
        assert ContactRecord.from_dict(quantities) == c  # as --json writes a quantity
    older = {("slip" if k == "sliding_length" else k): v for k, v in c.to_dict().items()}
    with pytest.warns(DeprecationWarning, match="'slip' is renamed 'sliding_length'"):
        assert ContactRecord.from_dict(older) == c
    with pytest.raises(ValueError, match=r"^data: a contact record needs the keys .*missing"):
        ContactRecord.from_dict({"end": 0})


def test_the_glossary_has_a_row_for_every_contact_field() -> None:
    text = GLOSSARY.read_text(encoding="utf-8")
    section = text[text.index("A drop's contacts (`DropResult.contacts`") :]
    section = section[: section.index("\n\n", section.index("| name |"))]
    rows = [line.split("|")[1] for line in section.splitlines() if line.startswith("| `")]
    named = {n for cell in rows for n in re.findall(r"`([^`]+)`", cell)}
    missing = [f.name for f in fields(ContactRecord) if f.name not in named]
    assert not missing, f"no row in the glossary's contacts table for {missing}"
