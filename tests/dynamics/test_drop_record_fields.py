"""A drop's record reruns only as it was written, down to the fields of its body and materials:
a record whose rod or material lacks one (a damping ratio, a mode count, the beam theory, the
material, a material's ``brittle``) is refused naming it, in Python and on the command line,
rather than run on the field's default. And a drop's ``n_dents`` is a field of one result, as
it is a column of a batch; the batch's ``t_final`` and ``n_jumps`` say where to read them."""

from __future__ import annotations

import copy
import dataclasses
import json
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import impactlab as il
from impactlab.bodies import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.dynamics.record_codec import OPTIONAL_FIELDS
from impactlab.materials import Material

CliMain = Callable[..., tuple[int, str, str]]

#: The tail of every refusal of an incomplete record (the words of a missing 'rate').
TAIL = (
    r"every record of the format holds each, and a rerun without one would run on a "
    r"default, not as recorded"
)
KW: dict[str, Any] = {"angle": "20 deg", "velocity": (0.0, -1.41), "mu": 0.2}


@pytest.fixture(scope="module")
def drop() -> il.DropResult:
    """A small flexible rod whose every field differs from its default where it can."""
    rod = FlexibleRod.paper(n_axial=2, n_bending=4, damping=0.05, theory="euler-bernoulli")
    return il.simulate_drop(rod, history=False, **KW)


def _without(record: dict[str, Any], path: str) -> dict[str, Any]:
    """A copy of ``record`` whose ``input`` lacks the key at ``path`` (``body.material.E``)."""
    bad = copy.deepcopy(record)
    *parents, key = path.split(".")
    node = bad["input"]
    for p in parents:
        node = node[p]
    del node[key]
    return bad


def _fields(cls: type) -> list[str]:
    return [f.name for f in dataclasses.fields(cls) if f.init]


def test_the_complete_record_reruns_to_the_same_numbers(drop: il.DropResult) -> None:
    again = il.rerun(drop.to_dict())
    assert again.e == drop.e and again.dent_depth == drop.dent_depth


@pytest.mark.parametrize("field", _fields(FlexibleRod))
def test_a_rod_field_left_out_is_refused_by_name(drop: il.DropResult, field: str) -> None:
    with pytest.raises(ValueError, match=rf"^the record's body FlexibleRod lacks '{field}'"):
        il.rerun(_without(drop.to_dict(), f"body.{field}"))


@pytest.mark.parametrize("where", ["body.material", "flat"])
@pytest.mark.parametrize("field", _fields(Material))
def test_a_material_field_left_out_is_refused_by_name(
    drop: il.DropResult, where: str, field: str
) -> None:
    with pytest.raises(ValueError, match=rf"^the record's {where} Material lacks '{field}'"):
        il.rerun(_without(drop.to_dict(), f"{where}.{field}"))


def test_the_refusal_says_why_in_the_words_of_a_missing_key(drop: il.DropResult) -> None:
    """Without its damping such a record ran with zeta = 0 (e 0.655, not
    0.588) and said nothing."""
    with pytest.raises(ValueError, match="lacks 'damping'") as err:
        il.rerun(_without(drop.to_dict(), "body.damping"))
    text = str(err.value)
    assert text.startswith("the record's body FlexibleRod lacks 'damping' ")
    assert '{"value": ..., "unit": "1"}' in text and "\n" not in text
    assert re.search(TAIL, text)
    with pytest.raises(ValueError, match=TAIL):  # the top-level keys say the same
        il.rerun(_without(drop.to_dict(), "rate"))


def test_a_rigid_rod_s_record_needs_its_inertia_too() -> None:
    r = il.simulate(il.Rod.paper(), history=False, **KW)
    assert il.rerun(r.to_dict()).e == r.e
    for field in ("inertia", "mass", "diameter", "material"):
        with pytest.raises(ValueError, match=rf"^the record's body Rod lacks '{field}'.*{TAIL}"):
            il.rerun(_without(r.to_dict(), f"body.{field}"))


def test_only_a_contact_model_s_descriptive_fields_may_be_left_out() -> None:
    assert OPTIONAL_FIELDS == {ContactModel: frozenset({"details", "source", "references"})}


def test_drop_from_refuses_a_record_without_a_rod_field(
    drop: il.DropResult, cli_main: CliMain, tmp_path: Path
) -> None:
    path = tmp_path / "no_damping.json"
    path.write_text(json.dumps(_without(drop.to_dict(), "body.damping")))
    for command in ("drop", "simulate"):
        code, out, err = cli_main(command, "--from", str(path))
        assert code == 2 and out == "", command
        assert err.startswith("error: ") and err.count("\n") == 1, err
        assert "the record's body FlexibleRod lacks 'damping'" in err


def test_one_drop_counts_its_dents_as_the_batch_does(drop: il.DropResult) -> None:
    assert drop.n_dents == len(drop.dents) >= 1
    d = drop.to_dict()
    assert d["n_dents"] == drop.n_dents and isinstance(d["n_dents"], int)
    assert drop.units["n_dents"] == "1" and drop.to_pint()["n_dents"].magnitude == drop.n_dents
    batch = il.simulate_drops(il.Rod.paper(), angle=math.radians(20), vy=-1.41, mu=0.2)
    one = il.simulate_drop(il.Rod.paper(), **KW)
    assert batch.n_dents[0] == one.n_dents
    assert one.history is not None
    assert batch.t_final[0] == one.history.t[-1]  # where the hint below points


@pytest.mark.parametrize(
    ("name", "pointer"),
    [
        ("t_final", r"one result does not hold it: history\.t\[-1\] .*simulate_drops"),
        ("n_jumps", r"one result does not hold it: .*simulate_drops\(\.\.\.\)\.n_jumps"),
        ("vx_out", r"in one result: vx_out -> velocity_out\[0\]"),
    ],
)
def test_a_batch_column_one_drop_lacks_says_where_to_read_it(
    drop: il.DropResult, name: str, pointer: str
) -> None:
    with pytest.raises(AttributeError, match=rf"'DropResult' object has no attribute '{name}' "):
        getattr(drop, name)
    with pytest.raises(AttributeError, match=pointer):
        getattr(drop, name)


def test_drop_json_writes_n_dents_as_an_integer(cli_main: CliMain) -> None:
    code, out, err = cli_main("drop", "--rigid", "--angle", "20 deg", "--vy", "-1.41 m/s",
                              "--mu", "0.2", "--json")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    assert d["n_dents"] == len(d["dents"]) == 1
