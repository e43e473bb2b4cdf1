"""An impact on a brittle material past its first yield is marked BRITTLE, never plain success:
the library's tungsten carbide, alumina and glass carry their compressive strength as the yield
strength, crack rather than yield, and impactlab has no fracture model. The material that
yields first (the smaller yield strength) decides; the threshold is the law's first-yield
interference (``contact.ranges.critical_interference``). ``simulate`` (both friction paths),
batches, drops and sweeps alike."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import impactlab as il
from impactlab.cli import app
from impactlab.contact.ranges import brittle_flags, critical_interference
from impactlab.dynamics.models import contact_model
from impactlab.flags import FLAG_BRITTLE, ResultFlag, invalidating_names, messages
from impactlab.materials import (
    AISI_201,
    AISI_1010,
    AISI_52100,
    ALUMINA_995,
    BRITTLE,
    PRESETS,
    SODA_LIME_GLASS,
    TUNGSTEN_CARBIDE,
    ContactPair,
    Material,
    get_material,
    yields_brittle,
)

ROD = il.Rod.paper()
TH = math.radians(45.0)


def test_the_library_marks_its_brittle_entries() -> None:
    assert {k for k, m in PRESETS.items() if m.brittle} == BRITTLE
    assert BRITTLE == {"tungsten-carbide", "alumina-99.5", "soda-lime-glass"}
    assert not AISI_1010.brittle and "brittle = yes" in str(SODA_LIME_GLASS)
    assert "brittle" not in str(AISI_1010)


def test_brittle_is_a_bool_and_a_change_of_it_relabels_a_library_entry() -> None:
    with pytest.raises(ValueError, match="brittle must be True or False, got 'yes'"):
        Material("x", 70e9, 0.2, 300e6, brittle="yes")  # type: ignore[arg-type]
    tough = dataclasses.replace(SODA_LIME_GLASS, brittle=False)
    assert tough.name.endswith("modified (brittle)") and tough.source == ""
    assert dataclasses.replace(SODA_LIME_GLASS, E=70e9).brittle  # still glass


@pytest.mark.parametrize(("text", "brittle"), [("yes", True), ("True", True), ("no", False)])
def test_a_material_by_values_says_whether_it_is_brittle(text: str, brittle: bool) -> None:
    m = get_material(f"E=70GPa, nu=0.22, Sy=300MPa, rho=2500, brittle={text}")
    assert m.brittle is brittle
    assert not get_material("E=70GPa, nu=0.22, Sy=300MPa, rho=2500").brittle


def test_a_bad_brittle_value_is_refused_by_name() -> None:
    with pytest.raises(ValueError, match="material brittle: expected true or false, got 'maybe'"):
        get_material("E=70GPa, nu=0.22, Sy=300MPa, rho=2500, brittle=maybe")


def test_the_material_that_yields_first_decides() -> None:
    assert yields_brittle(AISI_201, SODA_LIME_GLASS)  # glass 330 MPa < 760 MPa
    assert ContactPair(AISI_201, SODA_LIME_GLASS).brittle
    assert not yields_brittle(TUNGSTEN_CARBIDE, AISI_1010)  # the steel flat yields first
    assert yields_brittle(AISI_52100, ALUMINA_995) is False  # 2.03 GPa < 3.0 GPa: the steel


def test_the_threshold_is_first_yield() -> None:
    """Just below the law's delta_ref nothing, just above BRITTLE; never for a tough pair."""
    model = contact_model(ROD, SODA_LIME_GLASS, "ghaednia", None)
    ref = critical_interference(model.law_id, model.params)
    below, above = ref * (1 - 1e-9), ref * (1 + 1e-9)
    assert brittle_flags(model.law_id, model.params, below, True) == 0
    assert brittle_flags(model.law_id, model.params, above, True) == FLAG_BRITTLE
    assert brittle_flags(model.law_id, model.params, above, False) == 0
    assert brittle_flags(model.law_id, model.params, math.nan, True) == 0
    many = brittle_flags(model.law_id, model.params, np.array([below, above, above]),
                         np.array([True, True, False]))  # fmt: skip
    np.testing.assert_array_equal(many, [0, FLAG_BRITTLE, 0])


@pytest.mark.parametrize("law", ["ghaednia", "hertz", "kogut-komvopoulos"])
def test_the_papers_rod_on_glass_is_marked(law: str) -> None:
    r = il.simulate(ROD, SODA_LIME_GLASS, angle=TH, velocity=(0.0, -1.41), law=law)
    assert ResultFlag.BRITTLE in r.flags and not r.ok
    assert any(w.startswith("brittle: ") for w in r.warnings)
    assert r.max_delta_ratio > 1.0
    steel = il.simulate(ROD, AISI_1010, angle=TH, velocity=(0.0, -1.41), law=law)
    assert ResultFlag.BRITTLE not in steel.flags


def test_an_elastic_impact_on_glass_is_not_marked() -> None:
    """Below first yield (the rod at 5 mm/s: 0.5 of delta_c) the impact holds."""
    r = il.simulate(ROD, SODA_LIME_GLASS, angle=TH, velocity=(0.0, -0.005), gravity=False)
    assert r.max_delta_ratio < 1.0 and r.flags == ResultFlag.NONE and r.ok


def test_partial_slip_and_the_batch_agree_with_simulate() -> None:
    vy = np.array([-1.41, -0.005, -0.5])
    for friction in ("coulomb", "partial_slip"):
        b = il.simulate_batch(ROD, SODA_LIME_GLASS, vy=vy, angle=TH, gravity=False,
                              friction=friction)  # fmt: skip
        kw = {"angle": TH, "gravity": False, "friction": friction}
        one = [int(il.simulate(ROD, SODA_LIME_GLASS, velocity=(0.0, v), **kw).flags) for v in vy]
        np.testing.assert_array_equal(b.flags, one)
        assert [bool(f & FLAG_BRITTLE) for f in one] == [True, False, True]


def test_drops_are_marked() -> None:
    d = il.simulate_drop(ROD, SODA_LIME_GLASS, angle=TH, velocity=(0.0, -1.41))
    assert ResultFlag.BRITTLE in d.flags and not d.ok
    many = il.simulate_drops(ROD, SODA_LIME_GLASS, angle=TH, vy=np.array([-1.41, -1.0]))
    assert np.all(np.asarray(many.flags) & FLAG_BRITTLE)
    steel = il.simulate_drops(ROD, AISI_1010, angle=TH, vy=np.array([-1.41]))
    assert not np.any(np.asarray(steel.flags) & FLAG_BRITTLE)


def test_a_sweep_marks_the_brittle_cases(tmp_path: Path) -> None:
    from impactlab.sweep import Study, open_sweep, run_sweep
    from impactlab.sweep.options import EngineOptions

    st = Study(
        name="glass",
        fixed={"angle": TH, "mu": 0.2},
        grid={"vy": [-1.41, -0.005], "flat_material": ["soda-lime-glass", "aisi-1010"]},
        engine=EngineOptions(gravity=False),
    )
    ds = open_sweep(run_sweep(st, tmp_path / "g.zarr", quiet=True).path)
    flags = ds["flags"].sel(flat_material="soda-lime-glass").values.astype(int)
    assert [bool(f & FLAG_BRITTLE) for f in flags] == [True, False]
    steel = ds["flags"].sel(flat_material="aisi-1010").values.astype(int)
    assert not np.any(steel & FLAG_BRITTLE)


def test_the_flag_invalidates_and_explains_itself() -> None:
    assert "brittle" in invalidating_names()
    (text,) = messages(FLAG_BRITTLE)
    assert "compressive strength" in text and "no fracture model" in text


def test_the_command_line_prints_the_warning() -> None:
    res = CliRunner().invoke(
        app, ["simulate", "rod", "--angle", "45 deg", "--vy", "-1.41 m/s", "--flat", "glass"]
    )
    assert res.exit_code == 0, res.output
    assert "warning: brittle:" in res.output
