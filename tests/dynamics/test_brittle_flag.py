"""An impact on a brittle material past its first yield is marked BRITTLE, never plain success:
the library's tungsten carbide, alumina and glass carry their compressive strength as the yield
strength, crack rather than yield, and impactlab has no fracture model. Every brittle member of
the pair is checked (both carry the same pressure): the largest mean contact pressure against
the mean pressure of a Hertzian contact at the member's first yield (``contact.brittle``).
``simulate`` (both friction paths), batches, drops and sweeps alike."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import impactlab as il
from impactlab.cli import app
from impactlab.contact.brittle import (
    brittle_flags,
    brittle_pressure,
    first_yield_pressure,
    mean_pressure,
)
from impactlab.contact.ranges import critical_interference
from impactlab.dynamics.models import contact_model
from impactlab.flags import FLAG_BRITTLE, ResultFlag, invalidating_names, messages
from impactlab.materials import (
    AISI_201,
    AISI_1010,
    BRITTLE,
    PRESETS,
    SODA_LIME_GLASS,
    TUNGSTEN_CARBIDE,
    Material,
    get_material,
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


def test_every_brittle_member_counts() -> None:
    """The lowest first-yield pressure of the brittle members; inf without one."""
    glass = first_yield_pressure(SODA_LIME_GLASS)
    assert glass == pytest.approx(2 / 3 * 1.295 * math.exp(0.736 * 0.23) * 330e6)
    assert brittle_pressure(AISI_201, SODA_LIME_GLASS) == glass
    assert brittle_pressure(SODA_LIME_GLASS, AISI_1010) == glass  # the flat yields first
    assert brittle_pressure(SODA_LIME_GLASS, TUNGSTEN_CARBIDE) == glass
    assert brittle_pressure(AISI_201, AISI_1010) == math.inf


def test_the_threshold_is_first_yield() -> None:
    """For the brittle material that yields first, on the Hertzian branch, the pressure
    criterion is delta_max > delta_c: just below nothing, just above BRITTLE."""
    model = contact_model(ROD, SODA_LIME_GLASS, "hertz", None)
    ref = critical_interference(model.law_id, model.params)  # Jackson-Green delta_c
    limit = brittle_pressure(AISI_201, SODA_LIME_GLASS)
    below, above = ref * (1 - 1e-9), ref * (1 + 1e-9)
    force = [float(model.force(np.array([d]))[0]) for d in (below, above)]
    assert brittle_flags(model.law_id, model.params, below, force[0], limit) == 0
    assert brittle_flags(model.law_id, model.params, above, force[1], limit) == FLAG_BRITTLE
    assert brittle_flags(model.law_id, model.params, above, force[1], math.inf) == 0
    assert brittle_flags(model.law_id, model.params, math.nan, math.nan, limit) == 0
    many = brittle_flags(model.law_id, model.params, np.array([below, above, above]),
                         np.array([force[0], force[1], force[1]]),
                         np.array([limit, limit, math.inf]))  # fmt: skip
    np.testing.assert_array_equal(many, [0, FLAG_BRITTLE, 0])
    pm = mean_pressure(model.law_id, model.params, above, force[1])
    assert pm[0] == pytest.approx(limit, rel=1e-8)


def test_a_glass_ball_on_steel_is_marked_a_carbide_ball_is_not() -> None:
    """The steel flat yields first in both, but the glass ball carries the same pressure, far
    past its strength; the carbide ball's strength is far above what the steel can carry."""
    for mat, marked in ((SODA_LIME_GLASS, True), (TUNGSTEN_CARBIDE, False)):
        ball = il.Sphere(radius=0.005, material=mat)
        r = il.simulate(ball, AISI_1010, velocity=(0.0, -5.0))
        assert (ResultFlag.BRITTLE in r.flags) is marked, mat.name
        slow = il.simulate(ball, AISI_1010, velocity=(0.0, -0.05))
        assert ResultFlag.BRITTLE not in slow.flags


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


@pytest.mark.filterwarnings("ignore:friction = .* with mu = 0 is frictionless")  # mu's default
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
    from impactlab.sweep import FlaggedCasesWarning, Study, open_sweep, run_sweep
    from impactlab.sweep.options import EngineOptions

    st = Study(
        name="glass",
        fixed={"angle": TH, "mu": 0.2},
        grid={"vy": [-1.41, -0.005], "flat_material": ["soda-lime-glass", "aisi-1010"]},
        engine=EngineOptions(gravity=False),
    )
    with pytest.warns(FlaggedCasesWarning, match="brittle"):
        ds = open_sweep(run_sweep(st, tmp_path / "g.zarr", quiet=True).path)
    flags = ds["flags"].sel(flat_material="soda-lime-glass").values.astype(int)
    assert [bool(f & FLAG_BRITTLE) for f in flags] == [True, False]
    steel = ds["flags"].sel(flat_material="aisi-1010").values.astype(int)
    assert not np.any(steel & FLAG_BRITTLE)
    balls = Study(
        name="balls",
        fixed={"body": "sphere", "radius": 0.005, "mu": 0.2, "flat_material": "aisi-1010"},
        grid={"vy": [-5.0, -0.05], "body_material": ["soda-lime-glass", "tungsten-carbide"]},
    )
    with pytest.warns(FlaggedCasesWarning, match="brittle"):
        ds = open_sweep(run_sweep(balls, tmp_path / "b.zarr", quiet=True).path)
    bits = ds["flags"].transpose("body_material", "vy").values.astype(int) & FLAG_BRITTLE
    np.testing.assert_array_equal(bits != 0, [[True, False], [False, False]])


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
