"""Indentation curves record which body yields in them (``IndentationCurves.yielding``), and
the tabulated law takes curves only of a pair whose same body yields: an aluminium sphere on a
bearing-steel flat (the sphere yields) got the FE curves of a steel sphere on an aluminium
flat before, whose force an FE run of the pair itself puts 21 % too high at 300 delta_c
(docs/laws/tabulated.md). Pairs whose flat yields get the same curves and parameters."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab.contact import get_law
from impactlab.contact._common import jg_critical
from impactlab.contact.indentation_data import (
    SHIPPED_PATH,
    IndentationCurves,
    curves_file_record,
    curves_from_record,
    read_curves,
    shipped_curves,
    yielding_body,
)
from impactlab.contact.tabulated import Tabulated, select_curves
from impactlab.fe.curves import load_cases
from impactlab.materials import AISI_201, AISI_1010, AISI_52100, AL_6061_T6, ContactPair, Material

R = 8.8e-3
SPHERE_YIELDS = ContactPair(AL_6061_T6, AISI_52100)  # aluminium sphere, bearing-steel flat
SHIPPED_PAIR = ContactPair(AISI_201, AISI_1010)


def _aluminium() -> IndentationCurves:
    return next(c for c in shipped_curves() if c.name == "aisi201-on-al6061t6")


def test_which_body_yields_first() -> None:
    assert yielding_body(SHIPPED_PAIR) == "flat"
    assert yielding_body(SPHERE_YIELDS) == "sphere"
    steel = Material("hard steel", 205e9, 0.29, 1379e6)
    assert yielding_body(ContactPair(steel, steel)) == "flat"  # equal S_y: the flat


def test_a_pair_whose_sphere_yields_is_refused_the_flat_curves() -> None:
    # its E*/S_y and nu are the shipped aluminium case's (208.1, 0.33): taken before
    assert abs(SPHERE_YIELDS.E_star / SPHERE_YIELDS.yield_strength / 208.1 - 1) < 0.01
    with pytest.raises(ValueError, match=r"^law 'tabulated': the sphere yields first") as info:
        get_law("tabulated").build(SPHERE_YIELDS, R)
    text = str(info.value)
    assert text.startswith(
        "law 'tabulated': the sphere yields first in this pair (S_y 276 MPa for the sphere, "
        "2034 MPa for the flat), but the indentation curves for its E*/S_y = 208.1, nu = 0.33 "
        "('aisi201-on-al6061t6') are for a yielding flat: curves differ once the other body "
        "yields (docs/laws/tabulated.md); "
    )
    assert "impactlab.fe.tabulated_law(pair, radius) (runs CalculiX, the sphere elastic" in text
    assert text.endswith("(IndentationCurves.from_arrays, yielding='sphere')")
    softer = ContactPair(dataclasses.replace(AL_6061_T6, yield_strength=150e6), AISI_52100)
    with pytest.raises(ValueError, match=r"nu = 0.33 \(within 5 % and 0.03\) of a yielding sphere; "
                       r"nearest: '.*' \(E\*/S_y = .*, a yielding flat\)"):  # fmt: skip
        get_law("tabulated").build(softer, R)


def test_pairs_whose_flat_yields_keep_their_curves_and_parameters() -> None:
    """The same curves chosen for every shipped case's pair, and the same parameters as the
    curves read without the field (the shipped file has none)."""
    record = json.loads(SHIPPED_PATH.read_text())
    assert all("yielding" not in c for c in record["curves"])
    plain = {c["name"]: curves_from_record(c) for c in record["curves"]}
    for case in load_cases():
        model = get_law("tabulated").build(case.pair, case.radius)
        assert model.source.startswith(f"{case.name}: ")
        direct = Tabulated(plain[case.name]).build(case.pair, case.radius)
        assert model.params.tobytes() == direct.params.tobytes()
    assert select_curves(SHIPPED_PAIR, shipped_curves()).name == "paper-aisi201-on-aisi1010"


def test_the_shipped_curves_are_all_of_a_yielding_flat() -> None:
    assert {c.yielding for c in shipped_curves()} == {"flat"}
    described = get_law("tabulated").describe()["curves"]
    assert {c["yielding"] for c in described} == {"flat"}


def test_the_field_is_checked_and_kept_in_json(tmp_path: Path) -> None:
    flat = _aluminium()
    sphere = dataclasses.replace(flat, name="sphere-yields", yielding="sphere")
    assert "yielding" not in flat.record()  # as every file written before the field
    assert sphere.record()["yielding"] == "sphere"
    path = tmp_path / "c.json"
    path.write_text(json.dumps(curves_file_record([flat, sphere])))
    back = read_curves(path)
    assert [c.yielding for c in back] == ["flat", "sphere"]
    np.testing.assert_array_equal(back[1].force, sphere.force)
    assert curves_from_record(sphere.record()).yielding == "sphere"
    bads: tuple[Any, ...] = ("both", "Sphere", None, 1)
    for bad in bads:
        with pytest.raises(ValueError, match=r"^yielding must be 'flat' or 'sphere', got "):
            dataclasses.replace(flat, yielding=bad)
    record = sphere.record() | {"yielding": "body"}
    with pytest.raises(ValueError, match=r"^yielding must be 'flat' or 'sphere', got 'body'$"):
        curves_from_record(record)


def _measured(pair: ContactPair, **kw: str) -> IndentationCurves:
    """The aluminium case's curves as dimensional data of ``pair``."""
    c = _aluminium()
    dc, fc = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)
    dm = c.delta_max * dc
    return IndentationCurves.from_arrays(
        pair, R, c.delta * dc, c.force * fc, dm, c.residual_ratio * dm, **kw
    )


def test_measured_curves_take_the_pairs_yielding_body_and_serve_only_it() -> None:
    mine = _measured(SPHERE_YIELDS)
    assert mine.yielding == "sphere"
    model = Tabulated(mine).build(SPHERE_YIELDS, R)
    assert model.source == "measured: measured indentation data"
    # the aluminium case's own pair (its flat yields) is refused these curves
    flat_pair = next(c.pair for c in load_cases() if c.name == "aisi201-on-al6061t6")
    with pytest.raises(ValueError, match=r"the flat yields first .* are for a yielding sphere"):
        Tabulated(mine).build(flat_pair, R)
    assert _measured(SPHERE_YIELDS, yielding="flat").yielding == "flat"
    with pytest.raises(ValueError, match=r"^yielding must be 'flat' or 'sphere', got 'x'"):
        _measured(SPHERE_YIELDS, yielding="x")
